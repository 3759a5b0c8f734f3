// The `.fap` text reader and writer. spec/fap-text.md is the normative description: every rule
// id thrown here is listed there.
#include "fapcast/codec/fap_text.hpp"

#include "fapcast/core/input_error.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cstring>
#include <limits>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <tuple>
#include <utility>

namespace fapcast {
namespace {

constexpr int kMaskTokensStrict = kFapCount;       // 68
constexpr int kMaskTokens69 = kFapCount + 1;       // 69: a leading unused slot
constexpr int kVisemeFieldsStrict = 4;             // select1, select2, blend, def
constexpr int kExpressionFieldsStrict = 6;         // select1, intensity1, select2, intensity2, init_face, def
constexpr std::size_t kMaxLineTokens = 1 + kVisemeFieldsStrict + kExpressionFieldsStrict + 66 + 3;
constexpr std::uint32_t kMaxFpsMillis = 1'000'000;  // fps <= 1000
constexpr int kMaxFpsDigits = 6;                    // fractional digits of the fps token
constexpr std::uint8_t kFullWeight = 63;            // viseme_blend / expression_intensity: full weight
// The largest blend or intensity a standard FBA stream decodes to: 63 on the quantiser's grid of
// fap_quant 25 is 75 (spec/fba.md §5), so every decoded stream writes and reads back.
constexpr std::uint8_t kMaxWeight = 75;
constexpr int kLastViseme = 14;                     // visemes 0 (none) .. 14 (U, book)
constexpr int kLastExpression = 6;                  // expressions 0 (none) .. 6 (surprise)
// NTSC-family rates written as decimals: N x 1000/1001 (29.97 is 30000/1001).
constexpr std::array<std::uint32_t, 6> kNtscBases{24, 30, 48, 60, 120, 240};

bool is_blank(char c) { return c == ' ' || c == '\t'; }

// Replaces every byte that does not start a valid UTF-8 sequence (overlong forms, surrogates
// and code points past U+10FFFF included) by U+FFFD. Sets `repaired` when it changed anything.
std::string repair_utf8(std::string_view s, bool& repaired) {
  std::string out;
  out.reserve(s.size());
  std::size_t i = 0;
  while (i < s.size()) {
    const auto b0 = static_cast<unsigned char>(s[i]);
    int len = 0;
    std::uint32_t cp = 0;
    if (b0 < 0x80) {
      len = 1;
      cp = b0;
    } else if (b0 >= 0xC2 && b0 <= 0xDF) {
      len = 2;
      cp = b0 & 0x1Fu;
    } else if (b0 >= 0xE0 && b0 <= 0xEF) {
      len = 3;
      cp = b0 & 0x0Fu;
    } else if (b0 >= 0xF0 && b0 <= 0xF4) {
      len = 4;
      cp = b0 & 0x07u;
    }
    bool ok = len > 0 && i + static_cast<std::size_t>(len) <= s.size();
    for (int k = 1; ok && k < len; ++k) {
      const auto b = static_cast<unsigned char>(s[i + static_cast<std::size_t>(k)]);
      ok = (b & 0xC0u) == 0x80u;
      cp = (cp << 6) | (b & 0x3Fu);
    }
    if (ok && len == 3) ok = cp >= 0x800 && (cp < 0xD800 || cp > 0xDFFF);
    if (ok && len == 4) ok = cp >= 0x10000 && cp <= 0x10FFFF;
    if (ok) {
      out.append(s.substr(i, static_cast<std::size_t>(len)));
      i += static_cast<std::size_t>(len);
    } else {
      out += "\xEF\xBF\xBD";
      repaired = true;
      ++i;
    }
  }
  return out;
}

// A token as it may appear in a message: at most 24 bytes, non-printable bytes as \xNN.
std::string quote(std::string_view token) {
  constexpr std::size_t kShown = 24;
  std::string out = "'";
  for (std::size_t i = 0; i < token.size() && i < kShown; ++i) {
    const auto c = static_cast<unsigned char>(token[i]);
    if (c >= 0x20 && c < 0x7F) {
      out += static_cast<char>(c);
    } else {
      static constexpr char kHex[] = "0123456789abcdef";
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 0xF];
    }
  }
  if (token.size() > kShown) out += "...";
  return out + "'";
}

// An exact decimal: [+-]digits[.digits], with at least one digit.
struct Decimal {
  bool negative = false;
  std::string_view whole;     // digits before the point (may be empty)
  std::string_view fraction;  // digits after it (may be empty)
  bool has_point = false;
};

std::optional<Decimal> parse_decimal(std::string_view t) {
  Decimal d;
  std::size_t i = 0;
  if (i < t.size() && (t[i] == '+' || t[i] == '-')) d.negative = t[i++] == '-';
  const std::size_t w0 = i;
  while (i < t.size() && t[i] >= '0' && t[i] <= '9') ++i;
  d.whole = t.substr(w0, i - w0);
  if (i < t.size() && t[i] == '.') {
    d.has_point = true;
    const std::size_t f0 = ++i;
    while (i < t.size() && t[i] >= '0' && t[i] <= '9') ++i;
    d.fraction = t.substr(f0, i - f0);
  }
  if (i != t.size() || (d.whole.empty() && d.fraction.empty())) return std::nullopt;
  return d;
}

// Parses digits into a uint64; nullopt when they do not fit.
std::optional<std::uint64_t> parse_digits(std::string_view digits) {
  std::uint64_t v = 0;
  if (digits.empty()) return 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
  if (ec != std::errc{} || end != digits.data() + digits.size()) return std::nullopt;
  return v;
}

// Everything one read needs to report: the source, the info being filled, warnings.
class FapTextReader {
 public:
  FapTextReader(std::string_view bytes, std::string_view source) : bytes_(bytes), source_(source) {}

