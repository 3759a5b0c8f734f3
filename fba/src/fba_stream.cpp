#include "fapcast/fba/fba_stream.hpp"

#include "fba_plan.hpp"
#include "fba_plane.hpp"
#include "fba_standard_planes.hpp"

#include <vector>

namespace fapcast {

using detail::FapcastIntraHeader;
using detail::StandardIntraHeader;

namespace {
constexpr int kDefaultAlphabet = 16;  // fapcast: P levels +/-16 direct in the first intra period
}  // namespace

struct FbaFrameEncoder::State {
  FbaEncoderOptions options;
  FrameRate rate;
  FbaCodingState coding;
  std::uint64_t frame_index = 0;
  std::uint64_t since_intra = 0;
  std::uint64_t last_bits = 0;
  std::uint64_t intra_planes = 0, predicted_planes = 0, recoded = 0, not_alike = 0;
  std::vector<FapFrame> period;  // fapcast: the frames since the last intra plane
  std::string detail;
};

FbaFrameEncoder::FbaFrameEncoder(FbaEncoderOptions options, FrameRate rate) : state_(std::make_unique<State>()) {
  state_->options = options;
  state_->rate = rate;
  state_->coding.profile = options.profile;
}
FbaFrameEncoder::~FbaFrameEncoder() = default;
FbaFrameEncoder::FbaFrameEncoder(FbaFrameEncoder&&) noexcept = default;
FbaFrameEncoder& FbaFrameEncoder::operator=(FbaFrameEncoder&&) noexcept = default;

std::error_code FbaFrameEncoder::encode(const FapFrame& frame, FbaAccessUnit& out, bool force_intra) {
  State& s = *state_;
  s.detail.clear();
  const FbaEncoderOptions& o = s.options;
  if (o.fap_quant < 0 || o.fap_quant > kMaxFapQuant || o.intra_period < 0) {
    s.detail = "options: fap_quant must be 0..31 and intra_period >= 0";
    return std::make_error_code(std::errc::invalid_argument);
  }
  const auto rate = fba_rate_fields(s.rate);
  if (!rate) {
    s.detail = "frame rate has no frame_rate(8) + seconds(4)/16 form";
    return fba_errc::uncodable_frame_rate;
  }
  if (auto e = detail::check_codable(o.profile, frame, o.fap_quant, s.frame_index, s.detail)) return e;
  FbaCodingState& c = s.coding;
  const auto period = static_cast<std::uint64_t>(fba_intra_period(o, s.rate, false));
  bool intra = force_intra || !c.have_intra || !(frame.mask == c.mask) || s.since_intra >= period;
  if (!intra && o.profile == FbaProfile::kStandard) {
    intra = !detail::levels_fit(detail::predicted_levels(c.prediction, c.coded, frame), c.coded, false);  // left the P range
  }
  FbaBitWriter writer(o.profile == FbaProfile::kStandard ? FbaStuffing::kReference : FbaStuffing::kContinuous);
  writer.start_code(kFbaPlaneStartCode);
  if (o.profile == FbaProfile::kStandard) {
    detail::StandardPlanes planes(writer, c, s.intra_planes, s.predicted_planes, s.recoded, s.not_alike);
    if (!intra && !planes.predicted(frame, true)) intra = true;
    if (intra) {
      // No look-ahead here: I ranges sized to this frame, P ranges kept as they are in force (the
      // defaults, unless a stream set others).
      StandardIntraHeader header;
      header.fap_quant = o.fap_quant;
      header.rate = *rate;
      if (o.time_codes) header.time_code = detail::fba_time_code(s.frame_index, s.rate);
      header.flags.i_max = header.flags.i_min = true;
      header.fields = detail::intra_range_fields(detail::intra_levels(frame, o.fap_quant), frame.mask, o.fap_quant);
      planes.intra(frame, header, true);
    }
  } else {
    if (intra) {
      // No look-ahead either: predictors, references and alphabets from the period before, when it
      // had the same FAPs (backward adaptation; the header carries the choice).
      FapcastIntraHeader header;
      if (s.period.size() >= 2 && s.period.front().mask == frame.mask) {
        header = detail::plan_fapcast_period(s.period, 0, s.period.size(), o.fap_quant, o.choose_predictors);
      } else {
        for (int n = kFirstLowLevelFap; n <= kFapCount; ++n) {
          header.p_min[static_cast<std::size_t>(n - 1)] = -kDefaultAlphabet;
          header.p_max[static_cast<std::size_t>(n - 1)] = kDefaultAlphabet;
        }
        header.log2_increment = 3;
      }
      header.fap_quant = o.fap_quant;
      header.rate = *rate;
      header.frame_number = static_cast<std::uint16_t>(s.frame_index);
      detail::write_plane(c, frame, nullptr, &header, 0, writer);
      ++s.intra_planes;
      s.period.clear();
    } else {
      detail::write_plane(c, frame, nullptr, nullptr, 0, writer);
      ++s.predicted_planes;
    }
    s.period.push_back(frame);
  }
  s.since_intra = intra ? 1 : s.since_intra + 1;
  s.last_bits = fba_bit_count(writer.position());
  writer.stuff_to_start_code();
  ++s.frame_index;
  out.bytes = std::move(writer.bytes());
  out.intra = intra;
  return {};
}

const std::string& FbaFrameEncoder::error_detail() const { return state_->detail; }
const FbaCodingState& FbaFrameEncoder::coding_state() const { return state_->coding; }
std::uint64_t FbaFrameEncoder::last_bits() const { return state_->last_bits; }
std::uint64_t FbaFrameEncoder::recoded_intra() const { return state_->recoded; }

struct FbaFrameDecoder::State {
  FbaCodingState coding;
  detail::PlaneInfo info;
  std::uint64_t bits = 0, error_bit = 0;
};

FbaFrameDecoder::FbaFrameDecoder(FbaProfile profile) : state_(std::make_unique<State>()) { state_->coding.profile = profile; }
FbaFrameDecoder::~FbaFrameDecoder() = default;
FbaFrameDecoder::FbaFrameDecoder(FbaFrameDecoder&&) noexcept = default;
FbaFrameDecoder& FbaFrameDecoder::operator=(FbaFrameDecoder&&) noexcept = default;

std::error_code FbaFrameDecoder::decode(std::span<const std::uint8_t> unit, FapFrame& out) {
  if (unit.empty()) return std::make_error_code(std::errc::invalid_argument);
  State& s = *state_;
  FbaCodingState& c = s.coding;
  s.info = detail::PlaneInfo{};
  s.bits = 0;
  s.error_bit = 0;
  // The start code is read as bytes: its 23 zeros are exactly what stuffing keeps out of a plane.
  if (unit.size() < 4 || unit[0] != 0 || unit[1] != 0 || unit[2] != 1 || unit[3] != (kFbaPlaneStartCode & 0xFF)) {
    c.have_intra = false;
    return unit.size() < 4 ? fba_errc::truncated : fba_errc::bad_start_code;
  }
  FbaBitReader in(unit.subspan(4), c.profile == FbaProfile::kStandard ? FbaStuffing::kReference : FbaStuffing::kContinuous);
  std::error_code e = detail::read_plane(c, in, out, s.info);
  s.bits = fba_bit_count(in.position()) + 32;
  if (!e) {
    // next_start_code() stuffing to the unit's end, nothing after it.
    const std::uint64_t end = in.size_bits(), at = in.position().raw_bits;
    if (end - at > 8) {
      in.fail(fba_errc::trailing_bytes);
    } else {
      const auto d = in.data();
      bool stuffing = end > at;
      for (std::uint64_t p = at; p < end && stuffing; ++p) stuffing = ((d[p / 8] >> (7 - p % 8)) & 1) == (p == at ? 0 : 1);
      if (!stuffing) in.fail(fba_errc::bad_stuffing);
    }
    e = in.error();
    if (e) c.have_intra = false;
  }
  if (e) s.error_bit = 32 + in.error_bits();
  return e;
}

void FbaFrameDecoder::reset(FbaProfile profile) {
  // After a loss the ranges the lost units set are unknown: from the defaults again, as a decoder
  // that enters here (every intra unit of fapcast's is self-contained: spec/fba.md §8).
  state_->coding = FbaCodingState{};
  state_->coding.profile = profile;
}
FbaProfile FbaFrameDecoder::profile() const { return state_->coding.profile; }
bool FbaFrameDecoder::needs_intra() const { return !state_->coding.have_intra; }
FrameRate FbaFrameDecoder::rate() const { return state_->coding.rate; }
int FbaFrameDecoder::fap_quant() const { return state_->coding.fap_quant; }
const FbaCodingState& FbaFrameDecoder::coding_state() const { return state_->coding; }
std::uint64_t FbaFrameDecoder::last_bits() const { return state_->bits; }
int FbaFrameDecoder::last_skip_frames() const { return state_->info.skip_frames; }
std::uint64_t FbaFrameDecoder::error_bit() const { return state_->error_bit; }
int FbaFrameDecoder::last_frame_number() const {
  return state_->info.intra && state_->coding.profile == FbaProfile::kFapcast ? state_->info.frame_number : -1;
}

}  // namespace fapcast
