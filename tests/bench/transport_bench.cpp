// RTP transport on loopback: one-way latency (p50, p99), packets per second one core sends and
// receives, and how many 60 fps streams one core sustains; each against a raw UDP baseline that
// moves the same bytes without RTP processing, in the same run.
//   build/dev/tests/transport_bench
#include "fapcast/transport/asio.hpp"
#include "fapcast/transport/fba_track.hpp"
#include "fapcast/transport/rtp_stream_receiver.hpp"
#include "fapcast/transport/rtp_streamer.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <thread>
#include <unordered_map>

namespace {
using namespace fapcast;
using namespace fapcast;
using Clock = std::chrono::steady_clock;

udp::endpoint loopback() { return {asio::ip::make_address("127.0.0.1"), 0}; }

// Real FBA access units of a SYNTHETIC 60 fps track (what a talking head streams).
const std::vector<MediaUnit>& sample_units() {
  static const std::vector<MediaUnit> units = [] {
    FapSequence seq;
    seq.rate = {60, 1};
    for (int k = 0; k < 600; ++k) {
      FapFrame f;
      for (int fap = 3; fap <= 20; ++fap)
        f.set(fap, static_cast<std::int32_t>(200 * std::sin(k * 0.05 + fap)));
      seq.frames.push_back(f);
    }
    std::vector<MediaUnit> out;
    FbaEncoderOptions o;
    o.intra_period = 60;
    (void)encode_track_units(seq, SampleRate{48000}, o, out);
    return out;
  }();
  return units;
}

// The datagram of packet i: RTP (header + payload header + access unit) or, for the baseline,
// the same number of bytes copied from the access unit without any RTP processing.
template <bool kRtp>
void build(std::uint64_t i, std::uint32_t ssrc, std::vector<std::uint8_t>& packet) {
  const auto& units = sample_units();
  const MediaUnit& u = units[i % units.size()];
  packet.clear();
  if constexpr (kRtp) {
    (void)pack_animation_packet(u, static_cast<std::size_t>(i), {ssrc, 0, 0}, 96, packet);
  } else {
    packet.assign(u.bytes.begin(), u.bytes.end());
    packet.resize(packet.size() + kRtpFixedHeaderBytes + 1, 0);
  }
}

double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(q * static_cast<double>(v.size() - 1))];
}

// One-way latency: the sender stamps steady_clock before building packet i; a receiver thread
// blocked in recv stamps it after the unit is handed out. One packet in flight at a time.
template <bool kRtp>
void BM_OneWayLatency(benchmark::State& state) {
  asio::io_context io;
  udp::socket rx(io, loopback());
  udp::socket tx(io, udp::v4());
  const udp::endpoint to = rx.local_endpoint();
  constexpr std::size_t kRing = 1 << 16;
  std::vector<Clock::time_point> sent(kRing);
  std::vector<double> latency_us;
  std::atomic<std::uint64_t> done{0};
  std::thread receiver([&] {
    std::array<std::uint8_t, 2048> buf;
    udp::endpoint from;
    RtpStreamReceiver stream;
    std::vector<ReceivedUnit> out;
    bool primed = false;
    std::uint64_t n = 0;
    for (;;) {
      const std::size_t len = rx.receive_from(asio::buffer(buf), from);
      if (len == 1) break;  // the stop datagram
      if constexpr (kRtp) {
        const auto now = Clock::now();
        (void)stream.on_datagram({buf.data(), len}, now, out);
        if (!primed) {  // the first packet waits to learn where the stream starts
          stream.poll(now + std::chrono::seconds(1), out);
          primed = true;
        }
        benchmark::DoNotOptimize(out.data());
        out.clear();
      }
      const auto t1 = Clock::now();
      latency_us.push_back(std::chrono::duration<double, std::micro>(t1 - sent[n % kRing]).count());
      ++n;
      done.store(n, std::memory_order_release);
    }
  });
  std::vector<std::uint8_t> packet;
  std::uint64_t i = 0;
  for (auto _ : state) {
    sent[i % kRing] = Clock::now();
    build<kRtp>(i, 1, packet);
    tx.send_to(asio::buffer(packet), to);
    ++i;
    while (done.load(std::memory_order_acquire) < i) std::this_thread::yield();
  }
  const std::uint8_t bye = 0;
  tx.send_to(asio::buffer(&bye, 1), to);
  receiver.join();
  state.counters["p50_us"] = percentile(latency_us, 0.50);
  state.counters["p99_us"] = percentile(latency_us, 0.99);
  state.counters["max_us"] = percentile(latency_us, 1.0);
  state.SetItemsProcessed(static_cast<std::int64_t>(i));
}
BENCHMARK_TEMPLATE(BM_OneWayLatency, false)->Name("OneWayLatency/raw_udp")->UseRealTime()->Iterations(20000);
BENCHMARK_TEMPLATE(BM_OneWayLatency, true)->Name("OneWayLatency/rtp")->UseRealTime()->Iterations(20000);