  FapTextRead run();

 private:
  struct Line {
    std::string_view text;
    std::uint64_t number = 0;
  };
  // The tokens of one line: the first kMaxLineTokens are kept, all are counted.
  struct Tokens {
    std::array<std::string_view, kMaxLineTokens> token;
    std::size_t count = 0;
    std::string_view operator[](std::size_t i) const { return token[i]; }
  };

  std::optional<Line> next_line();
  Tokens split(std::string_view text);
  void read_header(const Line& line);
  FrameRate read_fps(std::string_view token, std::uint64_t line);
  FapMask read_mask(const Line& line);
  void read_frame(const FapMask& mask, std::uint64_t mask_line, const Line& values);
  std::int64_t number(std::string_view token, std::uint64_t line, std::string_view what);
  std::uint8_t field(std::string_view token, std::uint64_t line, const char* rule,
                     const char* name, int max);
  void hold_until(std::uint64_t frame_number, std::uint64_t line);
  void check_count_against_file();

  [[noreturn]] void fail(std::uint64_t line, const char* rule, const std::string& detail) const {
    throw InputError({std::string(source_), line, std::nullopt}, rule, detail);
  }
  void warn(std::uint64_t line, const char* rule, const std::string& detail) {
    ++out_.info.warning_count;
    // Formatted exactly as an error would be, so that warnings and errors read alike.
    if (out_.info.warnings.size() < kFapTextMaxWarnings)
      out_.info.warnings.push_back(
          InputError({std::string(source_), line, std::nullopt}, rule, detail).what());
  }

  std::string_view bytes_;
  std::string_view source_;
  std::size_t pos_ = 0;
  std::uint64_t line_number_ = 0;
  std::uint64_t header_line_ = 0;
  int mask_tokens_ = 0;  // 68 or 69 once the first mask line is read
  std::uint64_t first_mask_line_ = 0;
  // FAP 1/2 fields per value line: unknown until the first frame that masks one of them; then
  // the standard's 4/6, or one integer each (the 69-token dialect, and 68-token files written for
  // Greta and VREng: told apart by the token count, which differs by 3 per FAP 1, 5 per FAP 2).
  std::optional<bool> single_fap12_;
  std::optional<std::uint64_t> first_number_;  // the first record's frame number
  std::uint64_t first_frame_warning_ = 0;     // warning_count after the first-frame warning (0: none)
  std::uint64_t frame_offset_ = 0;            // 1 once the file is read one-based
  std::uint64_t held_runs_ = 0;               // skips that held frames
  FapTextRead out_;
};

// The next line that is neither blank nor a comment, with its line ending removed. Refuses
// control bytes (NUL included): a text file has none but tab, CR before LF, and LF.
std::optional<FapTextReader::Line> FapTextReader::next_line() {
  while (pos_ < bytes_.size()) {
    const std::size_t end = bytes_.find('\n', pos_);
    const std::size_t stop = end == std::string_view::npos ? bytes_.size() : end;
    std::string_view text = bytes_.substr(pos_, stop - pos_);
    pos_ = end == std::string_view::npos ? bytes_.size() : end + 1;
    ++line_number_;
    if (!text.empty() && text.back() == '\r') {
      text.remove_suffix(1);
      out_.info.crlf = true;
    }
    for (std::size_t i = 0; i < text.size(); ++i) {
      const auto c = static_cast<unsigned char>(text[i]);
      if (c == '\r')
        fail(line_number_, "bare-cr",
             "a CR not followed by LF at column " + std::to_string(i + 1) +
                 " (lines end with LF or CRLF)");
      if ((c < 0x20 && c != '\t') || c == 0x7F)
        fail(line_number_, "binary-byte",
             "byte " + quote(text.substr(i, 1)) + " at column " + std::to_string(i + 1) +
                 ": not a text file");
      if (c == '\t') out_.info.tabs = true;
    }
    const std::size_t first = text.find_first_not_of(" \t");
    if (first == std::string_view::npos) continue;  // blank
    if (text[first] == '#') {
      out_.info.comments = true;
      continue;
    }
    return Line{text, line_number_};
  }
  return std::nullopt;
}

FapTextReader::Tokens FapTextReader::split(std::string_view text) {
  Tokens t;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && is_blank(text[i])) ++i;
    if (i == text.size()) break;
    const std::size_t start = i;
    while (i < text.size() && !is_blank(text[i])) ++i;
    if (t.count < kMaxLineTokens) t.token[t.count] = text.substr(start, i - start);
    ++t.count;
  }
  return t;
}

