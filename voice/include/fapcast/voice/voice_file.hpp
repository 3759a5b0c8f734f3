#pragma once
// The voice file (spec/voice.md): one versioned binary container of typed, checksummed sections,
// each aligned to 64 bytes so the file can be memory-mapped and its arrays used in place.
//
//   header (64 bytes) | section table (48 bytes per section) | section data, each 64-aligned
//
// All integers little-endian. VoiceFileWriter produces the bytes; VoiceFileView maps a file
// read-only, checks every rule before handing anything out, and refuses a bad file with an
// InputError naming the file, the byte offset, the rule and the section.
#include "fapcast/core/input_error.hpp"
#include "fapcast/core/eigen_types.hpp"

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace fapcast {

// A section's four-character id, e.g. SectionId{"PCOM"} (stored as those 4 ASCII bytes).
struct SectionId {
  std::array<char, 4> code{};
  constexpr SectionId() = default;
  constexpr SectionId(const char (&s)[5]) : code{s[0], s[1], s[2], s[3]} {}  // NOLINT: implicit
  std::string str() const { return std::string(code.data(), 4); }
  friend constexpr bool operator==(const SectionId&, const SectionId&) = default;
};

// What a section's elements are; a section is a rows x cols row-major array of them.
enum class ElementType : std::uint16_t {
  kBytes = 0,    // opaque bytes (1 x size): e.g. the phone graph until it has its own layout
  kFloat32 = 1,
  kFloat64 = 2,
  kInt32 = 3,
  kUint32 = 4,
  kJson = 5,     // UTF-8 JSON text (1 x size)
};
// Size in bytes of one element (1 for kBytes and kJson); 0 for an unknown type.
std::size_t element_size(ElementType type);

inline constexpr std::array<char, 8> kVoiceMagic = {'F', 'A', 'P', 'C', 'V', 'O', 'I', 'C'};
inline constexpr std::uint32_t kVoiceFormatVersion = 1;
inline constexpr std::uint64_t kVoiceHeaderBytes = 64;
inline constexpr std::uint64_t kVoiceTableEntryBytes = 48;
inline constexpr std::uint64_t kVoiceSectionAlignment = 64;
inline constexpr std::uint32_t kVoiceMaxSections = 64;
inline constexpr std::uint64_t kVoiceMaxBytes = 4ull << 30;  // 4 GiB: far above a full voice

// One row of the section table, as read (offsets and sizes in bytes from the file's start).
struct SectionInfo {
  SectionId id;
  ElementType type = ElementType::kBytes;
  std::uint64_t rows = 0;
  std::uint64_t cols = 0;
  std::uint64_t offset = 0;
  std::uint64_t size = 0;
  std::uint32_t crc32 = 0;
};

// The sections of a voice (spec/voice.md has the table with shapes and meanings).
namespace voice_section {
inline constexpr SectionId kProvenance{"PROV"};    // json: VoiceProvenance
inline constexpr SectionId kPcaMean{"PMEA"};       // f32 1 x D: mean target frame
inline constexpr SectionId kPcaComponents{"PCOM"}; // f32 k x D: orthonormal components
inline constexpr SectionId kPcaVariances{"PVAR"};  // f32 1 x k: variance along each component
inline constexpr SectionId kFrameCoefficients{"FCOE"};  // f32 frames x k: the corpus in PCA
inline constexpr SectionId kRbfCentres{"RCEN"};    // f64 m x d: source prototypes
inline constexpr SectionId kRbfWeights{"RWEI"};    // f32 m x D
inline constexpr SectionId kRbfOffset{"ROFF"};     // f32 1 x D: intercept b
inline constexpr SectionId kRbfScalars{"RPAR"};    // f64 1 x 2: r^2, lambda
inline constexpr SectionId kPhoneGraph{"GRPH"};    // bytes: phone graph (voice_graph.hpp layout)
inline constexpr SectionId kFeaturePoints{"FPNT"}; // json: target-face feature points (voice.hpp)
// Optional: f32 N x 9, vertex i's 3 x 3 map (row-major) from the generic ICT face to the voice's
// face; written by `fapcast voice retarget` (voice_adaptation.hpp), absent in a voice built on ICT.
inline constexpr SectionId kFaceMaps{"FMAP"};
// Optional, together: the retargeting's lip-contact term (lip_contact.hpp). LCSH f32 1 x D, the
// closing shape on the voice's face; LCON f64 1 x (5 + m): gap offset, shape gap, source contact,
// target contact, reach (metres), then the m gap weights.
inline constexpr SectionId kLipContactShape{"LCSH"};
inline constexpr SectionId kLipContact{"LCON"};
inline constexpr std::uint64_t kLipContactScalars = 5;
}  // namespace voice_section

// A human name for a known section id ("pca components"), or "unknown section".
std::string_view section_name(SectionId id);

// Where a voice came from (the PROV section, JSON).
struct VoiceProvenance {
  std::string corpus;          // corpus directory or name
  std::string target_face;     // e.g. "ICT-FaceKit generic neutral"
  std::uint64_t seed = 0;      // the build's seed: same corpus + seed -> same voice
  bool synthetic = false;      // true when the corpus is the reference talker's
  std::string build_time_utc;  // ISO 8601, e.g. "2026-11-22T04:00:00Z"
  std::string tool_version;    // fapcast version that built it
  std::map<std::string, double> parameters;  // k, lambda, r_squared, frames, ...
  std::map<std::string, std::string> notes;  // optional texts: prototype rule, PCA route, ...
  friend bool operator==(const VoiceProvenance&, const VoiceProvenance&) = default;
};

using RowMajorMatrixXd = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// Collects sections and lays out the file. Returns bytes rather than writing: the tools write them
// with write_file_atomically (one atomic writer in the project; synth does no output
// I/O), and a full voice (~20 MB) costs nothing to hold.
class VoiceFileWriter {
 public:
  // Adds a section of rows x cols elements of `type` taken from `data` (size must equal
  // rows * cols * element_size). Throws std::invalid_argument on a duplicate id or bad size.
  void add(SectionId id, ElementType type, std::uint64_t rows, std::uint64_t cols,
           std::span<const std::byte> data);
  // Adds a float32 / float64 matrix (stored row-major).
  void add_matrix(SectionId id, const RowMajorMatrixXf& m);
  void add_matrix(SectionId id, const RowMajorMatrixXd& m);
  // Adds the provenance as the PROV JSON section.
  void add_provenance(const VoiceProvenance& provenance);
  // The complete file.
  std::string bytes() const;

 private:
  struct Pending {
    SectionInfo info;
    std::vector<std::byte> data;
  };
  std::vector<Pending> sections_;
};

// A verified, read-only voice file: owns its memory mapping (or borrows caller's bytes) and hands
// out sections as spans and Eigen maps. Move-only.
class VoiceFileView {
 public:
  // Maps `path` read-only and verifies header, table and every section checksum. Throws
  // InputError (bad file) or std::runtime_error (cannot open / map).
  static VoiceFileView open(const std::filesystem::path& path);
  // Verifies bytes the caller keeps alive (8-byte aligned, e.g. from a std::vector<double>);
  // `source` names them in errors. For tests and fuzzing.
  static VoiceFileView over_bytes(std::span<const std::byte> bytes, std::string source);

  VoiceFileView(VoiceFileView&& other) noexcept;
  VoiceFileView& operator=(VoiceFileView&& other) noexcept;
  VoiceFileView(const VoiceFileView&) = delete;
  VoiceFileView& operator=(const VoiceFileView&) = delete;
  ~VoiceFileView();

  const std::string& source() const { return source_; }
  std::uint64_t file_size() const { return size_; }
  const std::vector<SectionInfo>& sections() const { return sections_; }
  // The section with this id, or nullptr.
  const SectionInfo* find(SectionId id) const;
  // The section with this id; throws InputError "missing-section" when absent.
  const SectionInfo& require(SectionId id) const;
  // The section's bytes.
  std::span<const std::byte> bytes(SectionId id) const;
  // The section as a rows x cols matrix in place; throws InputError "section-type" when its
  // element type is not float32 / float64.
  Eigen::Map<const RowMajorMatrixXf> matrix_f32(SectionId id) const;
  Eigen::Map<const RowMajorMatrixXd> matrix_f64(SectionId id) const;
  // The PROV section parsed; throws InputError "provenance-json" / "provenance-field".
  VoiceProvenance provenance() const;

 private:
  VoiceFileView(std::string source, const std::byte* data, std::uint64_t size, bool owns);
  void release() noexcept;
  const SectionInfo& typed(SectionId id, ElementType type) const;

  std::string source_;
  const std::byte* data_ = nullptr;
  std::uint64_t size_ = 0;
  bool owns_mapping_ = false;
  std::vector<SectionInfo> sections_;
};

// Checks that a verified file is a complete voice: every required section present with its
// element type, and shapes that agree (D, k, m shared between sections). Throws InputError
// "missing-section", "section-type" or "section-shape".
void check_voice_sections(const VoiceFileView& view);

// Opens a voice for use: VoiceFileView::open, check_voice_sections and a parse of the provenance,
// so every way a voice can be bad is reported before the first frame is synthesised.
VoiceFileView open_voice(const std::filesystem::path& path);

}  // namespace fapcast
