#include "fapcast/voice/voice_file.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cstring>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <utility>

#include "fapcast/core/crc32.hpp"
#include "fapcast/core/input_error.hpp"
#include "fapcast/core/synthetic_label.hpp"

namespace fapcast {
namespace {

// Arrays are stored in the host's order and used in place; the format is little-endian.
static_assert(std::endian::native == std::endian::little, "voice files are little-endian");

// Header field offsets (spec/voice.md).
constexpr std::uint64_t kAtVersion = 8, kAtCount = 12, kAtFileSize = 16, kAtTableCrc = 24,
                        kAtHeaderCrc = 28;
// Table entry field offsets.
constexpr std::uint64_t kAtType = 4, kAtRows = 8, kAtCols = 16, kAtOffset = 24, kAtSize = 32,
                        kAtCrc = 40;

template <class T>
T load(const std::byte* p) {
  T v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
template <class T>
void store(std::string& out, std::uint64_t at, T v) {
  std::memcpy(out.data() + at, &v, sizeof v);
}

std::uint64_t align_up(std::uint64_t n) {
  return (n + kVoiceSectionAlignment - 1) / kVoiceSectionAlignment * kVoiceSectionAlignment;
}

std::string hex32(std::uint32_t v) {
  static constexpr char digits[] = "0123456789abcdef";
  std::string s = "0x00000000";
  for (int i = 0; i < 8; ++i) s[9 - i] = digits[(v >> (4 * i)) & 0xF];
  return s;
}

// "section 'PCOM' (pca components)": how messages name a section. Non-printable id bytes are
// shown as '?', so hostile ids cannot inject control characters into a terminal.
std::string describe(SectionId id) {
  std::string s = id.str();
  for (char& c : s) {
    if (c < 0x20 || c > 0x7e) c = '?';
  }
  return "section '" + s + "' (" + std::string(section_name(id)) + ")";
}

[[noreturn]] void refuse(const std::string& source, std::uint64_t offset, const std::string& rule,
                         const std::string& detail) {
  throw InputError({source, std::nullopt, offset}, rule, detail);
}

// a * b * c without overflow; false when it would overflow 64 bits.
bool checked_product(std::uint64_t a, std::uint64_t b, std::uint64_t c, std::uint64_t& out) {
  std::uint64_t ab = 0;
  if (__builtin_mul_overflow(a, b, &ab)) return false;
  return !__builtin_mul_overflow(ab, c, &out);
}

// Checks every rule of spec/voice.md over `bytes` and returns the section table.
std::vector<SectionInfo> parse(std::span<const std::byte> bytes, const std::string& source) {
  const std::uint64_t size = bytes.size();
  const std::byte* p = bytes.data();
  if (size < kVoiceHeaderBytes) {
    refuse(source, size, "truncated-header",
           "file is " + std::to_string(size) + " bytes, shorter than the 64-byte header");
  }
  if (std::memcmp(p, kVoiceMagic.data(), kVoiceMagic.size()) != 0) {
    refuse(source, 0, "bad-magic", "not a fapcast voice (magic is not \"FAPCVOIC\")");
  }
  const auto version = load<std::uint32_t>(p + kAtVersion);
  if (version != kVoiceFormatVersion) {
    refuse(source, kAtVersion, "unsupported-version",
           "format version " + std::to_string(version) + ", this build reads version " +
               std::to_string(kVoiceFormatVersion));
  }
  const auto header_crc = load<std::uint32_t>(p + kAtHeaderCrc);
  const std::uint32_t header_actual = crc32(bytes.first(kAtHeaderCrc));
  if (header_crc != header_actual) {
    refuse(source, kAtHeaderCrc, "header-checksum",
           "header CRC-32 is " + hex32(header_actual) + ", stored " + hex32(header_crc));
  }
  const auto declared_size = load<std::uint64_t>(p + kAtFileSize);
  if (declared_size > size) {
    refuse(source, size, "truncated",
           "header says " + std::to_string(declared_size) + " bytes, file has " + std::to_string(size));
  }
  if (declared_size < size) {
    refuse(source, declared_size, "trailing-bytes",
           "header says " + std::to_string(declared_size) + " bytes, file has " + std::to_string(size));
  }
  const auto count = load<std::uint32_t>(p + kAtCount);
  if (count == 0 || count > kVoiceMaxSections) {
    refuse(source, kAtCount, "section-count",
           std::to_string(count) + " sections, expected 1 to " + std::to_string(kVoiceMaxSections));
  }
  const std::uint64_t table_end = kVoiceHeaderBytes + count * kVoiceTableEntryBytes;
  if (table_end > size) {
    refuse(source, kVoiceHeaderBytes, "table-out-of-bounds",
           "section table of " + std::to_string(count) + " entries ends at byte " +
               std::to_string(table_end) + ", past the end of the file");
  }
  const auto table_crc = load<std::uint32_t>(p + kAtTableCrc);
  const std::uint32_t table_actual =
      crc32(bytes.subspan(kVoiceHeaderBytes, table_end - kVoiceHeaderBytes));
  if (table_crc != table_actual) {
    refuse(source, kVoiceHeaderBytes, "table-checksum",
           "section table CRC-32 is " + hex32(table_actual) + ", stored " + hex32(table_crc));
  }

  std::vector<SectionInfo> sections;
  for (std::uint32_t i = 0; i < count; ++i) {
    const std::uint64_t at = kVoiceHeaderBytes + i * kVoiceTableEntryBytes;
    const std::byte* e = p + at;
    SectionInfo s;
    std::memcpy(s.id.code.data(), e, 4);
    s.type = static_cast<ElementType>(load<std::uint16_t>(e + kAtType));
    s.rows = load<std::uint64_t>(e + kAtRows);
    s.cols = load<std::uint64_t>(e + kAtCols);
    s.offset = load<std::uint64_t>(e + kAtOffset);
    s.size = load<std::uint64_t>(e + kAtSize);
    s.crc32 = load<std::uint32_t>(e + kAtCrc);
    const std::string what = describe(s.id);
    const std::size_t element = element_size(s.type);
    if (element == 0) {
      refuse(source, at + kAtType, "unknown-element-type",
             what + " has element type " + std::to_string(static_cast<unsigned>(s.type)));
    }
    std::uint64_t expected = 0;
    if (!checked_product(s.rows, s.cols, element, expected) || expected != s.size) {
      refuse(source, at + kAtRows, "section-shape",
             what + " is " + std::to_string(s.rows) + " x " + std::to_string(s.cols) +
                 " elements of " + std::to_string(element) + " bytes but " + std::to_string(s.size) +
                 " bytes long");
    }
    if (s.offset % kVoiceSectionAlignment != 0) {
      refuse(source, at + kAtOffset, "section-misaligned",
             what + " starts at byte " + std::to_string(s.offset) + ", not a multiple of 64");
    }
    if (s.offset < table_end || s.offset > size || s.size > size - s.offset) {
      refuse(source, at + kAtOffset, "section-out-of-bounds",
             what + " spans bytes " + std::to_string(s.offset) + " + " + std::to_string(s.size) +
                 ", outside the data area " + std::to_string(table_end) + ".." + std::to_string(size));
    }
    for (const SectionInfo& other : sections) {
      if (other.id == s.id) {
        refuse(source, at, "duplicate-section", what + " appears twice in the section table");
      }
    }
    sections.push_back(s);
  }
  std::vector<const SectionInfo*> by_offset;
  for (const SectionInfo& s : sections) by_offset.push_back(&s);
  std::sort(by_offset.begin(), by_offset.end(),
            [](const SectionInfo* a, const SectionInfo* b) { return a->offset < b->offset; });
  for (std::size_t i = 1; i < by_offset.size(); ++i) {
    const SectionInfo& a = *by_offset[i - 1];
    const SectionInfo& b = *by_offset[i];
    if (a.offset + a.size > b.offset) {
      refuse(source, b.offset, "section-overlap",
             describe(a.id) + " (bytes " + std::to_string(a.offset) + "+" + std::to_string(a.size) +
                 ") overlaps " + describe(b.id) + " at byte " + std::to_string(b.offset));
    }
  }
  for (const SectionInfo& s : sections) {
    const std::uint32_t actual = crc32(bytes.subspan(s.offset, s.size));
    if (actual != s.crc32) {
      refuse(source, s.offset, "section-checksum",
             describe(s.id) + ": CRC-32 is " + hex32(actual) + ", table says " + hex32(s.crc32));
    }
  }
  return sections;
}

}  // namespace

std::size_t element_size(ElementType type) {
  switch (type) {
    case ElementType::kBytes:
    case ElementType::kJson:
      return 1;
    case ElementType::kFloat32:
    case ElementType::kInt32:
    case ElementType::kUint32:
      return 4;
    case ElementType::kFloat64:
      return 8;
  }
  return 0;
}

std::string_view section_name(SectionId id) {
  namespace vs = voice_section;
  static constexpr std::pair<SectionId, std::string_view> kNames[] = {
      {vs::kProvenance, "provenance"},       {vs::kPcaMean, "pca mean"},
      {vs::kPcaComponents, "pca components"}, {vs::kPcaVariances, "pca variances"},
      {vs::kFrameCoefficients, "frame coefficients"}, {vs::kRbfCentres, "rbf centres"},
      {vs::kRbfWeights, "rbf weights"},      {vs::kRbfOffset, "rbf offset"},
      {vs::kRbfScalars, "rbf scalars"},      {vs::kPhoneGraph, "phone graph"},
      {vs::kFeaturePoints, "feature points"}, {vs::kFaceMaps, "face maps"},
      {vs::kLipContactShape, "lip contact shape"}, {vs::kLipContact, "lip contact"},
  };
  for (const auto& [known, name] : kNames) {
    if (known == id) return name;
  }
  return "unknown section";
}

// ---- writer ----

void VoiceFileWriter::add(SectionId id, ElementType type, std::uint64_t rows, std::uint64_t cols,
                          std::span<const std::byte> data) {
  std::uint64_t expected = 0;
  if (element_size(type) == 0 || !checked_product(rows, cols, element_size(type), expected) ||
      expected != data.size()) {
    throw std::invalid_argument("VoiceFileWriter::add: " + describe(id) + ": " +
                                std::to_string(data.size()) + " bytes do not hold " +
                                std::to_string(rows) + " x " + std::to_string(cols) + " elements");
  }
  for (const Pending& s : sections_) {
    if (s.info.id == id) throw std::invalid_argument("VoiceFileWriter::add: duplicate " + describe(id));
  }
  if (sections_.size() >= kVoiceMaxSections) {
    throw std::invalid_argument("VoiceFileWriter::add: more than 64 sections");
  }
  SectionInfo info;
  info.id = id;
  info.type = type;
  info.rows = rows;
  info.cols = cols;
  info.size = data.size();
  info.crc32 = crc32(data);
  sections_.push_back({info, std::vector<std::byte>(data.begin(), data.end())});
}

void VoiceFileWriter::add_matrix(SectionId id, const RowMajorMatrixXf& m) {
  add(id, ElementType::kFloat32, static_cast<std::uint64_t>(m.rows()),
      static_cast<std::uint64_t>(m.cols()), std::as_bytes(std::span(m.data(), static_cast<std::size_t>(m.size()))));
}

void VoiceFileWriter::add_matrix(SectionId id, const RowMajorMatrixXd& m) {
  add(id, ElementType::kFloat64, static_cast<std::uint64_t>(m.rows()),
      static_cast<std::uint64_t>(m.cols()), std::as_bytes(std::span(m.data(), static_cast<std::size_t>(m.size()))));
}

void VoiceFileWriter::add_provenance(const VoiceProvenance& p) {
  nlohmann::ordered_json j;
  j["format"] = "fapcast voice";
  j["corpus"] = p.corpus;
  j["target_face"] = p.target_face;
  j["seed"] = p.seed;
  j["synthetic"] = p.synthetic;
  if (p.synthetic) j["label"] = std::string(kSyntheticLabel);
  j["build_time_utc"] = p.build_time_utc;
  j["tool_version"] = p.tool_version;
  j["parameters"] = nlohmann::ordered_json::object();
  for (const auto& [name, value] : p.parameters) j["parameters"][name] = value;
  if (!p.notes.empty()) {
    j["notes"] = nlohmann::ordered_json::object();
    for (const auto& [name, text] : p.notes) j["notes"][name] = text;
  }
  const std::string text = j.dump(2) + "\n";
  add(voice_section::kProvenance, ElementType::kJson, 1, text.size(), std::as_bytes(std::span(text)));
}

std::string VoiceFileWriter::bytes() const {
  if (sections_.empty()) throw std::invalid_argument("VoiceFileWriter::bytes: no sections");
  const std::uint64_t table_end = kVoiceHeaderBytes + sections_.size() * kVoiceTableEntryBytes;
  std::vector<std::uint64_t> offsets;
  std::uint64_t end = table_end;
  for (const Pending& s : sections_) {
    offsets.push_back(align_up(end));
    end = offsets.back() + s.info.size;
  }
  std::string out(end, '\0');  // padding stays zero
  std::memcpy(out.data(), kVoiceMagic.data(), kVoiceMagic.size());
  store<std::uint32_t>(out, kAtVersion, kVoiceFormatVersion);
  store<std::uint32_t>(out, kAtCount, static_cast<std::uint32_t>(sections_.size()));
  store<std::uint64_t>(out, kAtFileSize, end);
  for (std::size_t i = 0; i < sections_.size(); ++i) {
    const SectionInfo& s = sections_[i].info;
    const std::uint64_t at = kVoiceHeaderBytes + i * kVoiceTableEntryBytes;
    std::memcpy(out.data() + at, s.id.code.data(), 4);
    store<std::uint16_t>(out, at + kAtType, static_cast<std::uint16_t>(s.type));
    store<std::uint64_t>(out, at + kAtRows, s.rows);
    store<std::uint64_t>(out, at + kAtCols, s.cols);
    store<std::uint64_t>(out, at + kAtOffset, offsets[i]);
    store<std::uint64_t>(out, at + kAtSize, s.size);
    store<std::uint32_t>(out, at + kAtCrc, s.crc32);
    if (s.size > 0) std::memcpy(out.data() + offsets[i], sections_[i].data.data(), s.size);
  }
  const auto all = std::as_bytes(std::span(out));
  store<std::uint32_t>(out, kAtTableCrc, crc32(all.subspan(kVoiceHeaderBytes, table_end - kVoiceHeaderBytes)));
  store<std::uint32_t>(out, kAtHeaderCrc, crc32(all.first(kAtHeaderCrc)));
  return out;
}

// ---- view ----

VoiceFileView::VoiceFileView(std::string source, const std::byte* data, std::uint64_t size, bool owns)
    : source_(std::move(source)), data_(data), size_(size), owns_mapping_(owns) {}

VoiceFileView::VoiceFileView(VoiceFileView&& other) noexcept
    : source_(std::move(other.source_)), data_(std::exchange(other.data_, nullptr)),
      size_(std::exchange(other.size_, 0)), owns_mapping_(std::exchange(other.owns_mapping_, false)),
      sections_(std::move(other.sections_)) {}

VoiceFileView& VoiceFileView::operator=(VoiceFileView&& other) noexcept {
  if (this != &other) {
    release();
    source_ = std::move(other.source_);
    data_ = std::exchange(other.data_, nullptr);
    size_ = std::exchange(other.size_, 0);
    owns_mapping_ = std::exchange(other.owns_mapping_, false);
    sections_ = std::move(other.sections_);
  }
  return *this;
}

VoiceFileView::~VoiceFileView() { release(); }

void VoiceFileView::release() noexcept {
  if (owns_mapping_ && data_ != nullptr) {
    ::munmap(const_cast<std::byte*>(data_), size_);
  }
  data_ = nullptr;
  owns_mapping_ = false;
}

VoiceFileView VoiceFileView::open(const std::filesystem::path& path) {
  const std::string source = path.string();
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    throw std::runtime_error(source + ": cannot open voice: " + std::strerror(errno));
  }
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    throw std::runtime_error(source + ": not a regular file");
  }
  const auto size = static_cast<std::uint64_t>(st.st_size);
  if (size < kVoiceHeaderBytes) {
    ::close(fd);
    refuse(source, size, "truncated-header",
           "file is " + std::to_string(size) + " bytes, shorter than the 64-byte header");
  }
  if (size > kVoiceMaxBytes) {
    ::close(fd);
    refuse(source, 0, "file-too-large", std::to_string(size) + " bytes, the limit is 4 GiB");
  }
  // MAP_POPULATE: every byte is read at once by the checksums below; reading the pages in
  // together costs less than faulting them in one by one.
  void* mapped = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
  const int map_errno = errno;
  ::close(fd);  // the mapping keeps the file alive
  if (mapped == MAP_FAILED) {
    throw std::runtime_error(source + ": cannot map voice: " + std::strerror(map_errno));
  }
  VoiceFileView view(source, static_cast<const std::byte*>(mapped), size, true);
  view.sections_ = parse(std::span(view.data_, size), source);  // on throw, ~view unmaps
  return view;
}

