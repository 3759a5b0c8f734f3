#include "fapcast/codec/json_export.hpp"

#include "fapcast/core/input_error.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <initializer_list>
#include <stdexcept>

namespace fapcast {
namespace {

using Json = nlohmann::ordered_json;

// The FAPU keys in file order, with the member each one fills.
struct FapuKey {
  const char* key;
  double FapuValues::*member;
};
constexpr FapuKey kFapuKeys[] = {{"MNS", &FapuValues::mns},
                                 {"MW", &FapuValues::mw},
                                 {"ENS", &FapuValues::ens},
                                 {"ES", &FapuValues::es},
                                 {"IRISD", &FapuValues::irisd}};

double frame_time_s(std::uint64_t k, FrameRate rate) {
  return static_cast<double>(k) * rate.denominator / rate.numerator;
}

// Whether frame_to_sample stays inside int64 for frames 0..last.
bool timeline_fits(std::uint64_t last, FrameRate rate, SampleRate sample_rate) {
  return static_cast<long double>(last) * sample_rate.hz * rate.denominator / rate.numerator < 4e18L;
}

Json frame_json(std::uint64_t k, const FapFrame& f, FrameRate rate,
                const std::optional<SampleRate>& sample_rate) {
  Json j;
  j["frame"] = k;
  j["time_s"] = frame_time_s(k, rate);
  if (sample_rate)
    j["sample"] = frame_to_sample(static_cast<std::int64_t>(k), rate, *sample_rate);
  Json faps = Json::object();
  for (int n = kFirstLowLevelFap; n <= kFapCount; ++n)
    if (f.mask.test(n)) faps[std::string(fap_info(n).name)] = f.value(n);
  j["faps"] = std::move(faps);
  if (f.mask.test(kVisemeFap))
    j["viseme"] = Json{{"select1", f.viseme.select1}, {"select2", f.viseme.select2},
                       {"blend", f.viseme.blend}, {"def", f.viseme.def}};
  if (f.mask.test(kExpressionFap))
    j["expression"] = Json{{"select1", f.expression.select1},
                           {"intensity1", f.expression.intensity1},
                           {"select2", f.expression.select2},
                           {"intensity2", f.expression.intensity2},
                           {"init_face", f.expression.init_face},
                           {"def", f.expression.def}};
  return j;
}

// Reading: every check names the JSON pointer of the value it refused.
class JsonTrackReader {
 public:
  explicit JsonTrackReader(std::string_view source) : source_(source) {}

  [[noreturn]] void fail(const std::string& rule, const std::string& pointer,
                         const std::string& detail) const {
    throw InputError({std::string(source_), std::nullopt, std::nullopt}, rule,
                     (pointer.empty() ? "/" : pointer) + ": " + detail);
  }

  const Json& object(const Json& j, const std::string& pointer) const {
    if (!j.is_object()) fail("not-object", pointer, std::string("expected an object, got ") + j.type_name());
    return j;
  }

  // Refuses keys outside `allowed`: a typo must not pass silently.
  void only_keys(const Json& j, const std::string& pointer,
                 std::initializer_list<std::string_view> allowed) const {
    for (const auto& [key, value] : j.items()) {
      bool known = false;
      for (std::string_view a : allowed) known = known || key == a;
      if (!known) fail("unknown-key", pointer + "/" + key, "unknown key");
    }
  }

  const Json& member(const Json& j, const std::string& pointer, const char* key) const {
    const auto it = j.find(key);
    if (it == j.end()) fail("missing-key", pointer + "/" + key, "missing");
    return *it;
  }

  std::int64_t integer(const Json& j, const std::string& pointer, std::int64_t lo,
                       std::int64_t hi, const std::string& rule) const {
    if (!j.is_number_integer()) fail("wrong-type", pointer, std::string("expected an integer, got ") + j.type_name());
    if (j.is_number_unsigned() && j.get<std::uint64_t>() > static_cast<std::uint64_t>(hi))
      fail(rule, pointer, std::to_string(j.get<std::uint64_t>()) + " is outside " +
                              std::to_string(lo) + ".." + std::to_string(hi));
    const auto v = j.get<std::int64_t>();
    if (v < lo || v > hi) fail(rule, pointer, std::to_string(v) + " is outside " + std::to_string(lo) + ".." + std::to_string(hi));
    return v;
  }

  double number(const Json& j, const std::string& pointer) const {
    if (!j.is_number()) fail("wrong-type", pointer, std::string("expected a number, got ") + j.type_name());
    return j.get<double>();
  }

  bool boolean(const Json& j, const std::string& pointer) const {
    if (!j.is_boolean()) fail("wrong-type", pointer, std::string("expected true or false, got ") + j.type_name());
    return j.get<bool>();
  }

  std::string string(const Json& j, const std::string& pointer) const {
    if (!j.is_string()) fail("wrong-type", pointer, std::string("expected a string, got ") + j.type_name());
    return j.get<std::string>();
  }

