#include "fapcast/transport/rtp_stream_receiver.hpp"

#include "fapcast/transport/fba_payload.hpp"
#include "fapcast/transport/rtcp_compound.hpp"
#include "fapcast/transport/rtp_error.hpp"
#include "fapcast/transport/timeline.hpp"

#include <algorithm>
#include <cstdlib>
#include <iterator>
#include <tuple>

namespace fapcast {
namespace {
// RFC 3550 A.1: a jump forward beyond kMaxDropout or back beyond kMaxMisorder needs
// confirmation by the next packet before the receiver believes the sender restarted.
constexpr std::int64_t kMaxDropout = 3000;
constexpr std::int64_t kMaxMisorder = 100;
constexpr std::uint64_t kFirstCycle = 1ull << 16;  // first extended sequence lies in cycle 1

// The extended number of `sequence` relative to `highest`, or nullopt when it is too far away.
std::optional<std::uint64_t> extend(std::uint64_t highest, std::uint16_t sequence) {
  const auto delta = static_cast<std::int16_t>(sequence - static_cast<std::uint16_t>(highest));
  if (delta > kMaxDropout || delta < -kMaxMisorder) return std::nullopt;
  const std::int64_t ext = static_cast<std::int64_t>(highest) + delta;
  if (ext < 0) return std::nullopt;
  return static_cast<std::uint64_t>(ext);
}
}  // namespace

struct RtpStreamReceiver::Candidate {
  std::uint32_t ssrc = 0;
  std::uint64_t highest = 0;              // highest extended sequence held
  std::map<std::uint64_t, Held> packets;  // at most reorder_capacity
  std::unique_ptr<UnitValidator> validator;
  Clock::time_point last_arrival{};
  bool decoded = false;  // one of its packets decoded (the start of a run): evicted last
};

std::ostream& operator<<(std::ostream& out, const ReceiverStats& s) {
  return out << "datagrams " << s.datagrams << ", accepted " << s.accepted << ", delivered "
             << s.delivered << ", lost " << s.lost << ", late " << s.late << ", duplicates "
             << s.duplicates << ", malformed " << s.malformed << ", foreign ssrc "
             << s.foreign_ssrc << ", wrong payload type " << s.wrong_payload_type
             << ", sequence jumps " << s.sequence_jumps << ", skipped waiting intra "
             << s.skipped_waiting_intra << ", probation discarded " << s.probation_discarded
             << ", validations " << s.validations << ", sender reports " << s.sender_reports
             << ", byes " << s.byes << ", rtcp refused " << s.rtcp_refused << ", jitter "
             << s.jitter;
}

RtpStreamReceiver::RtpStreamReceiver(ReceiverOptions options) : options_(std::move(options)) {
  if (options_.reorder_capacity == 0) options_.reorder_capacity = 1;
  if (options_.reorder_capacity > kHistory / 2) options_.reorder_capacity = kHistory / 2;
  if (!options_.clock_rate.valid()) options_.clock_rate = SampleRate{1};
  options_.min_sequential = std::clamp(options_.min_sequential, 1,
                                       static_cast<int>(options_.reorder_capacity));
}

RtpStreamReceiver::~RtpStreamReceiver() = default;
RtpStreamReceiver::RtpStreamReceiver(RtpStreamReceiver&&) noexcept = default;
RtpStreamReceiver& RtpStreamReceiver::operator=(RtpStreamReceiver&&) noexcept = default;

std::optional<std::uint32_t> RtpStreamReceiver::locked_ssrc() const { return ssrc_; }

bool RtpStreamReceiver::source_left(Clock::time_point now) const {
  return bye_at_ && now - *bye_at_ >= options_.reorder_delay;
}

double RtpStreamReceiver::jitter_seconds() const {
  return stats_.jitter / static_cast<double>(options_.clock_rate.hz);
}

std::error_code RtpStreamReceiver::on_datagram(std::span<const std::uint8_t> datagram,
                                               Clock::time_point arrival,
                                               std::vector<ReceivedUnit>& out) {
  ++stats_.datagrams;
  RtpPacketView packet;
  if (const auto ec = parse_rtp(datagram, packet)) {
    ++stats_.malformed;
    return ec;
  }
  const RtpHeader& h = packet.header;
  if (h.payload_type != options_.payload_type) {
    ++stats_.wrong_payload_type;
    return RtpErrc::kWrongPayloadType;
  }
  if ((options_.ssrc && *options_.ssrc != h.ssrc) || (ssrc_ && *ssrc_ != h.ssrc && !source_left(arrival))) {
    ++stats_.foreign_ssrc;
    return RtpErrc::kForeignSsrc;
  }
  ReceivedUnit unit;
  unit.timestamp = h.timestamp;
  unit.marker = h.marker;
  if (options_.fba_payload) {
    FbaPayload payload;
    if (const auto ec = parse_fba_payload(packet.payload, payload)) {
      ++stats_.malformed;
      return ec;
    }
    unit.intra = payload.intra;
    unit.fapcast = payload.fapcast;
    unit.bytes.assign(payload.access_unit.begin(), payload.access_unit.end());
  } else {
    unit.intra = true;  // every unit of a stateless format is a resumption point
    unit.bytes.assign(packet.payload.begin(), packet.payload.end());
  }
  if (ssrc_ && *ssrc_ != h.ssrc) release_source(out);  // the validated source said BYE
  if (!ssrc_) return on_probation(h, std::move(unit), arrival, out);

  // Extend the sequence number relative to the highest one accepted (RFC 3550 A.1).
  std::uint64_t ext = 0;
  if (const auto e = extend(highest_, h.sequence)) {
    ext = *e;
  } else {
    if (probation_ != h.sequence) {
      probation_ = static_cast<std::uint16_t>(h.sequence + 1);
      ++stats_.sequence_jumps;
      return RtpErrc::kSequenceJump;
    }
    // Two packets in a row agree: the sender restarted its numbering. The new numbers continue
    // in a later cycle so that extended numbers keep increasing.
    flush(out);
    restart(((highest_ >> 16) + 2) << 16 | h.sequence);
    ext = highest_;
  }
  probation_.reset();
  if (ext < next_) {
    const bool recent = next_ - ext <= kHistory;
    if (recent && received_history_.test(ext % kHistory)) {
      ++stats_.duplicates;
      return RtpErrc::kDuplicate;
    }
    ++stats_.late;
    return RtpErrc::kLate;
  }
  if (held_.contains(ext)) {
    ++stats_.duplicates;
    return RtpErrc::kDuplicate;
  }
  highest_ = std::max(highest_, ext);
  ++stats_.accepted;
  update_jitter(h.timestamp, arrival);
  unit.extended_sequence = ext;
  held_.emplace(ext, Held{std::move(unit), arrival});
  release(out, arrival);
  return {};
}

std::error_code RtpStreamReceiver::on_probation(const RtpHeader& h, ReceivedUnit&& unit,
                                                Clock::time_point arrival,
                                                std::vector<ReceivedUnit>& out) {
  auto it = std::find_if(candidates_.begin(), candidates_.end(),
                         [&](const Candidate& c) { return c.ssrc == h.ssrc; });
  if (it == candidates_.end()) {
    if (candidates_.size() >= kMaxCandidates) {
      // Room for the newcomer: the least recent source none of whose packets decoded (junk
      // under random SSRCs), else the least recent one.
      const auto oldest = std::min_element(
          candidates_.begin(), candidates_.end(), [](const Candidate& a, const Candidate& b) {
            return std::tie(a.decoded, a.last_arrival) < std::tie(b.decoded, b.last_arrival);
          });
      stats_.probation_discarded += oldest->packets.size();
      candidates_.erase(oldest);
    }
    Candidate c;
    c.ssrc = h.ssrc;
    c.highest = kFirstCycle + h.sequence;
    if (options_.make_validator) c.validator = options_.make_validator();
    candidates_.push_back(std::move(c));
    it = std::prev(candidates_.end());
  }
  Candidate& c = *it;
  c.last_arrival = arrival;
  std::uint64_t ext = 0;
  if (const auto e = extend(c.highest, h.sequence)) {
    ext = *e;
  } else {  // far from the run so far: a new run starts here
    stats_.probation_discarded += c.packets.size();
    c.packets.clear();
    ext = c.highest = kFirstCycle + h.sequence;
  }
  if (c.packets.contains(ext)) {
    ++stats_.duplicates;
    return RtpErrc::kDuplicate;
  }
  c.highest = std::max(c.highest, ext);
  unit.extended_sequence = ext;
  c.packets.emplace(ext, Held{std::move(unit), arrival});
  while (c.packets.size() > options_.reorder_capacity) {
    c.packets.erase(c.packets.begin());
    ++stats_.probation_discarded;
  }
  const auto at = c.packets.find(ext);
  if (at == c.packets.end()) return RtpErrc::kOutOfRun;  // older than everything held

  // The block of consecutive sequence numbers around the new packet, decoded from its start: a
  // run of min_sequential packets that decode validates the source.
  auto first = at;
  while (first != c.packets.begin() && std::prev(first)->first + 1 == first->first) --first;
  auto last = at;
  while (std::next(last) != c.packets.end() && std::next(last)->first == last->first + 1) ++last;
  if (c.validator) c.validator->restart();
  std::uint64_t run_start = first->first;
  int run = 0;
  bool packet_decodes = false;
  for (auto p = first;; ++p) {
    if (!c.validator || c.validator->decodes(p->second.unit)) {
      if (run == 0) run_start = p->first;
      if (p == at) packet_decodes = true;
      c.decoded = true;
      if (++run >= options_.min_sequential) {
        validate(c, run_start, arrival, out);
        return {};
      }
    } else {
      run = 0;
      if (c.validator) c.validator->restart();
    }
    if (p == last) break;
  }
  return packet_decodes ? std::error_code{} : make_error_code(RtpErrc::kUndecodable);
}

void RtpStreamReceiver::validate(Candidate& c, std::uint64_t run_start, Clock::time_point arrival,
                                 std::vector<ReceivedUnit>& out) {
  ssrc_ = c.ssrc;
  first_sequence_ = run_start;
  ++stats_.validations;
  bye_at_.reset();
  last_report_.reset();
  anchor_report_.reset();
  received_history_.reset();
  probation_.reset();
  highest_ = c.highest;
  next_ = run_start;
  need_intra_ = true;
  after_loss_ = true;
  for (auto& [seq, held] : c.packets) {
    if (seq < run_start) {
      ++stats_.probation_discarded;
      continue;
    }
    ++stats_.accepted;
    update_jitter(held.unit.timestamp, held.arrival);
    held_.emplace(seq, std::move(held));
  }
  for (const Candidate& other : candidates_)
    if (&other != &c) stats_.probation_discarded += other.packets.size();
  candidates_.clear();
  release(out, arrival);
}

void RtpStreamReceiver::release_source(std::vector<ReceivedUnit>& out) {
  flush(out);
  ssrc_.reset();
  bye_at_.reset();
  have_transit_ = false;
}

std::error_code RtpStreamReceiver::on_rtcp(std::span<const std::uint8_t> datagram,
                                           Clock::time_point arrival) {
  RtcpCompound rtcp;
  if (const auto ec = parse_rtcp_compound(datagram, rtcp)) {
    ++stats_.rtcp_refused;
    return ec;
  }
  bool ours = false;
  if (ssrc_ && rtcp.sender_report && rtcp.sender_report->ssrc == *ssrc_) {
    // Reports may arrive out of order: the latest is the one with the highest count.
    if (!last_report_ || rtcp.sender_report->packet_count >= last_report_->packet_count)
      last_report_ = rtcp.sender_report;
    const bool closing = std::find(rtcp.bye_sources.begin(), rtcp.bye_sources.end(), *ssrc_) !=
                         rtcp.bye_sources.end();
    if (!anchor_report_ && !closing) anchor_report_ = rtcp.sender_report;
    ++stats_.sender_reports;
    ours = true;
  }
  for (const std::uint32_t s : rtcp.bye_sources)
    if (ssrc_ && s == *ssrc_) {
      if (!bye_at_) bye_at_ = arrival;
      ++stats_.byes;
      ours = true;
    }
  if (!ours) {
    ++stats_.rtcp_refused;
    return RtpErrc::kForeignSsrc;
  }
  return {};
}

void RtpStreamReceiver::update_jitter(std::uint32_t timestamp, Clock::time_point arrival) {
  // RFC 3550 A.8: transit = arrival (in timestamp units) - timestamp; J += (|D| - J) / 16.
  if (epoch_ == Clock::time_point{}) epoch_ = arrival;
  const auto since = std::chrono::duration_cast<std::chrono::nanoseconds>(arrival - epoch_);
  const std::int64_t arrival_units = duration_to_samples(since, options_.clock_rate);
  // Modulo-2^32 arithmetic keeps the difference right across timestamp wraps.
  const auto transit = static_cast<std::int32_t>(static_cast<std::uint32_t>(arrival_units) - timestamp);
  if (have_transit_) {
    const std::int64_t d = std::llabs(static_cast<std::int64_t>(
        static_cast<std::int32_t>(static_cast<std::uint32_t>(transit) -
                                  static_cast<std::uint32_t>(last_transit_))));
    stats_.jitter += (static_cast<double>(d) - stats_.jitter) / 16.0;
  }
  last_transit_ = transit;
  have_transit_ = true;
}

void RtpStreamReceiver::poll(Clock::time_point now, std::vector<ReceivedUnit>& out) {
  release(out, now);
}

void RtpStreamReceiver::flush(std::vector<ReceivedUnit>& out) {
  release(out, std::nullopt);
  for (const Candidate& c : candidates_) stats_.probation_discarded += c.packets.size();
  candidates_.clear();
}

void RtpStreamReceiver::release(std::vector<ReceivedUnit>& out,
                                std::optional<Clock::time_point> now) {
  const auto expired = [&](const Held& h) {
    return !now || *now - h.arrival >= options_.reorder_delay;
  };
  while (!held_.empty()) {
    auto first = held_.begin();
    if (first->first != next_) {
      // A gap: wait for it while the buffer has room and the oldest held packet may still wait.
      bool must_skip = held_.size() >= options_.reorder_capacity || !now;
      if (!must_skip)
        for (const auto& [seq, h] : held_)
          if (expired(h)) {
            must_skip = true;
            break;
          }
      if (!must_skip) return;
      declare_lost(next_, first->first);
    }
    ReceivedUnit unit = std::move(first->second.unit);
    held_.erase(first);
    received_history_.set(next_ % kHistory);
    ++next_;
    deliver(std::move(unit), out);
  }
}

void RtpStreamReceiver::declare_lost(std::uint64_t from, std::uint64_t to) {
  stats_.lost += to - from;
  for (std::uint64_t s = from; s < to && to - s <= kHistory; ++s) received_history_.reset(s % kHistory);
  if (to - from > kHistory) received_history_.reset();
  next_ = to;
  need_intra_ = true;
  after_loss_ = true;
}

void RtpStreamReceiver::deliver(ReceivedUnit&& unit, std::vector<ReceivedUnit>& out) {
  if (need_intra_ && !unit.intra) {
    ++stats_.skipped_waiting_intra;
    return;
  }
  need_intra_ = false;
  unit.after_loss = after_loss_;
  after_loss_ = false;
  ++stats_.delivered;
  out.push_back(std::move(unit));
}

void RtpStreamReceiver::restart(std::uint64_t ext) {
  highest_ = ext;
  next_ = ext;
  probation_.reset();
  need_intra_ = true;
  after_loss_ = true;
  received_history_.reset();
}

}  // namespace fapcast