VoiceFileView VoiceFileView::over_bytes(std::span<const std::byte> bytes, std::string source) {
  if (reinterpret_cast<std::uintptr_t>(bytes.data()) % alignof(double) != 0) {
    throw std::invalid_argument("VoiceFileView::over_bytes: bytes must be 8-byte aligned");
  }
  VoiceFileView view(std::move(source), bytes.data(), bytes.size(), false);
  view.sections_ = parse(bytes, view.source_);
  return view;
}

const SectionInfo* VoiceFileView::find(SectionId id) const {
  for (const SectionInfo& s : sections_) {
    if (s.id == id) return &s;
  }
  return nullptr;
}

const SectionInfo& VoiceFileView::require(SectionId id) const {
  const SectionInfo* s = find(id);
  if (s == nullptr) refuse(source_, kVoiceHeaderBytes, "missing-section", describe(id) + " is missing");
  return *s;
}

std::span<const std::byte> VoiceFileView::bytes(SectionId id) const {
  const SectionInfo& s = require(id);
  return {data_ + s.offset, static_cast<std::size_t>(s.size)};
}

const SectionInfo& VoiceFileView::typed(SectionId id, ElementType type) const {
  const SectionInfo& s = require(id);
  if (s.type != type) {
    refuse(source_, s.offset, "section-type",
           describe(id) + " has element type " + std::to_string(static_cast<unsigned>(s.type)) +
               ", expected " + std::to_string(static_cast<unsigned>(type)));
  }
  return s;
}

