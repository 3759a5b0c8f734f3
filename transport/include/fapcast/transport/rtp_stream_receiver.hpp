#pragma once
// The receiving state machine of one RTP stream, without sockets. A source is accepted only
// after probation (RFC 3550 8.2 and A.1, MIN_SEQUENTIAL): a run of `min_sequential` packets in
// sequence whose units also decode (`make_validator`). Once validated, a source is never
// displaced by another SSRC; only its RTCP BYE (after `reorder_delay` more) releases it, or the
// `ssrc` option names it from the start. For the validated source it extends sequence numbers
// across wraps, drops duplicates, puts packets back in order in a bounded buffer, declares loss
// when a gap outlives its wait, and after loss withholds units until the next intra one. It keeps
// RFC 3550 statistics: loss (A.3) and interarrival jitter (A.8). Memory is bounded whatever
// arrives: at most `reorder_capacity` packets are held, per source on probation too, and at most
// kMaxCandidates sources are on probation at once.
#include "fapcast/core/sample_rate.hpp"
#include "fapcast/transport/rtcp_sender_report.hpp"
#include "fapcast/transport/rtp_packet.hpp"

#include <bitset>
#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <ostream>
#include <span>
#include <system_error>
#include <vector>

namespace fapcast {

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

// Says whether the units of a source on probation decode, in sequence order from the start of
// a run (FbaUnitValidator decodes FBA access units). One per candidate source.
class UnitValidator {
 public:
  virtual ~UnitValidator() = default;
  // Whether `unit`, following the units accepted since the last restart(), decodes.
  virtual bool decodes(const ReceivedUnit& unit) = 0;
  // A new run starts: forget the units seen so far.
  virtual void restart() = 0;
};

struct ReceiverOptions {
  std::uint8_t payload_type = kDefaultFbaPayloadType;  // others are refused
  std::optional<std::uint32_t> ssrc;  // accept this source only; unset: the first one validated
  SampleRate clock_rate{48'000};      // RTP timestamp units per second (jitter is in these)
  bool fba_payload = true;            // packets carry the one-byte FBA payload header
  std::size_t reorder_capacity = 64;  // packets held waiting for an earlier one (>= 1)
  std::chrono::milliseconds reorder_delay{40};  // longest a packet waits for an earlier one
  int min_sequential = 2;             // RFC 3550 A.1 MIN_SEQUENTIAL: packets in a row to validate
  // Makes the decode check of one candidate source; empty: every parseable payload passes.
  std::function<std::unique_ptr<UnitValidator>()> make_validator;
};

struct ReceiverStats {
  std::uint64_t datagrams = 0;          // everything offered
  std::uint64_t accepted = 0;           // distinct packets of the validated source
  std::uint64_t delivered = 0;          // units handed out
  std::uint64_t lost = 0;               // sequence numbers declared lost
  std::uint64_t late = 0;               // arrived after being declared lost (discarded)
  std::uint64_t duplicates = 0;
  std::uint64_t malformed = 0;          // refused by the RTP parser or payload header check
  std::uint64_t foreign_ssrc = 0;       // other sources while one is validated (or --ssrc)
  std::uint64_t wrong_payload_type = 0;
  std::uint64_t sequence_jumps = 0;     // refused jumps (a confirmed jump restarts the stream)
  std::uint64_t skipped_waiting_intra = 0;  // in-order units withheld until the next intra unit
  std::uint64_t probation_discarded = 0;    // packets of sources never validated, or before the
                                            // validated run (undecodable, out of sequence)
  std::uint64_t validations = 0;        // sources validated (more than 1 only after a BYE)
  std::uint64_t sender_reports = 0;     // RTCP SRs of the validated source
  std::uint64_t byes = 0;               // RTCP BYEs of the validated source
  std::uint64_t rtcp_refused = 0;       // RTCP malformed or of other sources
  double jitter = 0;                    // interarrival jitter J (RFC 3550 A.8), timestamp units