// "<version> <name ...> <fps> <count>": the first token is the version, the last two are the
// fps and the frame count, and everything between them (spaces included) is the name.
void FapTextReader::read_header(const Line& line) {
  header_line_ = line.number;
  std::string_view rest = line.text;
  auto take_first = [&] {
    rest.remove_prefix(std::min(rest.find_first_not_of(" \t"), rest.size()));
    const std::size_t end = std::min(rest.find_first_of(" \t"), rest.size());
    std::string_view tok = rest.substr(0, end);
    rest.remove_prefix(end);
    return tok;
  };
  auto take_last = [&] {
    rest.remove_suffix(rest.size() - (rest.find_last_not_of(" \t") + 1));
    const std::size_t sep = rest.find_last_of(" \t");
    const std::size_t start = sep == std::string_view::npos ? 0 : sep + 1;
    std::string_view tok = rest.substr(start);
    rest.remove_suffix(rest.size() - start);
    return tok;
  };
  const std::string_view version = take_first();
  const std::string_view count = take_last();
  const std::string_view fps = take_last();
  if (version.empty() || count.empty() || fps.empty())
    fail(line.number, "header-tokens",
         "the header needs at least 3 tokens: version, [name], fps, frame count");
  if (version != "2.0" && version != "2.1")
    fail(line.number, "header-version", "version " + quote(version) + " is not 2.0 or 2.1");
  out_.info.version = std::string(version);

  const std::size_t name_start = std::min(rest.find_first_not_of(" \t"), rest.size());
  std::string_view name = rest.substr(name_start);
  name.remove_suffix(name.size() - (name.find_last_not_of(" \t") + 1));
  out_.info.name_has_spaces = name.find_first_of(" \t") != std::string_view::npos;
  bool repaired = false;
  out_.sequence.name = repair_utf8(name, repaired);
  if (repaired)
    warn(line.number, "name-encoding", "the name is not UTF-8; invalid bytes became U+FFFD");

  out_.sequence.rate = read_fps(fps, line.number);

  const auto d = parse_decimal(count);
  const auto n = d && !d->negative && !d->has_point ? parse_digits(d->whole) : std::nullopt;
  if (!n)
    fail(line.number, "header-count", "frame count " + quote(count) + " is not a whole number");
  if (*n > kFapTextMaxFrames)
    fail(line.number, "header-count",
         "frame count " + std::to_string(*n) + " is more than the " +
             std::to_string(kFapTextMaxFrames) + " frames a .fap file may hold");
  out_.info.header_frame_count = *n;
}