Eigen::Map<const RowMajorMatrixXf> VoiceFileView::matrix_f32(SectionId id) const {
  const SectionInfo& s = typed(id, ElementType::kFloat32);
  return {reinterpret_cast<const float*>(data_ + s.offset), static_cast<Eigen::Index>(s.rows),
          static_cast<Eigen::Index>(s.cols)};
}

Eigen::Map<const RowMajorMatrixXd> VoiceFileView::matrix_f64(SectionId id) const {
  const SectionInfo& s = typed(id, ElementType::kFloat64);
  return {reinterpret_cast<const double*>(data_ + s.offset), static_cast<Eigen::Index>(s.rows),
          static_cast<Eigen::Index>(s.cols)};
}

VoiceProvenance VoiceFileView::provenance() const {
  const SectionInfo& s = typed(voice_section::kProvenance, ElementType::kJson);
  const auto raw = bytes(voice_section::kProvenance);
  const std::string_view text(reinterpret_cast<const char*>(raw.data()), raw.size());
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded() || !j.is_object()) {
    refuse(source_, s.offset, "provenance-json", describe(s.id) + " is not a JSON object");
  }
  auto field = [&](const char* name, auto check) -> const nlohmann::json& {
    const auto it = j.find(name);
    if (it == j.end() || !check(*it)) {
      refuse(source_, s.offset, "provenance-field",
             describe(s.id) + ": field \"" + name + "\" is missing or has the wrong type");
    }
    return *it;
  };
  const auto is_string = [](const nlohmann::json& v) { return v.is_string(); };
  VoiceProvenance p;
  p.corpus = field("corpus", is_string).get<std::string>();
  p.target_face = field("target_face", is_string).get<std::string>();
  p.seed = field("seed", [](const nlohmann::json& v) { return v.is_number_unsigned(); }).get<std::uint64_t>();
  p.synthetic = field("synthetic", [](const nlohmann::json& v) { return v.is_boolean(); }).get<bool>();
  p.build_time_utc = field("build_time_utc", is_string).get<std::string>();
  p.tool_version = field("tool_version", is_string).get<std::string>();
  const nlohmann::json& params = field("parameters", [](const nlohmann::json& v) { return v.is_object(); });
  for (const auto& [name, value] : params.items()) {
    if (!value.is_number()) {
      refuse(source_, s.offset, "provenance-field",
             describe(s.id) + ": parameter \"" + name + "\" is not a number");
    }
    p.parameters[name] = value.get<double>();
  }
  if (const auto notes = j.find("notes"); notes != j.end()) {  // optional
    if (!notes->is_object()) refuse(source_, s.offset, "provenance-field", describe(s.id) + ": \"notes\" is not an object");
    for (const auto& [name, value] : notes->items()) {
      if (!value.is_string())
        refuse(source_, s.offset, "provenance-field", describe(s.id) + ": note \"" + name + "\" is not a string");
      p.notes[name] = value.get<std::string>();
    }
  }
  return p;
}