// Packets per second one core sends: build + send (the receiving socket is never read, so the
// kernel drops what overflows; the sender's cost is what is measured).
template <bool kRtp>
void BM_Send(benchmark::State& state) {
  asio::io_context io;
  udp::socket sink(io, loopback());
  udp::socket tx(io, udp::v4());
  const auto to = sink.local_endpoint();
  std::vector<std::uint8_t> packet;
  std::uint64_t i = 0;
  for (auto _ : state) {
    build<kRtp>(i++, 1, packet);
    boost::system::error_code ec;
    tx.send_to(asio::buffer(packet), to, 0, ec);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(i));
  if constexpr (kRtp) {  // the access-unit sizes this run carried
    std::size_t lo = SIZE_MAX, hi = 0, sum = 0;
    for (const auto& u : sample_units()) {
      lo = std::min(lo, u.bytes.size());
      hi = std::max(hi, u.bytes.size());
      sum += u.bytes.size();
    }
    state.counters["au_bytes_min"] = static_cast<double>(lo);
    state.counters["au_bytes_max"] = static_cast<double>(hi);
    state.counters["au_bytes_mean"] = static_cast<double>(sum) / static_cast<double>(sample_units().size());
  }
}
BENCHMARK_TEMPLATE(BM_Send, false)->Name("Send/raw_udp");
BENCHMARK_TEMPLATE(BM_Send, true)->Name("Send/rtp");

// Packets per second one core carries end to end: send, receive and (RTP) parse, duplicate and
// loss bookkeeping and release, both sides in one thread: the whole per-packet CPU on one core.
template <bool kRtp>
void BM_SendReceive(benchmark::State& state) {
  asio::io_context io;
  udp::socket rx(io, loopback());
  udp::socket tx(io, udp::v4());
  const auto to = rx.local_endpoint();
  std::array<std::uint8_t, 2048> buf;
  udp::endpoint from;
  RtpStreamReceiver stream;
  std::vector<ReceivedUnit> out;
  std::vector<std::uint8_t> packet;
  std::uint64_t i = 0;
  for (auto _ : state) {
    build<kRtp>(i++, 1, packet);
    tx.send_to(asio::buffer(packet), to);
    const std::size_t n = rx.receive_from(asio::buffer(buf), from);
    if constexpr (kRtp) {
      (void)stream.on_datagram({buf.data(), n}, Clock::now(), out);
      out.clear();
    }
    benchmark::DoNotOptimize(buf.data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(i));
}
BENCHMARK_TEMPLATE(BM_SendReceive, false)->Name("SendReceive/raw_udp");
BENCHMARK_TEMPLATE(BM_SendReceive, true)->Name("SendReceive/rtp");

// Many concurrent 60 fps streams on one core: N sources (SSRCs) round robin through one socket
// pair and demultiplexed by SSRC into N receivers, or one receiving socket per stream.
// streams_per_core = packets per second / 60 (sender and receiver both on this core).
void BM_ManyStreams(benchmark::State& state) {
  const auto n = static_cast<std::uint32_t>(state.range(0));
  const bool socket_per_stream = state.range(1) != 0;
  asio::io_context io;
  std::vector<udp::socket> rx;
  rx.emplace_back(io, loopback());
  if (socket_per_stream)
    for (std::uint32_t s = 1; s < n; ++s) rx.emplace_back(io, loopback());
  udp::socket tx(io, udp::v4());
  std::vector<udp::endpoint> to;
  for (auto& s : rx) to.push_back(s.local_endpoint());
  std::unordered_map<std::uint32_t, RtpStreamReceiver> receivers;
  for (std::uint32_t s = 0; s < n; ++s) receivers.emplace(s + 1, RtpStreamReceiver{});
  std::array<std::uint8_t, 2048> buf;
  udp::endpoint from;
  std::vector<ReceivedUnit> out;
  std::vector<std::uint8_t> packet;
  std::uint64_t i = 0;
  for (auto _ : state) {
    const auto stream = static_cast<std::uint32_t>(i % n);
    build<true>(i / n, stream + 1, packet);
    const std::size_t k = socket_per_stream ? stream : 0;
    tx.send_to(asio::buffer(packet), to[k]);
    const std::size_t len = rx[k].receive_from(asio::buffer(buf), from);
    RtpPacketView view;
    if (!parse_rtp({buf.data(), len}, view)) {
      const auto it = receivers.find(view.header.ssrc);
      if (it != receivers.end()) (void)it->second.on_datagram({buf.data(), len}, Clock::now(), out);
    }
    out.clear();
    ++i;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(i));
  state.counters["streams_per_core"] =
      benchmark::Counter(static_cast<double>(i) / 60.0, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ManyStreams)->Name("ManyStreams")->ArgNames({"streams", "socket_per_stream"})
    ->Args({1000, 0})->Args({1000, 1});

}  // namespace

BENCHMARK_MAIN();