// fps: an integer or a decimal with at most 6 fractional digits, 0 < fps <= 1000. A decimal
// that is N x 1000/1001 (N in kNtscBases) rounded to the digits written, with at least two
// of them, is read as exactly N x 1000/1001; any other decimal as its exact value.
FrameRate FapTextReader::read_fps(std::string_view token, std::uint64_t line) {
  const auto d = parse_decimal(token);
  if (!d || d->fraction.size() > kMaxFpsDigits)
    fail(line, "header-fps",
         "fps " + quote(token) + " is not a number with at most 6 decimal places");
  std::uint64_t scale = 1;
  for (std::size_t i = 0; i < d->fraction.size(); ++i) scale *= 10;
  // At most 7 whole digits keeps raw * 1000 far inside uint64.
  const std::uint64_t raw =
      d->whole.size() > 7 ? 0 : *parse_digits(d->whole) * scale + *parse_digits(d->fraction);
  if (d->negative || raw == 0 || raw * 1000 > kMaxFpsMillis * scale)
    fail(line, "fps-range", "fps " + quote(token) + " is not in (0, 1000]");
  if (d->fraction.size() >= 2) {
    for (const std::uint32_t base : kNtscBases) {
      const auto diff = static_cast<std::int64_t>(raw * 1001) -
                        static_cast<std::int64_t>(std::uint64_t{base} * 1000 * scale);
      if (2 * (diff < 0 ? -diff : diff) < 1001) return FrameRate{base * 1000, 1001};
    }
  }
  const std::uint64_t g = std::gcd(raw, scale);
  return FrameRate{static_cast<std::uint32_t>(raw / g), static_cast<std::uint32_t>(scale / g)};
}

FapMask FapTextReader::read_mask(const Line& line) {
  const Tokens t = split(line.text);
  if (mask_tokens_ == 0) {
    if (t.count != kMaskTokensStrict && t.count != kMaskTokens69)
      fail(line.number, "mask-token-count",
           "a mask line has 68 tokens (or 69 in the 69-token dialect), this one has " +
               std::to_string(t.count));
    mask_tokens_ = static_cast<int>(t.count);
    first_mask_line_ = line.number;
    out_.info.dialect = t.count == kMaskTokens69 ? FapTextDialect::kMask69 : FapTextDialect::kStrict;
  } else if (t.count != static_cast<std::size_t>(mask_tokens_)) {
    fail(line.number, "mask-token-count",
         "this mask line has " + std::to_string(t.count) + " tokens; the first one (line " +
             std::to_string(first_mask_line_) + ") had " + std::to_string(mask_tokens_));
  }
  FapMask mask;
  for (std::size_t i = 0; i < t.count; ++i) {
    if (t[i] != "0" && t[i] != "1")
      fail(line.number, "mask-token",
           "mask token " + std::to_string(i + 1) + " is " + quote(t[i]) + ", not 0 or 1");
    // In the 69-token dialect token 1 is an unused slot: FAP n is token n+1.
    const int fap = static_cast<int>(i) + (mask_tokens_ == kMaskTokens69 ? 0 : 1);
    if (fap >= 1 && t[i] == "1") mask.set(fap);
  }
  return mask;
}

// A value token: an integer, or a decimal rounded half away from zero (with a warning).
// Exact digit arithmetic: no binary floating point is involved.
std::int64_t FapTextReader::number(std::string_view token, std::uint64_t line, std::string_view what) {
  const auto d = parse_decimal(token);
  if (!d) fail(line, "value-token", std::string(what) + " " + quote(token) + " is not a number");
  const auto whole = parse_digits(d->whole);
  constexpr std::uint64_t kMaxNegative = std::uint64_t{1} << 31;  // |INT32_MIN|
  const bool round_up = !d->fraction.empty() && d->fraction[0] >= '5';
  const std::uint64_t magnitude = whole && *whole <= kMaxNegative ? *whole + round_up : ~0ull;
  if (magnitude > (d->negative ? kMaxNegative : kMaxNegative - 1))
    fail(line, "value-range", std::string(what) + " " + quote(token) + " is outside int32");
  const auto m = static_cast<std::int64_t>(magnitude);
  const std::int64_t v = d->negative ? -m : m;
  if (d->has_point) {
    out_.info.real_valued_tokens = true;
    warn(line, "real-value", quote(token) + " rounded to " + std::to_string(v));
  }
  return v;
}

std::uint8_t FapTextReader::field(std::string_view token, std::uint64_t line, const char* rule,
                                  const char* name, int max) {
  const std::int64_t v = number(token, line, name);
  if (v < 0 || v > max)
    fail(line, rule,
         std::string(name) + " is " + std::to_string(v) + ", not in 0.." + std::to_string(max));
  return static_cast<std::uint8_t>(v);
}