void check_voice_sections(const VoiceFileView& view) {
  namespace vs = voice_section;
  const auto shape = [&](SectionId id, ElementType type) -> const SectionInfo& {
    const SectionInfo& s = view.require(id);
    if (s.type != type) {
      refuse(view.source(), s.offset, "section-type",
             describe(id) + " has element type " + std::to_string(static_cast<unsigned>(s.type)) +
                 ", expected " + std::to_string(static_cast<unsigned>(type)));
    }
    return s;
  };
  const auto expect = [&](const SectionInfo& s, std::uint64_t rows, std::uint64_t cols,
                          const char* meaning) {
    if (s.rows != rows || s.cols != cols) {
      refuse(view.source(), s.offset, "section-shape",
             describe(s.id) + " is " + std::to_string(s.rows) + " x " + std::to_string(s.cols) +
                 ", expected " + std::to_string(rows) + " x " + std::to_string(cols) + " (" + meaning + ")");
    }
  };
  shape(vs::kProvenance, ElementType::kJson);
  shape(vs::kPhoneGraph, ElementType::kBytes);
  const SectionInfo& mean = shape(vs::kPcaMean, ElementType::kFloat32);
  const std::uint64_t d = mean.cols;
  expect(mean, 1, d, "1 x D");
  const SectionInfo& components = shape(vs::kPcaComponents, ElementType::kFloat32);
  const std::uint64_t k = components.rows;
  expect(components, k, d, "k x D, D from the pca mean");
  expect(shape(vs::kPcaVariances, ElementType::kFloat32), 1, k, "1 x k");
  const SectionInfo& coefficients = shape(vs::kFrameCoefficients, ElementType::kFloat32);
  expect(coefficients, coefficients.rows, k, "frames x k");
  const SectionInfo& centres = shape(vs::kRbfCentres, ElementType::kFloat64);
  expect(shape(vs::kRbfWeights, ElementType::kFloat32), centres.rows, d, "m x D");
  expect(shape(vs::kRbfOffset, ElementType::kFloat32), 1, d, "1 x D");
  expect(shape(vs::kRbfScalars, ElementType::kFloat64), 1, 2, "r^2, lambda");
  const SectionInfo* contact_shape = view.find(vs::kLipContactShape);
  const SectionInfo* contact = view.find(vs::kLipContact);
  if ((contact_shape == nullptr) != (contact == nullptr)) {
    const SectionInfo& present = contact_shape ? *contact_shape : *contact;
    refuse(view.source(), present.offset, "missing-section",
           describe(present.id) + " needs " + describe(contact_shape ? vs::kLipContact : vs::kLipContactShape) +
               " (the lip-contact term is the two together)");
  }
  if (contact_shape != nullptr) {
    expect(shape(vs::kLipContactShape, ElementType::kFloat32), 1, d, "1 x D");
    expect(shape(vs::kLipContact, ElementType::kFloat64), 1, vs::kLipContactScalars + centres.rows,
           "1 x (5 + m): five scalars, then m gap weights");
  }
  if (k == 0 || d == 0 || centres.rows < 2) {
    refuse(view.source(), components.offset, "section-shape",
           "a voice needs k >= 1 components, D >= 1 coordinates and m >= 2 centres");
  }
}

VoiceFileView open_voice(const std::filesystem::path& path) {
  VoiceFileView view = VoiceFileView::open(path);
  check_voice_sections(view);
  (void)view.provenance();
  return view;
}

}  // namespace fapcast
