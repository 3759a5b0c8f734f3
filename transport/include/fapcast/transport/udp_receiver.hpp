#pragma once
// The sockets that feed one RtpStreamReceiver: RTP on port P and its RTCP on P+1 (RFC 3550 11),
// bound (and joined to a multicast group when the address is one), filtered by source address,
// polling the reorder buffer, stopping when the stream is over. Every wait is bounded.
#include "fapcast/transport/asio.hpp"
#include "fapcast/transport/rtp_stream_receiver.hpp"
#include "fapcast/transport/srtp_key.hpp"
#include "fapcast/transport/srtp_session.hpp"

#include <atomic>
#include <chrono>
#include <functional>
#include <optional>
#include <system_error>

namespace fapcast {

struct ReceiverSocketOptions {
  std::optional<asio::ip::address> source;     // accept datagrams from this address only
  std::optional<asio::ip::address> interface;  // interface to join a multicast group on (IPv4)
  bool rtcp = true;  // also listen for the stream's RTCP on P+1 (sender reports, BYE)
  // Set: datagrams are SRTP and SRTCP; each is authenticated and decrypted before the RTP (RTCP)
  // parser sees it, and refused (counted in srtp_stats()) when spoofed, tampered with or replayed.
  std::optional<SrtpMasterKey> srtp = std::nullopt;
};

// Why run() returned.
enum class ReceiveEnd {
  kIdle,         // idle_timeout passed without an accepted packet
  kBye,          // the validated source sent an RTCP BYE (and reorder_delay passed)
  kMaxDuration,  // max_duration passed
  kMaxUnits,     // max_units units were delivered
  kDone,         // the `done` predicate said so (e.g. the track is full)
  kStopped,      // stop() was called (e.g. from a signal handler on the same io_context)
  kSocketError,  // the socket failed (the error_code says how)
};
const char* to_string(ReceiveEnd end);

struct ReceiveLimits {
  // Stop after this long without an accepted packet: refused, malformed, filtered and foreign
  // datagrams do not count, so junk cannot keep a receiver waiting.
  std::chrono::milliseconds idle_timeout{5000};
  std::optional<std::chrono::milliseconds> max_duration;  // stop after this long regardless
  std::uint64_t max_units = UINT64_MAX;                   // stop after delivering this many
  bool stop_on_bye = true;                                // stop when the source says BYE
  std::function<bool()> done;                             // checked after every delivery batch
};

struct ReceiveReport {
  ReceiveEnd end = ReceiveEnd::kIdle;
  std::uint64_t filtered = 0;       // RTP datagrams refused by the source filter
  std::uint64_t rtcp_filtered = 0;  // RTCP datagrams from another address than the source's RTP
  std::uint64_t rtcp_datagrams = 0;
};

class UdpReceiver {
 public:
  // Binds `listen` (port 0: the system picks an RTP port whose successor is free for RTCP; a
  // multicast address: joins that group). Throws std::system_error when the sockets cannot be
  // bound or the group not joined.
  UdpReceiver(asio::io_context& io, udp::endpoint listen, ReceiverSocketOptions options = {});
  UdpReceiver(asio::io_context& io, udp::endpoint listen, ReceiverSocketOptions options,
              std::error_code& ec);

  udp::endpoint local_endpoint() const;  // the RTP port P (RTCP, if any, is P+1)
  // SRTP's counts when the options carry a key, else null.
  const SrtpStats* srtp_stats() const { return srtp_ ? &srtp_->stats() : nullptr; }

  // Receives into `stream` until a limit is reached, calling `sink` for each unit in order, then
  // flushes the stream. Runs the io_context given at construction. Throws std::system_error on a
  // socket failure.
  ReceiveReport run(RtpStreamReceiver& stream, const ReceiveLimits& limits,
                    const std::function<void(ReceivedUnit&&)>& sink);
  ReceiveReport run(RtpStreamReceiver& stream, const ReceiveLimits& limits,
                    const std::function<void(ReceivedUnit&&)>& sink, std::error_code& ec);
  // Makes a running run() return (kStopped) within one poll period. Safe from another thread
  // and from a handler on the receiver's io_context.
  void stop() { stop_ = true; }

 private:
  void open(udp::endpoint listen, std::error_code& ec);
  void open_socket(udp::socket& socket, udp::endpoint at, boost::system::error_code& ec);
  asio::io_context& io_;
  udp::socket socket_;
  udp::socket rtcp_socket_;
  ReceiverSocketOptions options_;
  std::optional<SrtpSession> srtp_;
  std::atomic<bool> stop_{false};
};

}  // namespace fapcast