// Fills the frames before `frame_number` that the file skipped: each holds the frame before it
// (as players do); skipped frames before the first record are neutral (nothing masked).
void FapTextReader::hold_until(std::uint64_t frame_number, std::uint64_t line) {
  auto& frames = out_.sequence.frames;
  if (frame_number - frames.size() > kFapTextMaxHeldFrames)
    fail(line, "frame-gap",
         "frame " + std::to_string(frame_number) + " skips " +
             std::to_string(frame_number - frames.size()) + " frames; a skip may hold at most " +
             std::to_string(kFapTextMaxHeldFrames));
  if (frames.empty()) {
    warn(line, "first-frame",
         "the first frame is " + std::to_string(frame_number) + "; frames before it are neutral");
    first_frame_warning_ = out_.info.warning_count;
  }
  ++held_runs_;
  out_.info.skipped_frames = true;
  const FapFrame held = frames.empty() ? FapFrame{} : frames.back();
  frames.resize(frame_number, held);
}

void FapTextReader::read_frame(const FapMask& mask, std::uint64_t mask_line, const Line& values) {
  const bool fap12 = mask.test(kVisemeFap) || mask.test(kExpressionFap);
  if (mask_tokens_ == kMaskTokens69) single_fap12_ = true;
  const auto expected_for = [&](bool single) {
    return 1 + (mask.test(kVisemeFap) ? (single ? 1 : kVisemeFieldsStrict) : 0) +
           (mask.test(kExpressionFap) ? (single ? 1 : kExpressionFieldsStrict) : 0) +
           static_cast<std::size_t>(mask.count() - mask.test(kVisemeFap) - mask.test(kExpressionFap));
  };
  const Tokens t = split(values.text);
  if (fap12 && !single_fap12_ && t.count == expected_for(true)) {
    single_fap12_ = true;  // a file written for Greta or VREng
    out_.info.single_fap12 = true;
  }
  if (fap12 && !single_fap12_) single_fap12_ = false;
  const bool d69 = single_fap12_.value_or(false);
  const std::size_t expected = expected_for(d69);
  if (t.count != expected)
    fail(values.number, "value-count",
         std::to_string(t.count) + " tokens where the mask at line " + std::to_string(mask_line) +
             " asks for " + std::to_string(expected) + " (frame number + values" +
             (fap12 && out_.info.single_fap12 ? "; FAP 1 and 2 one integer each, as in the file's earlier frames" : "") +
             ")");

  const auto fd = parse_decimal(t[0]);
  const auto fn = fd && !fd->negative && !fd->has_point ? parse_digits(fd->whole) : std::nullopt;
  if (!fn)
    fail(values.number, "frame-number",
         "frame number " + quote(t[0]) + " is not a whole number >= 0");
  auto& frames = out_.sequence.frames;
  if (!first_number_) first_number_ = *fn;
  // A file numbered 1..N under a count of N (VREng's own eyes.fap): read one-based, in order,
  // as VREng plays it (frames by order), not with a neutral frame 0 and frame N past the count.
  if (frame_offset_ == 0 && *first_number_ == 1 && *fn == out_.info.header_frame_count && first_frame_warning_ != 0 &&
      !frames.empty()) {
    frames.erase(frames.begin());
    frame_offset_ = 1;
    if (first_frame_warning_ <= out_.info.warnings.size()) {
      out_.info.warnings.erase(out_.info.warnings.begin() + static_cast<std::ptrdiff_t>(first_frame_warning_ - 1));
      --out_.info.warning_count;
    }
    out_.info.skipped_frames = held_runs_ > 1;
    out_.info.one_based = true;
    warn(values.number, "one-based-frames",
         "frames numbered from 1 up to the header's count of " + std::to_string(out_.info.header_frame_count) +
             ": read as 0.." + std::to_string(out_.info.header_frame_count - 1) +
             " in order, as VREng plays them (Xface would index past its frames)");
  }
  const std::uint64_t slot = *fn - frame_offset_;
  if (slot < frames.size())
    fail(values.number, "frame-order",
         "frame " + std::to_string(*fn) + " follows frame " + std::to_string(frames.size() - 1 + frame_offset_) +
             ": frame numbers must increase");
  if (slot >= out_.info.header_frame_count)
    fail(values.number, "frame-past-count",
         "frame " + std::to_string(*fn) + " is past the header's count of " +
             std::to_string(out_.info.header_frame_count) + " frames");
  if (slot > frames.size()) hold_until(slot, values.number);

  FapFrame f;
  f.mask = mask;
  std::size_t i = 1;
  const std::uint64_t ln = values.number;
  if (mask.test(kVisemeFap)) {
    auto& v = f.viseme;
    v.select1 = field(t[i++], ln, "viseme-range", "viseme_select1", kLastViseme);
    if (d69) {
      v.blend = kFullWeight;
    } else {
      v.select2 = field(t[i++], ln, "viseme-range", "viseme_select2", kLastViseme);
      v.blend = field(t[i++], ln, "viseme-range", "viseme_blend", kMaxWeight);
      v.def = field(t[i++], ln, "viseme-range", "viseme_def", 1) != 0;
    }
  }
  if (mask.test(kExpressionFap)) {
    auto& e = f.expression;
    e.select1 = field(t[i++], ln, "expression-range", "expression_select1", kLastExpression);
    if (d69) {
      e.intensity1 = kFullWeight;
    } else {
      e.intensity1 = field(t[i++], ln, "expression-range", "expression_intensity1", kMaxWeight);
      e.select2 = field(t[i++], ln, "expression-range", "expression_select2", kLastExpression);
      e.intensity2 = field(t[i++], ln, "expression-range", "expression_intensity2", kMaxWeight);
      e.init_face = field(t[i++], ln, "expression-range", "init_face", 1) != 0;
      e.def = field(t[i++], ln, "expression-range", "expression_def", 1) != 0;
    }
  }
  for (int n = kFirstLowLevelFap; n <= kFapCount; ++n)
    if (mask.test(n))
      f.values[static_cast<std::size_t>(n - 1)] =
          static_cast<std::int32_t>(number(t[i++], ln, fap_info(n).name.data()));
  frames.push_back(f);
  ++out_.info.frame_records;
}

