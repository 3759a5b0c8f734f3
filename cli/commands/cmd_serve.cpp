// `fapcast serve --listen HOST:PORT --token-file FILE [--config FILE] [...]`: the HTTP and
// WebSocket server that speaks text live to RTP receivers and browsers (spec/serve.md).
// Argument parsing only: the server is fapcast::Server.
#include "command.hpp"
#include "default_voice.hpp"

#include "fapcast/serve/serve_config.hpp"
#include "fapcast/serve/server.hpp"

#include <boost/asio/signal_set.hpp>

#include <csignal>
#include <iostream>
#include <memory>

namespace {
using namespace fapcast;

struct ServeArgs {
  std::string listen;
  std::string token_file;
  std::string config;
  std::vector<std::string> origins;
  std::vector<std::string> rtp_networks;
  std::string srtp_key_file;
  bool require_srtp = false;
  std::vector<std::string> voices;  // FILE (the default voice) or NAME=FILE
  std::string three_dir;
  std::uint32_t fps = 25;
  std::size_t synthesis_threads = 1;
  int pacer_priority = 0;
  std::size_t max_body = 0, max_text = 0, max_sessions = 0, max_queue = 0, max_clients = 0, max_connections = 0,
              client_queue = 0;
  bool quiet = false;
};

void run_serve(const ServeArgs& a, const CLI::App& cmd) {
  ServeConfig config;
  if (!a.config.empty()) read_serve_config(a.config, config);
  if (!a.listen.empty()) {
    const auto address = parse_listen_address(a.listen);
    boost::system::error_code numeric;
    if (address) (void)asio::ip::make_address(address->host, numeric);
    if (!address || numeric)
      throw cli::UsageError("serve: --listen '" + a.listen +
                            "': expected ADDRESS:PORT, [IPv6]:PORT or :PORT with a numeric IP address (names are not resolved)");
    config.host = address->host;
    config.port = address->port;
  }
  if (!a.token_file.empty()) config.token_file = a.token_file;
  if (config.token_file.empty()) throw cli::UsageError("serve: --token-file is required (or token_file in --config)");
  if (!a.origins.empty()) config.allowed_origins = a.origins;
  if (!a.rtp_networks.empty()) config.rtp_networks = a.rtp_networks;
  if (!a.srtp_key_file.empty()) config.srtp_key_file = a.srtp_key_file;
  if (a.require_srtp) config.require_srtp = true;
  if (!a.three_dir.empty()) config.three_dir = a.three_dir;
  if (cmd.count("--fps")) config.rate = FrameRate{a.fps, 1};
  if (cmd.count("--synthesis-threads")) config.synthesis_threads = a.synthesis_threads;
  if (cmd.count("--pacer-priority")) config.pacer_priority = a.pacer_priority;
  ServeLimits& l = config.limits;
  if (cmd.count("--max-body-bytes")) l.max_body_bytes = a.max_body;
  if (cmd.count("--max-text-bytes")) l.max_text_bytes = a.max_text;
  if (cmd.count("--max-sessions")) l.max_sessions = a.max_sessions;
  if (cmd.count("--max-queue")) l.max_queue = a.max_queue;
  if (cmd.count("--max-clients")) l.max_clients = a.max_clients;
  if (cmd.count("--max-connections")) l.max_connections = a.max_connections;
  if (cmd.count("--client-queue-frames")) l.client_queue_frames = a.client_queue;
  for (const std::string& v : a.voices) {
    const auto eq = v.find('=');
    if (eq == std::string::npos) config.voices["default"] = v;
    else config.voices[v.substr(0, eq)] = v.substr(eq + 1);
  }
  if (!config.voices.contains("default")) config.voices["default"] = "";
  ServeVoices voices;
  for (const auto& [name, path] : config.voices) voices.emplace(name, cli::open_voice_or_default(path, a.quiet));

  asio::io_context io;
  std::unique_ptr<Server> server;
  // Before the server exists: a SIGTERM right after the URL is read ends it cleanly, not by signal.
  boost::asio::signal_set signals(io, SIGINT, SIGTERM);
  signals.async_wait([&](const boost::system::error_code& ec, int) {
    if (!ec && server) server->stop();
  });
  try {
    server = std::make_unique<Server>(io, std::move(config), std::move(voices), [](std::string_view line) {
      std::cerr << line << '\n';
    });
  } catch (const std::invalid_argument& e) {
    throw cli::UsageError(std::string("serve: ") + e.what());
  }
  std::cout << server->url() << std::endl;  // the first line: tests and scripts read it
  io.run();
  signals.cancel();
  server.reset();
}

const cli::Registration serve_command{"serve", [](CLI::App& app) {
  auto args = std::make_shared<ServeArgs>();
  auto* cmd = app.add_subcommand(
      "serve", "Serve text-to-face live: HTTP + WebSocket API, RTP (SRTP) and a browser avatar page (spec/serve.md)");
  cmd->add_option("--listen", args->listen, "HOST:PORT to listen on, [IPv6]:PORT or :PORT (default 127.0.0.1:8080; port 0: any, printed)");
  cmd->add_option("--token-file", args->token_file, "File holding the bearer token (16-512 characters of A-Z a-z 0-9 - . _ ~ +)");
  cmd->add_option("--config", args->config, "JSON configuration (spec/serve.md, \"Configuration\"); flags override it");
  cmd->add_option("--allow-origin", args->origins, "An Origin allowed besides the server's own (repeatable)");
  cmd->add_option("--allow-rtp", args->rtp_networks,
                  "A network RTP may be sent to, ADDRESS/BITS (repeatable; default loopback: 127.0.0.0/8 ::1/128)");
  cmd->add_option("--srtp-key-file", args->srtp_key_file, "SRTP master key (base64) for RTP destinations");
  cmd->add_flag("--require-srtp", args->require_srtp, "Refuse RTP destinations without SRTP");
  cmd->add_option("--voice", args->voices, "Voice file (the default voice), or NAME=FILE (repeatable; default: the default voice)");
  cmd->add_option("--three-dir", args->three_dir, "Folder of three.js served under /three/ (default /usr/share/javascript/three)");
  cmd->add_option("--fps", args->fps, "Frames per second of every session (default 25)")->check(CLI::Range(1, 120));
  cmd->add_option("--synthesis-threads", args->synthesis_threads, "Threads synthesising sentences (default 1)")
      ->check(CLI::Range(1, 64));
  cmd->add_option("--pacer-priority", args->pacer_priority,
                  "Run the frame pacer thread in SCHED_FIFO at this priority, 1-99 (needs CAP_SYS_NICE or RLIMIT_RTPRIO; "
                  "refused: logged, runs on); 0: the default class (default 0)")
      ->check(CLI::Range(0, 99));
  cmd->add_option("--max-body-bytes", args->max_body, "Largest request body (default 16384)")->check(CLI::Range(256, 16 << 20));
  cmd->add_option("--max-text-bytes", args->max_text, "Longest text of one request (default 4096)")->check(CLI::Range(1, 32768));
  cmd->add_option("--max-sessions", args->max_sessions, "Sessions speaking or queued (default 256)")->check(CLI::Range(1, 100000));
  cmd->add_option("--max-queue", args->max_queue, "Sessions waiting on one channel (default 8)")->check(CLI::Range(0, 10000));
  cmd->add_option("--max-clients", args->max_clients, "Live WebSocket clients (default 256)")->check(CLI::Range(0, 100000));
  cmd->add_option("--max-connections", args->max_connections, "Open TCP connections (default 512)")
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--client-queue-frames", args->client_queue,
                  "Messages waiting for one live client before it is dropped (default 25)")
      ->check(CLI::Range(1, 100000));
  cmd->add_flag("-q,--quiet", args->quiet, "No progress on standard error (request lines are still logged)");
  cmd->callback([args, cmd] { run_serve(*args, *cmd); });
}};

}  // namespace
