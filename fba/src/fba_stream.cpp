#include "fapcast/fba/fba_stream.hpp"

#include "fba_plane.hpp"

namespace fapcast {

using detail::IntraHeader;

struct FbaFrameEncoder::State {
  FbaEncoderOptions options;
  FrameRate rate;
  FbaCodingState coding;
  std::uint64_t frame_index = 0;
  std::uint64_t since_intra = 0;
  std::uint64_t last_bits = 0;
  std::string detail;
};

FbaFrameEncoder::FbaFrameEncoder(FbaEncoderOptions options, FrameRate rate)
    : state_(std::make_unique<State>(State{options, rate, {}, 0, 0, 0, {}})) {}
FbaFrameEncoder::~FbaFrameEncoder() = default;
FbaFrameEncoder::FbaFrameEncoder(FbaFrameEncoder&&) noexcept = default;
FbaFrameEncoder& FbaFrameEncoder::operator=(FbaFrameEncoder&&) noexcept = default;

std::error_code FbaFrameEncoder::encode(const FapFrame& frame, FbaAccessUnit& out, bool force_intra) {
  State& s = *state_;
  s.detail.clear();
  const FbaEncoderOptions& o = s.options;
  if (o.fap_quant < 0 || o.fap_quant > kMaxFapQuant || o.intra_period < 1) {
    s.detail = "options: fap_quant must be 0..31 and intra_period >= 1";
    return std::make_error_code(std::errc::invalid_argument);
  }
  const auto rate = fba_rate_fields(s.rate);
  if (!rate) {
    s.detail = "frame rate has no frame_rate(8)/seconds(4) form";
    return fba_errc::uncodable_frame_rate;
  }
  if (auto e = detail::check_codable(frame, o.fap_quant, s.frame_index, s.detail)) return e;

  FbaCodingState& c = s.coding;
  bool intra = force_intra || !c.have_intra || !(frame.mask == c.mask) ||
               s.since_intra >= static_cast<std::uint64_t>(o.intra_period);
  if (!intra) {
    const auto levels = detail::predicted_levels(c.prediction, c.coded, frame);
    intra = !detail::levels_fit(levels, c.coded, false);  // left the P range
  }
  FbaBitWriter writer;
  if (intra) {
    // No look-ahead here: I ranges sized to this frame, P ranges the FAP table's defaults.
    // Predictor 0 everywhere: without look-ahead there is nothing to choose a predictor from.
    IntraHeader header{o.fap_quant, detail::intra_range_fields(detail::intra_levels(frame, o.fap_quant), frame.mask, o.fap_quant),
                       {}, static_cast<std::uint16_t>(s.frame_index), *rate};
    for (int n = kFirstLowLevelFap; n <= kFapCount; ++n) {
      const FbaRangeFields d = fba_default_range_fields(n);
      header.ranges[static_cast<std::size_t>(n - 1)].p_min = d.p_min;
      header.ranges[static_cast<std::size_t>(n - 1)].p_max = d.p_max;
    }
    s.last_bits = detail::write_unit(c, frame, &header, writer);
    s.since_intra = 1;
  } else {
    s.last_bits = detail::write_unit(c, frame, nullptr, writer);
    ++s.since_intra;
  }
  ++s.frame_index;
  out.bytes = std::move(writer.bytes());
  out.intra = intra;
  return {};
}

const std::string& FbaFrameEncoder::error_detail() const { return state_->detail; }
const FbaCodingState& FbaFrameEncoder::coding_state() const { return state_->coding; }
std::uint64_t FbaFrameEncoder::last_bits() const { return state_->last_bits; }

struct FbaFrameDecoder::State {
  FbaCodingState coding;
  detail::PlaneInfo info;
  std::uint64_t bits = 0, error_bit = 0;
};

FbaFrameDecoder::FbaFrameDecoder() : state_(std::make_unique<State>()) {}
FbaFrameDecoder::~FbaFrameDecoder() = default;
FbaFrameDecoder::FbaFrameDecoder(FbaFrameDecoder&&) noexcept = default;
FbaFrameDecoder& FbaFrameDecoder::operator=(FbaFrameDecoder&&) noexcept = default;

std::error_code FbaFrameDecoder::decode(std::span<const std::uint8_t> access_unit, FapFrame& out) {
  if (access_unit.empty()) return std::make_error_code(std::errc::invalid_argument);
  State& s = *state_;
  return detail::read_unit(s.coding, access_unit, out, s.info, s.bits, s.error_bit);
}

void FbaFrameDecoder::reset() { state_->coding.have_intra = false; }
bool FbaFrameDecoder::needs_intra() const { return !state_->coding.have_intra; }
FrameRate FbaFrameDecoder::rate() const { return state_->coding.rate; }
const FbaCodingState& FbaFrameDecoder::coding_state() const { return state_->coding; }
std::uint64_t FbaFrameDecoder::last_bits() const { return state_->bits; }
int FbaFrameDecoder::last_skip_frames() const { return state_->info.skip_frames; }
std::uint64_t FbaFrameDecoder::error_bit() const { return state_->error_bit; }
int FbaFrameDecoder::last_frame_number() const { return state_->info.intra ? state_->info.frame_number : -1; }

}  // namespace fapcast
