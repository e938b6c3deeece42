#pragma once
// The server's routes (docs/serve.md): the page, the state as JSON and as server-sent events, the
// current image, and the page's requests (camera, integrator, pick, save). Nothing else is
// served: no file of the machine is reachable, every other path is a 404.
#include <string>
#include <vector>

namespace httplib {
class Server;
}

namespace raycast::serve {

class PreviewLoop;

/// Bounds on what one client can ask for.
struct RouteLimits {
  int max_event_streams = 16;         // open /events streams at once (each holds a thread)
  std::size_t max_body_bytes = 4096;  // request bodies (all small JSON objects)
};

/// Registers every route on `server`. `hosts` are the Host header values accepted ("127.0.0.1:PORT"
/// and the like; empty: any): a request naming another host is refused (DNS rebinding). POST
/// requests must be application/json from the page's own origin (a foreign page cannot drive the
/// server).
void add_routes(httplib::Server& server, PreviewLoop& loop, const std::vector<std::string>& hosts,
                const RouteLimits& limits);

}  // namespace raycast::serve
