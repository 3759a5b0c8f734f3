// `fapcast serve` under load, on loopback, against the obvious alternatives in the same run
// (spec/serve.md, "Latency and load"):
//   BM_FirstFrame: POST /v1/say of a short first sentence -> the first FBA RTP packet at a UDP
//     receiver (TTS, synthesis, encoding and the send included); BM_EspeakAlone: espeak-ng alone
//     on the same sentence (its cost inside that figure).
//   BM_LiveSessions/N/P: N sessions on N channels speaking at 25 fps to one RTP receiver, the
//     server's network thread and frame pacer pinned to CPU 0 (synthesis threads and clients on
//     CPU 1), the pacer at real-time priority P (SCHED_FIFO; 0: the default class, as served by
//     default), both in the same run so that they see the same machine (and CPU 0's steal time
//     over the row: the hypervisor's share of the stalls):
//     frame-send lateness p50/p99/max as the server counts it and as the receiver sees it
//     (kernel receive timestamps against each stream's RTP clock), the network thread's CPU
//     share, the peak of sessions speaking at once and the memory per session (heap and RSS
//     growth at that peak / sessions). BM_StreamFinished/N: N RtpStreamers (what `fapcast
//     stream` runs) sending the same sentence as a finished track, one thread each, all pinned
//     to CPU 0; the same receiver measures them.
// The voice: $FAPCAST_BENCH_VOICE, else the default voice in the fapcast cache (built by `fapcast
// say`), else the small SYNTHETIC test voice (support/spoken_voice.hpp). Figures come from a
// Release build: cmake -S . -B build/rel -DCMAKE_BUILD_TYPE=Release -DFAPCAST_BENCH=ON &&
// cmake --build build/rel --target serve_bench && build/rel/tests/serve_bench
#include <benchmark/benchmark.h>
#include <espeak-ng/speak_lib.h>

#include <malloc.h>
#include <pthread.h>
#include <sched.h>
#include <sys/socket.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <limits>
#include <cstring>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <future>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "fapcast/core/file_io.hpp"
#include "fapcast/frontend/text_frontend.hpp"
#include "fapcast/serve/server.hpp"
#include "fapcast/transport/fba_track.hpp"
#include "fapcast/transport/rtp_packet.hpp"
#include "fapcast/transport/rtp_streamer.hpp"
#include "fapcast/utterance/speaker.hpp"
#include "fapcast/voice/voice.hpp"
#include "support/run_command.hpp"
#include "support/serve_client.hpp"
#include "support/spoken_voice.hpp"

