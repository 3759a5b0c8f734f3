#pragma once
// Loopback helpers for the socket tests: synthetic media units, a thread that runs a receiver,
// and a lossy forwarding shim (drops, duplicates and swaps packets, seeded) between sender and
// receiver. Every wait is bounded.
#include "fapcast/transport/asio.hpp"
#include "fapcast/transport/media_unit.hpp"
#include "fapcast/transport/rtp_packet.hpp"
#include "fapcast/transport/udp_receiver.hpp"

#include <atomic>
#include <chrono>
#include <random>
#include <set>
#include <thread>
#include <vector>

namespace fapcast::test {

// Unit i: 1 ms apart at 48 kHz (so a paced test of 300 units takes 0.3 s), intra every
// `iperiod`, bytes that name i.
inline std::vector<MediaUnit> synthetic_units(int n, int iperiod, std::int64_t step = 48) {
  std::vector<MediaUnit> units;
  for (int i = 0; i < n; ++i) {
    MediaUnit u;
    u.sample = step * i;
    u.intra = i % iperiod == 0;
    u.bytes = {static_cast<std::uint8_t>(i), static_cast<std::uint8_t>(i >> 8), 0xfa, 0xce};
    u.bytes.resize(4 + static_cast<std::size_t>(i % 17), static_cast<std::uint8_t>(i * 3));
    units.push_back(std::move(u));
  }
  return units;
}

// Receives on its own io_context in a thread until idle for `idle`.
struct ReceiverThread {
  asio::io_context io;
  UdpReceiver receiver;
  RtpStreamReceiver stream;
  std::vector<ReceivedUnit> units;
  std::uint64_t filtered = 0;
  ReceiveReport report;
  std::chrono::steady_clock::time_point ended;  // when run() returned
  std::thread thread;

  ReceiverThread(udp::endpoint listen, ReceiverOptions options,
                 ReceiverSocketOptions socket = {})
      : receiver(io, listen, socket), stream(options) {}
  void start(std::chrono::milliseconds idle) {
    thread = std::thread([this, idle] {
      ReceiveLimits limits;
      limits.idle_timeout = idle;
      limits.max_duration = std::chrono::seconds(30);
      report = receiver.run(stream, limits, [this](ReceivedUnit&& u) { units.push_back(std::move(u)); });
      filtered = report.filtered;
      ended = std::chrono::steady_clock::now();
    });
  }
  void join() {
    if (thread.joinable()) thread.join();
  }
  ~ReceiverThread() { join(); }
};

// Forwards datagrams from its own port to `to`, dropping each with p_loss, sending a copy
// again with p_dup, and holding one back behind its successor with p_swap. Remembers the
// sequence numbers it forwarded. `port` 0: any free port; `drop_first` datagrams are dropped
// before any random choice (a lost start).
class LossyShim {
 public:
  LossyShim(udp::endpoint to, double p_loss, double p_dup, double p_swap, std::uint64_t seed,
            std::uint16_t port = 0, int drop_first = 0)
      : in_(io_, udp::endpoint(asio::ip::make_address("127.0.0.1"), port)),
        out_(io_, udp::v4()), to_(to), p_loss_(p_loss), p_dup_(p_dup), p_swap_(p_swap), rng_(seed),
        drop_first_(drop_first) {}
  udp::endpoint endpoint() const { return in_.local_endpoint(); }
  void start(std::chrono::milliseconds idle) {
    thread_ = std::thread([this, idle] { run(idle); });
  }
  void join() {
    if (thread_.joinable()) thread_.join();
  }
  ~LossyShim() { join(); }

  std::set<std::uint16_t> forwarded;  // distinct sequence numbers that went through
  std::uint64_t duplicates_sent = 0;
  std::uint64_t swaps = 0;
  std::uint64_t dropped = 0;

 private:
  using Bytes = std::vector<std::uint8_t>;
  void send(const Bytes& p) {
    boost::system::error_code ec;
    out_.send_to(asio::buffer(p), to_, 0, ec);
    if (p.size() >= 4) forwarded.insert(static_cast<std::uint16_t>((p[2] << 8) | p[3]));
  }
  void run(std::chrono::milliseconds idle) {
    std::uniform_real_distribution<double> u(0, 1);
    std::array<std::uint8_t, 2048> buf;
    udp::endpoint from;
    std::optional<Bytes> held;
    auto last = std::chrono::steady_clock::now();
    bool pending = false;
    for (;;) {
      if (!pending) {
        pending = true;
        in_.async_receive_from(asio::buffer(buf), from, [&](const boost::system::error_code& ec, std::size_t n) {
          pending = false;
          if (ec) return;
          last = std::chrono::steady_clock::now();
          Bytes p(buf.begin(), buf.begin() + static_cast<std::ptrdiff_t>(n));
          if (drop_first_ > 0) {
            --drop_first_;
            ++dropped;
            return;
          }
          if (u(rng_) < p_loss_) {
            ++dropped;
            return;
          }
          const bool dup = u(rng_) < p_dup_;
          if (held) {
            send(p);
            send(*held);
            held.reset();
          } else if (u(rng_) < p_swap_) {
            held = p;
            ++swaps;
          } else {
            send(p);
          }
          if (dup) {
            send(p);
            ++duplicates_sent;
          }
        });
      }
      io_.restart();
      io_.run_for(std::chrono::milliseconds(5));
      if (std::chrono::steady_clock::now() - last > idle) break;
    }
    if (held) send(*held);
    boost::system::error_code ignored;
    in_.cancel(ignored);
    io_.restart();
    io_.run_for(std::chrono::milliseconds(100));
  }

  asio::io_context io_;
  udp::socket in_;
  udp::socket out_;
  udp::endpoint to_;
  double p_loss_, p_dup_, p_swap_;
  std::mt19937_64 rng_;
  int drop_first_;
  std::thread thread_;
};

inline udp::endpoint loopback(std::uint16_t port = 0) {
  return {asio::ip::make_address("127.0.0.1"), port};
}

}  // namespace fapcast::test