  // "accepted 100, delivered 90, lost 5, ..." on one line.
  friend std::ostream& operator<<(std::ostream& out, const ReceiverStats& s);
};

class RtpStreamReceiver {
 public:
  using Clock = std::chrono::steady_clock;
  static constexpr std::size_t kMaxCandidates = 16;  // sources on probation at once

  explicit RtpStreamReceiver(ReceiverOptions options = {});
  ~RtpStreamReceiver();
  RtpStreamReceiver(RtpStreamReceiver&&) noexcept;
  RtpStreamReceiver& operator=(RtpStreamReceiver&&) noexcept;

  // Offers one RTP datagram that arrived at `arrival`; units now in order are appended to `out`.
  // Returns why the packet was not accepted (RtpErrc), or success (accepted, or held on probation).
  std::error_code on_datagram(std::span<const std::uint8_t> datagram, Clock::time_point arrival,
                              std::vector<ReceivedUnit>& out);
  // Offers one RTCP datagram (compound). A sender report of the validated source is kept; its
  // BYE marks the source as leaving: its packets are still taken for reorder_delay, then another
  // source may be validated. Returns RtpErrc::kBadRtcp or kForeignSsrc when refused.
  std::error_code on_rtcp(std::span<const std::uint8_t> datagram, Clock::time_point arrival);
  // Releases units whose earlier neighbours waited longer than reorder_delay (declaring lost).
  void poll(Clock::time_point now, std::vector<ReceivedUnit>& out);
  // End of stream: releases everything held, declaring the gaps lost.
  void flush(std::vector<ReceivedUnit>& out);

  const ReceiverStats& stats() const { return stats_; }
  // The validated source (or the `ssrc` option's, once validated).
  std::optional<std::uint32_t> locked_ssrc() const;
  // The extended sequence number the validated source's run started at (its first packet taken).
  std::optional<std::uint64_t> first_sequence() const { return first_sequence_; }
  // The validated source sent a BYE at least reorder_delay before `now`.
  bool source_left(Clock::time_point now) const;
  // The validated source's latest sender report.
  const std::optional<SenderReport>& last_sender_report() const { return last_report_; }
  // The validated source's first report made during the stream (not in a compound with its BYE):
  // its packet count says how many frames the sender sent before its RTP timestamp.
  const std::optional<SenderReport>& anchor_sender_report() const { return anchor_report_; }
  // Packets waiting in the reorder buffer (never more than options.reorder_capacity).
  std::size_t held_packets() const { return held_.size(); }
  // The jitter in seconds.
  double jitter_seconds() const;

 private:
  struct Held {
    ReceivedUnit unit;
    Clock::time_point arrival;
  };
  struct Candidate;
  static constexpr std::size_t kHistory = 1024;  // how far back duplicates are told from late

  std::error_code on_probation(const RtpHeader& h, ReceivedUnit&& unit, Clock::time_point arrival,
                               std::vector<ReceivedUnit>& out);
  void validate(Candidate& c, std::uint64_t run_start, Clock::time_point arrival,
                std::vector<ReceivedUnit>& out);
  void release_source(std::vector<ReceivedUnit>& out);
  void release(std::vector<ReceivedUnit>& out, std::optional<Clock::time_point> now);
  void deliver(ReceivedUnit&& unit, std::vector<ReceivedUnit>& out);
  void declare_lost(std::uint64_t from, std::uint64_t to);  // [from, to)
  void update_jitter(std::uint32_t timestamp, Clock::time_point arrival);
  void restart(std::uint64_t ext);

  ReceiverOptions options_;
  ReceiverStats stats_;
  std::optional<std::uint32_t> ssrc_;  // the validated source
  std::optional<std::uint64_t> first_sequence_;
  std::vector<Candidate> candidates_;  // sources on probation (none once one is validated)
  std::optional<Clock::time_point> bye_at_;
  std::optional<SenderReport> last_report_;    // the one with the highest packet count
  std::optional<SenderReport> anchor_report_;
  std::uint64_t highest_ = 0;        // highest extended sequence accepted
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
