#include "fapcast/transport/rtp_stream_receiver.hpp"

#include "fapcast/transport/fba_payload.hpp"
#include "fapcast/transport/rtp_error.hpp"
#include "fapcast/transport/timeline.hpp"

#include <cstdlib>

namespace fapcast {
namespace {
// RFC 3550 A.1: a jump forward beyond kMaxDropout or back beyond kMaxMisorder needs
// confirmation by the next packet before the receiver believes the sender restarted.
constexpr std::int64_t kMaxDropout = 3000;
constexpr std::int64_t kMaxMisorder = 100;
constexpr std::uint64_t kFirstCycle = 1ull << 16;  // first extended sequence lies in cycle 1
}  // namespace

std::ostream& operator<<(std::ostream& out, const ReceiverStats& s) {
  return out << "datagrams " << s.datagrams << ", accepted " << s.accepted << ", delivered "
             << s.delivered << ", lost " << s.lost << ", late " << s.late << ", duplicates "
             << s.duplicates << ", malformed " << s.malformed << ", foreign ssrc "
             << s.foreign_ssrc << ", wrong payload type " << s.wrong_payload_type
             << ", sequence jumps " << s.sequence_jumps << ", skipped waiting intra "
             << s.skipped_waiting_intra << ", jitter " << s.jitter;
}

RtpStreamReceiver::RtpStreamReceiver(ReceiverOptions options) : options_(options) {
  if (options_.reorder_capacity == 0) options_.reorder_capacity = 1;
  if (options_.reorder_capacity > kHistory / 2) options_.reorder_capacity = kHistory / 2;
  if (!options_.clock_rate.valid()) options_.clock_rate = SampleRate{1};
  ssrc_ = options_.ssrc;
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
  if (ssrc_ && *ssrc_ != h.ssrc) {
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
  if (!ssrc_) ssrc_ = h.ssrc;

  // Extend the sequence number relative to the highest one seen (RFC 3550 A.1).
  std::uint64_t ext = kFirstCycle + h.sequence;
  if (have_highest_) {
    const auto delta = static_cast<std::int16_t>(h.sequence - static_cast<std::uint16_t>(highest_));
    if (delta > kMaxDropout || delta < -kMaxMisorder) {
      if (probation_ != h.sequence) {
        probation_ = static_cast<std::uint16_t>(h.sequence + 1);
        ++stats_.sequence_jumps;
        return RtpErrc::kSequenceJump;
      }
      // Two packets in a row agree: the sender restarted its numbering.
      flush(out);
      restart();
      ext = kFirstCycle + h.sequence;
    } else {
      const std::int64_t candidate = static_cast<std::int64_t>(highest_) + delta;
      if (candidate < 0) {
        ++stats_.late;
        return RtpErrc::kLate;
      }
      ext = static_cast<std::uint64_t>(candidate);
    }
  }
  probation_.reset();
  if (started_ && ext < next_) {
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
  if (!have_highest_ || ext > highest_) highest_ = ext;
  have_highest_ = true;
  ++stats_.accepted;
  update_jitter(h.timestamp, arrival);
  unit.extended_sequence = ext;
  held_.emplace(ext, Held{std::move(unit), arrival});
  release(out, arrival);
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

void RtpStreamReceiver::flush(std::vector<ReceivedUnit>& out) { release(out, std::nullopt); }

void RtpStreamReceiver::release(std::vector<ReceivedUnit>& out,
                                std::optional<Clock::time_point> now) {
  const auto expired = [&](const Held& h) {
    return !now || *now - h.arrival >= options_.reorder_delay;
  };
  while (!held_.empty()) {
    auto first = held_.begin();
    if (!started_) {
      // The first packets may arrive out of order: wait before deciding where the stream starts.
      if (held_.size() < options_.reorder_capacity && !expired(first->second)) return;
      started_ = true;
      next_ = first->first;
    }
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

void RtpStreamReceiver::restart() {
  have_highest_ = false;
  started_ = false;
  probation_.reset();
  need_intra_ = true;
  after_loss_ = true;
  received_history_.reset();
}

}  // namespace fapcast