 private:
  std::string_view source_;
};

FapFrame read_frame(const JsonTrackReader& r, const Json& j, const std::string& at, std::uint64_t k,
                    FrameRate rate, const std::optional<SampleRate>& sample_rate) {
  r.object(j, at);
  r.only_keys(j, at, {"frame", "time_s", "sample", "faps", "viseme", "expression"});
  const auto index = r.integer(r.member(j, at, "frame"), at + "/frame", 0, INT64_MAX, "frame-index");
  if (static_cast<std::uint64_t>(index) != k)
    r.fail("frame-index", at + "/frame", "frame " + std::to_string(index) + " where " + std::to_string(k) + " belongs");
  const double t = r.number(r.member(j, at, "time_s"), at + "/time_s");
  const double expected = frame_time_s(k, rate);
  if (!(std::abs(t - expected) <= 1e-6))
    r.fail("frame-time", at + "/time_s", "frame " + std::to_string(k) + " is at " + std::to_string(expected) + " s");
  if (sample_rate) {
    const auto s = r.integer(r.member(j, at, "sample"), at + "/sample", 0, INT64_MAX, "frame-sample");
    const auto want = frame_to_sample(static_cast<std::int64_t>(k), rate, *sample_rate);
    if (s != want)
      r.fail("frame-sample", at + "/sample", "frame " + std::to_string(k) + " starts at sample " + std::to_string(want));
  } else if (j.contains("sample")) {
    r.fail("frame-sample", at + "/sample", "a sample position needs the header's sample_rate");
  }

  FapFrame f;
  const std::string faps_at = at + "/faps";
  const Json& faps = r.object(r.member(j, at, "faps"), faps_at);
  for (const auto& [name, value] : faps.items()) {
    const auto n = fap_number(name);
    if (!n || *n < kFirstLowLevelFap)
      r.fail("unknown-fap", faps_at + "/" + name, "not a low-level FAP name (3..68)");
    f.set(*n, static_cast<std::int32_t>(r.integer(value, faps_at + "/" + name, INT32_MIN, INT32_MAX, "fap-value")));
  }
  if (j.contains("viseme")) {
    const std::string v_at = at + "/viseme";
    const Json& v = r.object(j["viseme"], v_at);
    r.only_keys(v, v_at, {"select1", "select2", "blend", "def"});
    auto field = [&](const char* key, int hi) {
      return static_cast<std::uint8_t>(r.integer(r.member(v, v_at, key), v_at + "/" + key, 0, hi, "viseme-range"));
    };
    f.viseme.select1 = field("select1", 14);
    f.viseme.select2 = field("select2", 14);
    f.viseme.blend = field("blend", 63);
    f.viseme.def = r.boolean(r.member(v, v_at, "def"), v_at + "/def");
    f.mask.set(kVisemeFap);
  }
  if (j.contains("expression")) {
    const std::string e_at = at + "/expression";
    const Json& e = r.object(j["expression"], e_at);
    r.only_keys(e, e_at, {"select1", "intensity1", "select2", "intensity2", "init_face", "def"});
    auto field = [&](const char* key, int hi) {
      return static_cast<std::uint8_t>(r.integer(r.member(e, e_at, key), e_at + "/" + key, 0, hi, "expression-range"));
    };
    f.expression.select1 = field("select1", 6);
    f.expression.intensity1 = field("intensity1", 63);
    f.expression.select2 = field("select2", 6);
    f.expression.intensity2 = field("intensity2", 63);
    f.expression.init_face = r.boolean(r.member(e, e_at, "init_face"), e_at + "/init_face");
    f.expression.def = r.boolean(r.member(e, e_at, "def"), e_at + "/def");
    f.mask.set(kExpressionFap);
  }
  return f;
}

}  // namespace

std::string write_fap_json(const FapSequence& seq, const FapJsonOptions& options) {
  const FrameRate rate = seq.rate;
  if (!rate.valid() || rate.numerator > kFapJsonMaxRate || rate.denominator > kFapJsonMaxRate)
    throw std::invalid_argument("JSON export: frame rate terms must be 1.." + std::to_string(kFapJsonMaxRate));
  if (options.sample_rate &&
      (options.sample_rate->hz < 1 || options.sample_rate->hz > kFapJsonMaxRate ||
       !timeline_fits(seq.frames.size(), rate, *options.sample_rate)))
    throw std::invalid_argument("JSON export: sample rate must be 1.." + std::to_string(kFapJsonMaxRate) + " Hz");

  Json header;
  header["format"] = kFapJsonFormat;
  header["version"] = kFapJsonVersion;
  header["generator"] = options.generator;
  header["name"] = seq.name;
  header["frame_rate"] = Json{{"numerator", rate.numerator}, {"denominator", rate.denominator}};
  header["fps"] = rate.fps();
  header["frame_count"] = seq.frames.size();
  if (options.sample_rate) header["sample_rate"] = options.sample_rate->hz;
  if (options.fapu) {
    Json fapu;
    for (const FapuKey& k : kFapuKeys) fapu[k.key] = (*options.fapu).*k.member;
    header["fapu"] = std::move(fapu);
  }
  std::string out = "{\n";
  for (const auto& [key, value] : header.items())
    out += "  " + Json(key).dump() + ": " + value.dump() + ",\n";
  out += "  \"frames\": [";
  for (std::uint64_t k = 0; k < seq.frames.size(); ++k) {
    out += k == 0 ? "\n    " : ",\n    ";
    out += frame_json(k, seq.frames[k], rate, options.sample_rate).dump();
  }
  out += seq.frames.empty() ? "]\n}\n" : "\n  ]\n}\n";
  return out;
}

FapJsonRead read_fap_json(std::string_view bytes, std::string_view source) {
  Json doc;
  try {
    doc = Json::parse(bytes.begin(), bytes.end());
  } catch (const Json::parse_error& e) {
    throw InputError({std::string(source), std::nullopt, e.byte > 0 ? e.byte - 1 : 0},
                     "json-syntax", e.what());
  } catch (const Json::exception& e) {
    // The parser's other refusals (a number beyond double's range: out_of_range 406).
    throw InputError({std::string(source), std::nullopt, std::nullopt}, "json-syntax", e.what());
  }
  const JsonTrackReader r(source);
  r.object(doc, "");
  r.only_keys(doc, "", {"format", "version", "generator", "name", "frame_rate", "fps",
                        "frame_count", "sample_rate", "fapu", "frames"});
  if (r.string(r.member(doc, "", "format"), "/format") != kFapJsonFormat)
    r.fail("format", "/format", "expected \"" + std::string(kFapJsonFormat) + "\"");
  const Json& version = r.member(doc, "", "version");
  if (version != kFapJsonVersion)
    r.fail("format", "/version", "version " + version.dump() + " is not supported (this reader reads " + std::to_string(kFapJsonVersion) + ")");

  FapJsonRead out;
  out.options.generator = r.string(r.member(doc, "", "generator"), "/generator");
  out.sequence.name = r.string(r.member(doc, "", "name"), "/name");
  const Json& fr = r.object(r.member(doc, "", "frame_rate"), "/frame_rate");
  r.only_keys(fr, "/frame_rate", {"numerator", "denominator"});
  out.sequence.rate.numerator = static_cast<std::uint32_t>(
      r.integer(r.member(fr, "/frame_rate", "numerator"), "/frame_rate/numerator", 1, kFapJsonMaxRate, "frame-rate"));
  out.sequence.rate.denominator = static_cast<std::uint32_t>(
      r.integer(r.member(fr, "/frame_rate", "denominator"), "/frame_rate/denominator", 1, kFapJsonMaxRate, "frame-rate"));
  const FrameRate rate = out.sequence.rate;
  const double fps = r.number(r.member(doc, "", "fps"), "/fps");
  if (!(std::abs(fps - rate.fps()) <= 1e-9 * rate.fps()))
    r.fail("frame-rate", "/fps", "disagrees with frame_rate " + std::to_string(rate.fps()));

  if (doc.contains("sample_rate"))
    out.options.sample_rate = SampleRate{r.integer(doc["sample_rate"], "/sample_rate", 1, kFapJsonMaxRate, "sample-rate")};
  if (doc.contains("fapu")) {
    const Json& fapu = r.object(doc["fapu"], "/fapu");
    r.only_keys(fapu, "/fapu", {"MNS", "MW", "ENS", "ES", "IRISD"});
    FapuValues v{};
    for (const FapuKey& k : kFapuKeys) {
      const double x = r.number(r.member(fapu, "/fapu", k.key), std::string("/fapu/") + k.key);
      if (!(x > 0.0) || !std::isfinite(x)) r.fail("fapu", std::string("/fapu/") + k.key, "must be a positive length");
      v.*k.member = x;
    }
    out.options.fapu = v;
  }

  const Json& frames = r.member(doc, "", "frames");
  if (!frames.is_array()) r.fail("wrong-type", "/frames", std::string("expected an array, got ") + frames.type_name());
  const auto count = r.integer(r.member(doc, "", "frame_count"), "/frame_count", 0, INT64_MAX, "frame-count-mismatch");
  if (static_cast<std::uint64_t>(count) != frames.size())
    r.fail("frame-count-mismatch", "/frame_count",
           std::to_string(count) + " but the array holds " + std::to_string(frames.size()) + " frames");
  if (out.options.sample_rate && !timeline_fits(frames.size(), rate, *out.options.sample_rate))
    r.fail("sample-rate", "/sample_rate", "the frames' sample positions overflow 64 bits");
  out.sequence.frames.reserve(frames.size());  // the array is parsed: its size is real data
  for (std::uint64_t k = 0; k < frames.size(); ++k)
    out.sequence.frames.push_back(read_frame(r, frames[k], "/frames/" + std::to_string(k), k, rate, out.options.sample_rate));
  return out;
}

}  // namespace fapcast