// The header's count may exceed the frames the file holds by a little (a writer that counted
// one too many): up to max(1, count/100) frames short is accepted with a warning. More than
// that is a file that is not what its header says, and is refused.
void FapTextReader::check_count_against_file() {
  const std::uint64_t claimed = out_.info.header_frame_count;
  const std::uint64_t held = out_.sequence.frames.size();
  if (claimed == held) return;
  const std::uint64_t tolerance = std::max<std::uint64_t>(1, claimed / 100);
  if (claimed - held > tolerance)
    fail(header_line_, "header-count-beyond-file",
         "the header claims " + std::to_string(claimed) + " frames; the file holds " +
             std::to_string(held));
  out_.info.header_count_short = true;
  warn(header_line_, "header-count-short",
       "the header claims " + std::to_string(claimed) + " frames; the file holds " +
           std::to_string(held) + ", which are used");
}

FapTextRead FapTextReader::run() {
  constexpr std::string_view kBom = "\xEF\xBB\xBF";  // Windows editors write one
  if (bytes_.substr(0, kBom.size()) == kBom) {
    pos_ = kBom.size();
    out_.info.utf8_bom = true;
  }
  const auto header = next_line();
  if (!header) fail(line_number_ == 0 ? 1 : line_number_, "missing-header", "the file has no header line");
  read_header(*header);
  while (const auto mask_line = next_line()) {
    const FapMask mask = read_mask(*mask_line);
    const auto values = next_line();
    if (!values)
      fail(mask_line->number, "truncated",
           "the file ends after this mask line, without its value line");
    read_frame(mask, mask_line->number, *values);
  }
  check_count_against_file();
  if (out_.info.warning_count > out_.info.warnings.size())
    out_.info.warnings.push_back(std::string(source_) + ": " +
                                 std::to_string(out_.info.warning_count - out_.info.warnings.size()) +
                                 " more warnings not shown");
  return std::move(out_);
}

void append_int(std::string& out, std::int64_t v) {
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

}  // namespace

std::string FapTextInfo::describe() const {
  std::string s = dialect == FapTextDialect::kMask69 ? "69-token masks" : "68-token masks";
  const std::pair<bool, const char*> flags[] = {
      {utf8_bom, "UTF-8 BOM"},
      {crlf, "CRLF"},
      {tabs, "tabs"},
      {comments, "comments"},
      {name_has_spaces, "name with spaces"},
      {skipped_frames, "skipped frames"},
      {real_valued_tokens, "real-valued tokens"},
      {header_count_short, "header count short"},
      {single_fap12, "FAP 1/2 one integer each"},
      {one_based, "frames numbered from 1"},
  };
  for (const auto& [on, what] : flags)
    if (on) s += std::string(", ") + what;
  return s;
}

FapTextRead read_fap_text(std::string_view bytes, std::string_view source) {
  return FapTextReader(bytes, source).run();
}

std::string fap_text_name(std::string_view name) {
  bool repaired = false;
  std::string s = repair_utf8(name, repaired);
  for (char& c : s)
    if (static_cast<unsigned char>(c) <= 0x20 || c == 0x7F) c = '_';
  return s.empty() ? "unnamed" : s;
}

