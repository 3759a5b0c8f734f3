#pragma once
// The receiving state machine of one RTP stream, without sockets: locks on one synchronisation
// source, extends sequence numbers across wraps, drops duplicates, puts packets back in order
// in a bounded buffer, declares loss when a gap outlives its wait, and after loss withholds units
// until the next intra one. It keeps RFC 3550 statistics: loss (A.3) and interarrival jitter
// (A.8). Memory is bounded whatever arrives: at most `reorder_capacity` packets are held.
#include "fapcast/core/sample_rate.hpp"
#include "fapcast/transport/rtp_packet.hpp"

#include <bitset>
#include <chrono>
#include <cstdint>
#include <map>
#include <optional>
#include <ostream>
#include <span>
#include <system_error>
#include <vector>

namespace fapcast {

struct ReceiverOptions {
  std::uint8_t payload_type = kDefaultFbaPayloadType;  // others are refused
  std::optional<std::uint32_t> ssrc;  // lock on this source; unset: on the first valid packet
  SampleRate clock_rate{48'000};     // RTP timestamp units per second (jitter is in these)
  bool fba_payload = true;            // packets carry the one-byte FBA payload header
  std::size_t reorder_capacity = 64;  // packets held waiting for an earlier one (>= 1)
  std::chrono::milliseconds reorder_delay{40};  // longest a packet waits for an earlier one
};

// A unit released in sequence order.
struct ReceivedUnit {
  std::uint64_t extended_sequence = 0;  // sequence number with wrap count (RFC 3550 A.1)
  std::uint32_t timestamp = 0;
  bool marker = false;
  bool intra = false;
  bool fapcast = false;                 // FBA: the payload header's F bit (the fapcast profile)
  bool after_loss = false;              // the first unit delivered after a gap (or the first)
  std::vector<std::uint8_t> bytes;      // the access unit (FBA) or payload (other formats)
};

struct ReceiverStats {
  std::uint64_t datagrams = 0;          // everything offered
  std::uint64_t accepted = 0;           // distinct packets of the locked source
  std::uint64_t delivered = 0;          // units handed out
  std::uint64_t lost = 0;               // sequence numbers declared lost
  std::uint64_t late = 0;               // arrived after being declared lost (discarded)
  std::uint64_t duplicates = 0;
  std::uint64_t malformed = 0;          // refused by the RTP parser or payload header check
  std::uint64_t foreign_ssrc = 0;
  std::uint64_t wrong_payload_type = 0;
  std::uint64_t sequence_jumps = 0;     // refused jumps (a confirmed jump restarts the stream)
  std::uint64_t skipped_waiting_intra = 0;  // in-order units withheld until the next intra unit
  double jitter = 0;                    // interarrival jitter J (RFC 3550 A.8), timestamp units

  // "accepted 100, delivered 90, lost 5, ..." on one line.
  friend std::ostream& operator<<(std::ostream& out, const ReceiverStats& s);
};

class RtpStreamReceiver {
 public:
  using Clock = std::chrono::steady_clock;

  explicit RtpStreamReceiver(ReceiverOptions options = {});

  // Offers one datagram that arrived at `arrival`; units now in order are appended to `out`.
  // Returns why the packet was not accepted (RtpErrc), or success.
  std::error_code on_datagram(std::span<const std::uint8_t> datagram, Clock::time_point arrival,
                              std::vector<ReceivedUnit>& out);
  // Releases units whose earlier neighbours waited longer than reorder_delay (declaring lost).
  void poll(Clock::time_point now, std::vector<ReceivedUnit>& out);
  // End of stream: releases everything held, declaring the gaps lost.
  void flush(std::vector<ReceivedUnit>& out);

  const ReceiverStats& stats() const { return stats_; }
  std::optional<std::uint32_t> locked_ssrc() const { return ssrc_; }
  // Packets waiting in the reorder buffer (never more than options.reorder_capacity).
  std::size_t held_packets() const { return held_.size(); }
  // The jitter in seconds.
  double jitter_seconds() const;

 private:
  struct Held {
    ReceivedUnit unit;
    Clock::time_point arrival;
  };
  static constexpr std::size_t kHistory = 1024;  // how far back duplicates are told from late

  void release(std::vector<ReceivedUnit>& out, std::optional<Clock::time_point> now);
  void deliver(ReceivedUnit&& unit, std::vector<ReceivedUnit>& out);
  void declare_lost(std::uint64_t from, std::uint64_t to);  // [from, to)
  void update_jitter(std::uint32_t timestamp, Clock::time_point arrival);
  void restart();

  ReceiverOptions options_;
  ReceiverStats stats_;
  std::optional<std::uint32_t> ssrc_;
  bool have_highest_ = false;
  std::uint64_t highest_ = 0;        // highest extended sequence accepted
  bool started_ = false;             // next_ is known
  std::uint64_t next_ = 0;           // next extended sequence to release
  std::optional<std::uint16_t> probation_;  // a jump is confirmed by its successor
  bool need_intra_ = true;
  bool after_loss_ = true;
  std::map<std::uint64_t, Held> held_;
  std::bitset<kHistory> received_history_;  // bit (seq % kHistory): released seq was received
  bool have_transit_ = false;
  std::int64_t last_transit_ = 0;
  Clock::time_point epoch_{};
};

}  // namespace fapcast
