// `raycast serve SCENE [--port P] [--host H]` (docs/serve.md): a live, progressive preview of a
// scene in the browser, refreshed when the scene's files change.
#include <httplib.h>
#include <signal.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "commands.h"
#include "serve/http_routes.h"
#include "serve/preview_loop.h"

namespace raycast::cli {

namespace {

struct Options {
  std::string scene, host = "127.0.0.1";
  int port = 8080, threads = 0;
};

/// The Host header values a browser sends for this server; empty (any) when it listens on every
/// interface, since the machine's names and addresses are not known here.
std::vector<std::string> accepted_hosts(const std::string& host, int port) {
  if (host == "0.0.0.0" || host == "::") return {};
  const std::string p = ":" + std::to_string(port);
  std::vector<std::string> hosts = {host + p};
  if (host == "127.0.0.1" || host == "localhost" || host == "::1")
    for (const char* h : {"127.0.0.1", "localhost", "[::1]"}) hosts.push_back(h + p);
  if (host.find(':') != std::string::npos) hosts.push_back("[" + host + "]" + p);
  return hosts;
}

}  // namespace

Action add_serve_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "serve", "Serve a live, progressive preview of a scene in the browser (docs/serve.md)");
  auto opt = std::make_shared<Options>();
  cmd->add_option("SCENE", opt->scene, "Scene file (YAML or JSON), watched for changes")
      ->required();
  cmd->add_option("--port", opt->port, "TCP port (default 8080; 0 picks a free one)");
  cmd->add_option("--host", opt->host,
                  "Address to listen on (default 127.0.0.1: this machine only; 0.0.0.0 exposes "
                  "the preview to the network)");
  cmd->add_option("--threads", opt->threads, "Render threads (default: all cores)");
  return [opt] {
    if (opt->port < 0 || opt->port > 65535) {
      std::fprintf(stderr, "raycast serve: --port must be in [0, 65535], got %d\n", opt->port);
      return 2;
    }
    if (opt->threads < 0 || opt->threads > 4096) {
      std::fprintf(stderr, "raycast serve: --threads must be in [0, 4096], got %d\n", opt->threads);
      return 2;
    }
    std::error_code ec;
    if (!std::filesystem::is_regular_file(opt->scene, ec)) {
      std::fprintf(stderr, "raycast serve: %s: no such scene file\n", opt->scene.c_str());
      return 2;
    }

    // SIGINT and SIGTERM are taken by one thread with sigwait (blocked in every other thread),
    // which stops the server cleanly.
    sigset_t signals;
    sigemptyset(&signals);
    sigaddset(&signals, SIGINT);
    sigaddset(&signals, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &signals, nullptr);

    const serve::RouteLimits limits;
    httplib::Server server;
    // Event streams each hold a worker while open; the rest serve short requests.
    server.new_task_queue = [limits] {
      return new httplib::ThreadPool(std::size_t(limits.max_event_streams) + 8);
    };
    const int port = opt->port == 0 ? server.bind_to_any_port(opt->host)
                                    : (server.bind_to_port(opt->host, opt->port) ? opt->port : -1);
    if (port <= 0) {
      std::fprintf(stderr, "raycast serve: cannot listen on %s port %d\n", opt->host.c_str(),
                   opt->port);
      return 2;
    }
    serve::PreviewLoop loop(opt->scene, opt->threads);
    serve::add_routes(server, loop, accepted_hosts(opt->host, port), limits);
    const bool v6 = opt->host.find(':') != std::string::npos;
    std::printf("raycast serve: http://%s%s%s:%d/ (%s); Ctrl-C stops\n", v6 ? "[" : "",
                opt->host.c_str(), v6 ? "]" : "", port, opt->scene.c_str());
    std::fflush(stdout);
    loop.start();

    std::thread stopper([&server, &loop, signals] {
      int sig = 0;
      sigwait(&signals, &sig);
      loop.stop();
      server.stop();
    });
    server.listen_after_bind();
    // listen returned by itself (an error): let the stopper thread finish too.
    if (stopper.joinable()) {
      pthread_kill(stopper.native_handle(), SIGTERM);
      stopper.join();
    }
    loop.stop();
    return 0;
  };
}

}  // namespace raycast::cli