namespace {
using namespace fapcast;
using Clock = std::chrono::steady_clock;

constexpr const char* kToken = "c2VjcmV0LXRva2VuLWZvci10ZXN0cw";
constexpr const char* kFirstSentence = "Hello there.";
// One sentence under the server's sentence cut (120 bytes by default), about six seconds of
// speech: one synthesis job per session, so that the sessions overlap once started.
constexpr const char* kLongSentence =
    "The quick brown fox jumps over the lazy dog while seven bright lanterns glow along the quiet harbour at night";

std::filesystem::path voice_path() {
  if (const char* v = std::getenv("FAPCAST_BENCH_VOICE")) return v;
  std::filesystem::path cache;
  if (const char* c = std::getenv("FAPCAST_CACHE_DIR")) cache = c;
  else if (const char* x = std::getenv("XDG_CACHE_HOME")) cache = std::filesystem::path(x) / "fapcast";
  else if (const char* h = std::getenv("HOME")) cache = std::filesystem::path(h) / ".cache" / "fapcast";
  std::filesystem::path newest;
  std::error_code ec;
  std::filesystem::file_time_type when{};
  for (std::filesystem::directory_iterator it(cache, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.starts_with("reference-seed1-") && name.ends_with(".fapv") && it->last_write_time() > when) {
      newest = it->path();
      when = it->last_write_time();
    }
  }
  return newest.empty() ? test::spoken_voice_file() : newest;
}

const std::filesystem::path& token_file() {
  static const std::filesystem::path file = [] {
    const std::filesystem::path dir = test::make_temp_dir("serve_bench");
    write_file_atomically(dir / "token", std::string(kToken) + "\n");
    return dir / "token";
  }();
  return file;
}

void pin_to(int cpu) {
  cpu_set_t set;
  CPU_ZERO(&set);
  CPU_SET(cpu % static_cast<int>(std::max(1u, std::thread::hardware_concurrency())), &set);
  pthread_setaffinity_np(pthread_self(), sizeof set, &set);
}

double thread_cpu_seconds(pthread_t t) {
  clockid_t id;
  timespec ts{};
  if (pthread_getcpuclockid(t, &id) != 0 || clock_gettime(id, &ts) != 0) return 0.0;
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// What the kernel's scheduler saw of one thread (/proc/self/task/TID/schedstat and status): time
// on a CPU, time runnable but waiting for one (run_delay), and how often it was preempted while
// runnable (nonvoluntary context switches).
struct ThreadSched {
  double cpu_s = 0, run_delay_s = 0;
  long preempted = 0;
};
ThreadSched thread_sched(pid_t tid) {
  ThreadSched t;
  const std::string dir = "/proc/self/task/" + std::to_string(tid);
  std::ifstream stat(dir + "/schedstat");
  long long cpu = 0, delay = 0;
  stat >> cpu >> delay;
  t.cpu_s = 1e-9 * static_cast<double>(cpu);
  t.run_delay_s = 1e-9 * static_cast<double>(delay);
  std::ifstream status(dir + "/status");
  for (std::string line; std::getline(status, line);)
    if (line.starts_with("nonvoluntary_ctxt_switches:")) t.preempted = std::stol(line.substr(27));
  return t;
}
ThreadSched operator-(ThreadSched a, const ThreadSched& b) {
  return {a.cpu_s - b.cpu_s, a.run_delay_s - b.run_delay_s, a.preempted - b.preempted};
}

// Time the hypervisor gave CPU `cpu` to others while this guest had work for it (/proc/stat
// "steal", in USER_HZ ticks): a stall no priority inside the guest can prevent.
double cpu_steal_seconds(int cpu) {
  std::ifstream stat("/proc/stat");
  const std::string name = "cpu" + std::to_string(cpu);
  for (std::string label; stat >> label;) {
    if (label != name) {
      stat.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
      continue;
    }
    long long user, nice, system, idle, iowait, irq, softirq, steal = 0;
    stat >> user >> nice >> system >> idle >> iowait >> irq >> softirq >> steal;
    return static_cast<double>(steal) / static_cast<double>(sysconf(_SC_CLK_TCK));
  }
  return 0.0;
}

std::size_t heap_bytes() { return mallinfo2().uordblks; }
std::size_t rss_bytes() {
  std::ifstream statm("/proc/self/statm");
  std::size_t pages = 0, resident = 0;
  statm >> pages >> resident;
  return resident * static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
}

// The id of this process's thread named `name` (/proc/self/task/*/comm); 0 when there is none.
pid_t thread_named(const std::string& name) {
  std::error_code ec;
  for (std::filesystem::directory_iterator it("/proc/self/task", ec), end; !ec && it != end; it.increment(ec)) {
    std::ifstream comm(it->path() / "comm");
    std::string n;
    if (std::getline(comm, n) && n == name) return static_cast<pid_t>(std::stol(it->path().filename().string()));
  }
  return 0;
}

// A server on loopback (port 0), its network thread and its frame pacer pinned to CPU 0; made
// on a thread pinned to CPU 1, so that its synthesis threads run there.
class BenchServer {
 public:
  BenchServer(std::size_t sessions, int pacer_priority) {
    ServeConfig c;
    c.pacer_priority = pacer_priority;
    c.host = "127.0.0.1";
    c.port = 0;
    c.token_file = token_file();
    c.limits.max_sessions = sessions + 8;
    c.limits.max_connections = sessions + 64;
    c.limits.max_clients = 16;
    c.limits.max_queue = 8;
    c.synthesis_threads = 1;
    ServeVoices voices;
    voices.emplace("default", Voice::open(voice_path()));
    pin_to(1);
    server_ = std::make_unique<Server>(io_, std::move(c), std::move(voices));
    thread_ = std::thread([this] {
      pin_to(0);
      io_tid_ = gettid();
      io_.run();
    });
    while (io_tid_ == 0) std::this_thread::yield();
    if ((pacer_tid_ = thread_named("fapcast-pacer")) != 0) {
      cpu_set_t set;
      CPU_ZERO(&set);
      CPU_SET(0, &set);
      sched_setaffinity(pacer_tid_, sizeof set, &set);
    }
  }
  ~BenchServer() {
    asio::post(io_, [this] { server_->stop(); });
    thread_.join();
  }
  std::uint16_t port() const { return server_->port(); }
  ServeStats stats() const { return server_->stats(); }
  double io_cpu_seconds() { return thread_cpu_seconds(thread_.native_handle()); }
  ThreadSched io_sched() const { return thread_sched(io_tid_); }
  // The frame pacer's thread (none before it had one: the network thread sent the frames).
  ThreadSched pacer_sched() const { return pacer_tid_ ? thread_sched(pacer_tid_) : ThreadSched{}; }

 private:
  std::atomic<pid_t> io_tid_{0};
  pid_t pacer_tid_ = 0;
  asio::io_context io_;
  std::unique_ptr<Server> server_;
  std::thread thread_;
};

std::string say_body(const std::string& text, const std::string& rtp, const std::string& channel, bool interrupt) {
  return nlohmann::json{{"text", text}, {"rtp", rtp}, {"channel", channel}, {"interrupt", interrupt}}.dump();
}

bool is_animation_rtp(const std::vector<std::uint8_t>& p) {
  return p.size() >= 12 && (p[0] >> 6) == 2 && (p[1] & 0x7f) == kDefaultFbaPayloadType;
}

// Animation RTP packets as they reach P: kernel receive time, SSRC, RTP timestamp; then each
// packet's lateness against its stream's own clock (the earliest packet relative to its
// timestamp is on time).
class LatenessProbe {
 public:
  explicit LatenessProbe(int fd) : fd_(fd) {
    const int on = 1;
    ::setsockopt(fd_, SOL_SOCKET, SO_TIMESTAMPNS, &on, sizeof on);
    thread_ = std::thread([this] { run(); });
  }
  ~LatenessProbe() { stop(); }
  void stop() {
    if (!thread_.joinable()) return;
    done_ = true;
    thread_.join();
  }
  std::size_t packets() const { return packets_.size(); }
  // Lateness (ns, sorted) of every packet over all streams: arrival minus the packet's media
  // time (its RTP timestamp from the stream's first, unwrapped, at `rtp_clock_hz`), less the
  // stream's smallest such offset (its most punctual packet is on time).
  std::vector<double> lateness(double rtp_clock_hz) const { return lateness(rtp_clock_hz, 0, INT64_MAX); }
  // The same, of the packets that arrived in [from_ns, to_ns) (CLOCK_REALTIME).
  std::vector<double> lateness(double rtp_clock_hz, std::int64_t from_ns, std::int64_t to_ns) const {
    std::map<std::uint32_t, std::uint32_t> first;   // ssrc -> first timestamp
    std::map<std::uint32_t, double> earliest;       // ssrc -> min(arrival - media time)
    const auto offset = [&](const Packet& p) {
      const auto elapsed = static_cast<std::int32_t>(p.timestamp - first.at(p.ssrc));
      return static_cast<double>(p.arrival_ns) - 1e9 * static_cast<double>(elapsed) / rtp_clock_hz;
    };
    for (const Packet& p : packets_) {
      first.emplace(p.ssrc, p.timestamp);
      auto [it, fresh] = earliest.emplace(p.ssrc, offset(p));
      if (!fresh) it->second = std::min(it->second, offset(p));
    }
    std::vector<double> late;
    late.reserve(packets_.size());
    for (const Packet& p : packets_)
      if (p.arrival_ns >= from_ns && p.arrival_ns < to_ns) late.push_back(offset(p) - earliest.at(p.ssrc));
    std::sort(late.begin(), late.end());
    return late;
  }
  std::size_t streams() const {
    std::map<std::uint32_t, int> s;
    for (const Packet& p : packets_) s[p.ssrc] = 1;
    return s.size();
  }

 private:
  struct Packet {
    std::int64_t arrival_ns;
    std::uint32_t ssrc;
    std::uint32_t timestamp;
  };
  void run() {
    std::vector<std::uint8_t> buffer(2048);
    char control[256];
    while (!done_) {
      pollfd p{fd_, POLLIN, 0};
      if (::poll(&p, 1, 50) <= 0) continue;
      for (;;) {
        iovec iov{buffer.data(), buffer.size()};
        msghdr m{};
        m.msg_iov = &iov;
        m.msg_iovlen = 1;
        m.msg_control = control;
        m.msg_controllen = sizeof control;
        const auto got = ::recvmsg(fd_, &m, MSG_DONTWAIT);
        if (got <= 0) break;
        if (got < 12 || (buffer[0] >> 6) != 2 || (buffer[1] & 0x7f) != kDefaultFbaPayloadType) continue;
        std::int64_t at = 0;
        for (cmsghdr* c = CMSG_FIRSTHDR(&m); c; c = CMSG_NXTHDR(&m, c))
          if (c->cmsg_level == SOL_SOCKET && c->cmsg_type == SO_TIMESTAMPNS) {
            timespec ts;
            std::memcpy(&ts, CMSG_DATA(c), sizeof ts);
            at = ts.tv_sec * 1'000'000'000LL + ts.tv_nsec;
          }
        const auto be32 = [&](std::size_t i) {
          return std::uint32_t{buffer[i]} << 24 | std::uint32_t{buffer[i + 1]} << 16 | std::uint32_t{buffer[i + 2]} << 8 |
                 buffer[i + 3];
        };
        packets_.push_back({at, be32(8), be32(4)});
      }
    }
  }
  int fd_;
  std::atomic<bool> done_{false};
  std::vector<Packet> packets_;
  std::thread thread_;
};

double quantile(const std::vector<double>& sorted, double q) {
  if (sorted.empty()) return 0.0;
  return sorted[static_cast<std::size_t>(q * static_cast<double>(sorted.size() - 1))];
}

void report_lateness(benchmark::State& state, const std::vector<double>& late, const char* prefix) {
  state.counters[std::string(prefix) + "p50_ms"] = quantile(late, 0.50) / 1e6;
  state.counters[std::string(prefix) + "p99_ms"] = quantile(late, 0.99) / 1e6;
  state.counters[std::string(prefix) + "max_ms"] = late.empty() ? 0.0 : late.back() / 1e6;
}

// --- (a) request -> first animation frame on the wire ---------------------------------------

void BM_FirstFrame(benchmark::State& state) {
  BenchServer server(4, 0);
  test::RtpPorts sink;
  const std::string body = say_body(std::string(kFirstSentence) + " And a second sentence after it.", sink.url(),
                                    "bench", true);
  const std::string request = test::json_request("POST", "/v1/say", kToken, body);
  int refused = 0;
  for (auto _ : state) {
    sink.drain();
    const auto t0 = Clock::now();
    auto answer = std::async(std::launch::async, [&] { return test::http_exchange(server.port(), request); });
    std::optional<Clock::time_point> t1;
    while (!t1) {
      const auto p = sink.receive(0, std::chrono::seconds(10));
      if (!p) break;
      if (is_animation_rtp(*p)) t1 = Clock::now();
    }
    const auto answers = answer.get();
    if (!t1 || answers.empty() || answers[0].status != 202) {
      ++refused;
      state.SkipWithError("no first frame");
      break;
    }
    state.SetIterationTime(std::chrono::duration<double>(*t1 - t0).count());
  }
  state.counters["refused"] = refused;
  state.SetLabel(voice_path().filename().string());
}
BENCHMARK(BM_FirstFrame)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(20);

int drop_audio(short*, int, espeak_EVENT*) { return 0; }

void BM_EspeakAlone(benchmark::State& state) {
  (void)speak("");  // initialises espeak-ng (en-us, synchronous) as the front-end does
  espeak_SetSynthCallback(drop_audio);
  for (auto _ : state) {
    espeak_Synth(kFirstSentence, std::strlen(kFirstSentence) + 1, 0, POS_CHARACTER, 0, espeakCHARS_UTF8, nullptr,
                 nullptr);
    espeak_Synchronize();
  }
}
BENCHMARK(BM_EspeakAlone)->Unit(benchmark::kMillisecond)->UseRealTime();

// --- (b, c) N live sessions against N streams of a finished track ---------------------------

// The finished track of the same sentence: what `fapcast say` writes and `fapcast stream` sends.
struct FinishedTrack {
  std::vector<MediaUnit> units;
  Audio audio;
};
const FinishedTrack& finished_track() {
  static const FinishedTrack track = [] {
    const Voice voice = Voice::open(voice_path());
    const Speaker speaker(voice, SpeakerSettings{}, "bench");
    SpokenSentence s = speaker.speak(kLongSentence);
    FinishedTrack t{{}, std::move(s.audio)};
    if (encode_track_units(s.faps, t.audio.sample_rate, FbaEncoderOptions{}, t.units))
      throw std::runtime_error("the track does not encode");
    return t;
  }();
  return track;
}

void BM_LiveSessions(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const auto priority = static_cast<int>(state.range(1));
  const auto rtp_clock_hz = finished_track().audio.sample_rate.hz;  // a session's RTP clock: its speech's rate
  for (auto _ : state) {
    test::RtpPorts sink;
    const std::size_t heap0 = heap_bytes();
    BenchServer server(n, priority);
    // What the pacer got: a refusal (no CAP_SYS_NICE) would make the P > 0 row the default class.
    state.counters["pacer_priority"] = server.stats().pacer_priority;
    if (server.stats().pacer_priority != priority) state.SkipWithError("the pacer did not get the priority asked for");
    const std::size_t heap1 = heap_bytes(), rss1 = rss_bytes();  // the server alone
    LatenessProbe probe(sink.fd(0));
    const double cpu0 = server.io_cpu_seconds();
    const ThreadSched sched0 = server.io_sched(), pacer0 = server.pacer_sched();
    const double steal0 = cpu_steal_seconds(0);
    const auto t0 = Clock::now();
    std::atomic<std::int64_t> ramp_end_ns{0};  // the last request answered (CLOCK_REALTIME, as the probe's)
    // Requests from 8 client threads (each answer waits for its session's first frame).
    std::atomic<std::size_t> next{0}, ok{0};
    std::vector<std::thread> clients;
    for (int c = 0; c < 8; ++c)
      clients.emplace_back([&] {
        pin_to(1);
        for (std::size_t i; (i = next++) < n;) {
          const auto a = test::http_exchange(
              server.port(),
              test::json_request("POST", "/v1/say", kToken, say_body(kLongSentence, sink.url(), "s" + std::to_string(i), false)));
          if (!a.empty() && a[0].status == 202) ++ok;
        }
        const std::int64_t now = std::chrono::duration_cast<std::chrono::nanoseconds>(
                                     std::chrono::system_clock::now().time_since_epoch()).count();
        for (std::int64_t e = ramp_end_ns; e < now && !ramp_end_ns.compare_exchange_weak(e, now);) {}
      });
    // The peak of sessions speaking at once, and the memory then.
    std::size_t peak = 0, heap_peak = heap1, rss_peak = rss1;
    for (;;) {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      const ServeStats s = server.stats();
      if (s.sessions_speaking > peak) {
        peak = s.sessions_speaking;
        heap_peak = heap_bytes();
        rss_peak = rss_bytes();
      }
      if (next >= n && s.sessions_speaking == 0 && s.sessions_queued == 0 &&
          s.sessions_done + s.sessions_failed + s.sessions_stopped >= ok)
        break;
    }
    for (auto& t : clients) t.join();
    const double wall = std::chrono::duration<double>(Clock::now() - t0).count();
    const ServeStats s = server.stats();
    const double cpu = server.io_cpu_seconds() - cpu0;
    const ThreadSched sched = server.io_sched() - sched0, pacer = server.pacer_sched() - pacer0;
    const double steal = cpu_steal_seconds(0) - steal0;
    probe.stop();
    state.counters["cpu0_steal_ms"] = 1e3 * steal;
    state.counters["sessions_ok"] = static_cast<double>(ok);
    state.counters["peak_speaking"] = static_cast<double>(peak);
    state.counters["frames"] = static_cast<double>(s.frames);
    state.counters["server_late_p50_ms"] = 1e-6 * static_cast<double>(s.late_p50.count());
    state.counters["server_late_p99_ms"] = 1e-6 * static_cast<double>(s.late_p99.count());
    state.counters["server_late_max_ms"] = 1e-6 * static_cast<double>(s.late_max.count());
    report_lateness(state, probe.lateness(static_cast<double>(rtp_clock_hz)), "rx_late_");
    // The ramp (until the last request was answered) and the steady state after it, apart.
    report_lateness(state, probe.lateness(static_cast<double>(rtp_clock_hz), 0, ramp_end_ns), "rx_ramp_late_");
    report_lateness(state, probe.lateness(static_cast<double>(rtp_clock_hz), ramp_end_ns, INT64_MAX), "rx_steady_late_");
    state.counters["rx_streams"] = static_cast<double>(probe.streams());
    state.counters["io_cpu_share"] = cpu / wall;
    // The network thread as the scheduler saw it: runnable but not running, per frame, and
    // preemptions per second.
    state.counters["io_run_delay_us_per_frame"] = s.frames ? 1e6 * sched.run_delay_s / static_cast<double>(s.frames) : 0.0;
    state.counters["io_run_delay_share"] = sched.run_delay_s / wall;
    state.counters["io_preempted_per_s"] = static_cast<double>(sched.preempted) / wall;
    state.counters["pacer_cpu_share"] = pacer.cpu_s / wall;
    state.counters["pacer_run_delay_us_per_frame"] = s.frames ? 1e6 * pacer.run_delay_s / static_cast<double>(s.frames) : 0.0;
    state.counters["pacer_preempted_per_s"] = static_cast<double>(pacer.preempted) / wall;
    state.counters["server_wake_p99_ms"] = 1e-6 * static_cast<double>(s.wake_p99.count());
    state.counters["server_wake_max_ms"] = 1e-6 * static_cast<double>(s.wake_max.count());
    state.counters["server_heap_MiB"] = static_cast<double>(heap1 - std::min(heap1, heap0)) / (1 << 20);
    state.counters["heap_per_session_KiB"] =
        peak ? static_cast<double>(heap_peak - std::min(heap_peak, heap1)) / 1024.0 / static_cast<double>(peak) : 0.0;
    state.counters["rss_per_session_KiB"] =
        peak ? static_cast<double>(rss_peak - std::min(rss_peak, rss1)) / 1024.0 / static_cast<double>(peak) : 0.0;
  }
}
// Each N at the default class, then at real-time priority 10, one after the other.
BENCHMARK(BM_LiveSessions)
    ->ArgNames({"sessions", "rt"})
    ->Args({50, 0})->Args({50, 10})->Args({100, 0})->Args({100, 10})
    ->Args({200, 0})->Args({200, 10})->Args({400, 0})->Args({400, 10})
    ->Iterations(1)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

void BM_StreamFinished(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const FinishedTrack& track = finished_track();
  for (auto _ : state) {
    test::RtpPorts sink;
    LatenessProbe probe(sink.fd(0));
    std::atomic<std::size_t> ready{0};
    std::atomic<bool> go{false};
    std::atomic<std::int64_t> late_ns{0}, packets{0};
    std::vector<std::thread> streams;
    double cpu = 0.0;
    std::mutex cpu_mutex;
    const auto t0 = Clock::now();
    for (std::size_t i = 0; i < n; ++i)
      streams.emplace_back([&] {
        pin_to(0);
        asio::io_context io;
        StreamOptions options;
        options.clock_rate = track.audio.sample_rate;
        RtpStreamer streamer(io, udp::endpoint(asio::ip::make_address("127.0.0.1"), sink.port()), options);
        ++ready;
        while (!go) std::this_thread::yield();
        const StreamReport r = streamer.run(track.units, &track.audio);
        late_ns += r.late_total.count();
        packets += static_cast<std::int64_t>(r.animation.packets + r.audio.packets);
        std::lock_guard lock(cpu_mutex);
        cpu += thread_cpu_seconds(pthread_self());
      });
    while (ready < n) std::this_thread::yield();
    go = true;
    for (auto& t : streams) t.join();
    const double wall = std::chrono::duration<double>(Clock::now() - t0).count();
    probe.stop();
    report_lateness(state, probe.lateness(static_cast<double>(track.audio.sample_rate.hz)), "rx_late_");
    state.counters["rx_streams"] = static_cast<double>(probe.streams());
    state.counters["mean_send_late_ms"] = packets ? 1e-6 * static_cast<double>(late_ns) / static_cast<double>(packets) : 0.0;
    state.counters["cpu_share"] = cpu / wall;
  }
}
BENCHMARK(BM_StreamFinished)->Arg(50)->Arg(100)->Arg(200)->Arg(400)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