std::string fap_text_fps(FrameRate rate) {
  if (!rate.valid()) throw std::invalid_argument("frame rate with a zero term");
  // The shortest spelling with 0..6 decimal places that is within 0.001 fps of the rate (so
  // that naive readers are close too: 23.976, not 23.98) and that this reader maps back to it.
  std::uint64_t scale = 1;
  for (int digits = 0; digits <= kMaxFpsDigits; ++digits, scale *= 10) {
    const std::uint64_t num = rate.numerator, den = rate.denominator;
    const std::uint64_t scaled = (2 * num * scale + den) / (2 * den);
    const std::uint64_t error = scaled * den > num * scale ? scaled * den - num * scale
                                                           : num * scale - scaled * den;
    if (error * 1000 >= scale * den) continue;
    std::string s = std::to_string(scaled / scale);
    if (digits > 0) {
      const std::string frac = std::to_string(scaled % scale);
      s += "." + std::string(static_cast<std::size_t>(digits) - frac.size(), '0') + frac;
    }
    try {
      if (read_fap_text("2.1 x " + s + " 0\n", "").sequence.rate == rate) return s;
    } catch (const InputError&) {
      // 0 or above 1000 fps at this precision: try the next one
    }
  }
  throw std::invalid_argument("frame rate " + std::to_string(rate.numerator) + "/" +
                              std::to_string(rate.denominator) +
                              " has no exact decimal form in a .fap header");
}

FapFrame as_mask69(const FapFrame& frame) {
  FapFrame f = frame;
  if (f.mask.test(kVisemeFap)) f.viseme = VisemeField{frame.viseme.select1, 0, kFullWeight, false};
  if (f.mask.test(kExpressionFap))
    f.expression = ExpressionField{frame.expression.select1, kFullWeight, 0, 0, false, false};
  return f;
}

std::size_t mask69_lossy_frames(const FapSequence& seq) {
  return static_cast<std::size_t>(std::count_if(seq.frames.begin(), seq.frames.end(),
                                                [](const FapFrame& f) { return as_mask69(f) != f; }));
}

namespace {

bool whole_fps(FrameRate rate) { return rate.valid() && rate.numerator % rate.denominator == 0; }

bool masks_fap12(const FapSequence& seq) {
  return std::any_of(seq.frames.begin(), seq.frames.end(),
                     [](const FapFrame& f) { return f.mask.test(kVisemeFap) || f.mask.test(kExpressionFap); });
}

// The two lines of frame number k. mask69: the 69-token mask; single: FAP 1 and FAP 2 as one
// integer each.
void append_frame(std::string& out, const FapFrame& f, std::uint64_t k, bool mask69, bool single) {
  if (mask69) out += "0 ";
  for (int n = 1; n <= kFapCount; ++n) {
    out += f.mask.test(n) ? '1' : '0';
    out += n == kFapCount ? '\n' : ' ';
  }
  append_int(out, static_cast<std::int64_t>(k));
  auto put = [&](std::int64_t v) {
    out += ' ';
    append_int(out, v);
  };
  if (f.mask.test(kVisemeFap)) {
    put(f.viseme.select1);
    if (!single) {
      put(f.viseme.select2);
      put(f.viseme.blend);
      put(f.viseme.def);
    }
  }
  if (f.mask.test(kExpressionFap)) {
    put(f.expression.select1);
    if (!single) {
      put(f.expression.intensity1);
      put(f.expression.select2);
      put(f.expression.intensity2);
      put(f.expression.init_face);
      put(f.expression.def);
    }
  }
  for (int n = kFirstLowLevelFap; n <= kFapCount; ++n)
    if (f.mask.test(n)) put(f.value(n));
  out += '\n';
}

void check_frame_count(std::uint64_t frames) {
  if (frames > kFapTextMaxFrames)  // the reader would refuse the file
    throw std::invalid_argument(std::to_string(frames) + " frames: a .fap file holds at most " +
                                std::to_string(kFapTextMaxFrames));
}

std::string header_line(std::string_view name, FrameRate rate, std::uint64_t frames) {
  return "2.1 " + fap_text_name(name) + " " + fap_text_fps(rate) + " " + std::to_string(frames) + "\n";
}

std::string write_text(const FapSequence& seq, bool mask69, bool single) {
  check_frame_count(seq.frames.size());
  std::string out = header_line(seq.name, seq.rate, seq.frames.size());
  std::size_t values = 0;
  for (const FapFrame& f : seq.frames) values += static_cast<std::size_t>(f.mask.count());
  // Our own counts, not a file's: 137 bytes of mask, a frame number, ~8 bytes per value.
  out.reserve(out.size() + seq.frames.size() * 145 + values * 8);
  std::uint64_t k = 0;
  for (const FapFrame& f : seq.frames) append_frame(out, f, k++, mask69, single);
  return out;
}

// The layout `o` asks for, for a track at `rate`: {mask69, single}. Throws as write_fap_text does.
std::pair<bool, bool> layout(FrameRate rate, const FapTextWriteOptions& o) {
  if (!o.player) {
    const bool d69 = o.dialect == FapTextDialect::kMask69;
    return {d69, d69};
  }
  if (o.dialect == FapTextDialect::kMask69)
    throw std::invalid_argument("a player's file has 68 mask tokens: --dialect 69 and --player exclude each other");
  if (*o.player == FapPlayer::kXface) {
    if (!whole_fps(rate))
      throw std::invalid_argument("player-fps: Xface reads the fps as a whole number: " + fap_text_fps(rate) +
                                  " fps would play at " + std::to_string(rate.numerator / rate.denominator) +
                                  "; resample the track to a whole rate first");
    return {false, false};
  }
  return {false, true};  // Greta and VREng: FAP 1 and FAP 2 one integer each
}

}  // namespace

std::string write_fap_text(const FapSequence& seq, FapTextDialect dialect) {
  const bool d69 = dialect == FapTextDialect::kMask69;
  return write_text(seq, d69, d69);
}

std::optional<FapPlayer> fap_player_from_name(std::string_view name) {
  for (const FapPlayer p : {FapPlayer::kXface, FapPlayer::kGreta, FapPlayer::kVreng})
    if (name == fap_player_name(p)) return p;
  return std::nullopt;
}

const char* fap_player_name(FapPlayer player) {
  switch (player) {
    case FapPlayer::kXface: return "xface";
    case FapPlayer::kGreta: return "greta";
    case FapPlayer::kVreng: return "vreng";
  }
  return "?";
}

std::string write_fap_text(const FapSequence& seq, const FapTextWriteOptions& o) {
  const auto [mask69, single] = layout(seq.rate, o);
  return write_text(seq, mask69, single);
}

FapTextFrameWriter::FapTextFrameWriter(FrameRate rate, const FapTextWriteOptions& options) {
  std::tie(mask69_, single_) = layout(rate, options);
  stats_.rate = rate;
}

void FapTextFrameWriter::append(std::string& out, const FapFrame& frame) {
  check_frame_count(frames_ + 1);
  append_frame(out, frame, frames_++, mask69_, single_);
  stats_.fap12 = stats_.fap12 || frame.mask.test(kVisemeFap) || frame.mask.test(kExpressionFap);
  stats_.mask69_lossy += as_mask69(frame) != frame;
}

std::string FapTextFrameWriter::header(std::string_view name) const { return header_line(name, stats_.rate, frames_); }

std::vector<std::string> fap_text_player_notes(const FapSequence& seq, const FapTextWriteOptions& o) {
  return fap_text_player_notes(FapTextStats{seq.rate, masks_fap12(seq), mask69_lossy_frames(seq)}, o);
}

std::vector<std::string> fap_text_player_notes(const FapTextStats& seq, const FapTextWriteOptions& o) {
  std::vector<std::string> notes;
  const bool fap12 = seq.fap12;
  if (o.dialect == FapTextDialect::kMask69) {
    notes.push_back("69 mask tokens: Greta's layout; Xface and VREng read 68 and would misread the file");
    return notes;
  }
  if (!o.player) {
    if (fap12)
      notes.push_back("FAP 1/2 written in the standard layout (4 and 6 fields), as Xface reads them; Greta and VREng "
                      "read one field each and would shift every later value: write with --player greta or "
                      "--player vreng for them");
    if (!whole_fps(seq.rate))
      notes.push_back("fps " + fap_text_fps(seq.rate) + " is not a whole number: Xface would play at " +
                      std::to_string(seq.rate.numerator / seq.rate.denominator) + " fps");
    return notes;
  }
  if (*o.player != FapPlayer::kXface && fap12) {
    const std::size_t lossy = seq.mask69_lossy;
    if (lossy > 0)
      notes.push_back(std::string("FAP 1/2 one field each, as ") + (*o.player == FapPlayer::kGreta ? "Greta" : "VREng") +
                      " reads them: " + std::to_string(lossy) +
                      " frames lose viseme_select2/blend or expression intensities (Xface would read 4 and 6 fields)");
  }
  return notes;
}

}  // namespace fapcast
