#include "serve/http_routes.h"

#include <httplib.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <memory>
#include <sstream>

#include "io/scene_error.h"
#include "load/yaml_reader.h"
#include "render/explain.h"
#include "render/explain_format.h"
#include "serve/camera_request.h"
#include "serve/camera_writeback.h"
#include "serve/json_text.h"
#include "serve/page_asset.h"
#include "serve/pick.h"
#include "serve/preview_loop.h"

namespace raycast::serve {

namespace {

std::string state_json(const PreviewState& s, const std::string& scene) {
  std::ostringstream out;
  out << "{\"version\":" << s.version << ",\"frame\":" << s.frame << ",\"pass\":" << s.pass
      << ",\"passes\":" << s.passes << ",\"final\":" << (s.final ? "true" : "false")
      << ",\"width\":" << s.width << ",\"height\":" << s.height
      << ",\"image_width\":" << s.image_width << ",\"image_height\":" << s.image_height
      << ",\"spp\":" << s.spp << ",\"error\":" << json_string(s.error)
      << ",\"integrator\":" << json_string(s.integrator) << ",\"camera\":" << camera_json(s.camera)
      << ",\"camera_overridden\":" << (s.camera_overridden ? "true" : "false")
      << ",\"first_ms\":" << json_number(s.first_ms) << ",\"final_ms\":" << json_number(s.final_ms)
      << ",\"reloads\":" << s.reloads << ",\"scene\":" << json_string(scene) << "}";
  return out.str();
}

void send_json(httplib::Response& res, int status, const std::string& json) {
  res.status = status;
  res.set_header("Cache-Control", "no-store");
  res.set_content(json, "application/json");
}

void send_error(httplib::Response& res, int status, const std::string& message) {
  send_json(res, status, "{\"error\":" + json_string(message) + "}");
}

/// Runs a POST handler body, turning bad input into 400 with its message.
template <class F>
void guarded(httplib::Response& res, F&& body) {
  try {
    body();
  } catch (const SceneError& e) {
    send_error(res, 400, e.what());
  } catch (const std::exception& e) {
    send_error(res, 500, e.what());
  }
}

// A request about one pixel of the view shown: its {"x", "y"} and the scene and camera it
// refers to.
struct PixelRequest {
  double x = 0, y = 0;
  CameraDesc camera;
  std::shared_ptr<const Scene> scene;
};

// Reads a pixel request (`what` names it in errors); false, with the error answered, when the
// body is bad, the scene has not loaded or the pixel lies outside the image.
bool read_pixel_request(PreviewLoop& loop, std::size_t max_body, const httplib::Request& req,
                        httplib::Response& res, const char* what, PixelRequest& p) {
  const YamlDocument request = parse_request_object(req.body, max_body);
  const SourceContext ctx{"request", "."};
  Fields f(ctx, request.root(), what);
  p.x = f.number("x"), p.y = f.number("y");
  f.finish();
  p.scene = loop.scene(&p.camera);
  if (!p.scene) {
    send_error(res, 409, "the scene has not loaded yet");
    return false;
  }
  const int w = p.scene->image.width, h = p.scene->image.height;
  if (!(p.x >= 0 && p.x < w && p.y >= 0 && p.y < h)) {
    send_error(
        res, 400,
        "x and y must lie inside the " + std::to_string(w) + "x" + std::to_string(h) + " image");
    return false;
  }
  return true;
}

/// POST /explain: one pixel's ray tree at the view shown (docs/explain.md), one sample at the
/// pixel's centre.
void answer_explain(PreviewLoop& loop, std::size_t max_body, const httplib::Request& req,
                    httplib::Response& res) {
  PixelRequest p;
  if (!read_pixel_request(loop, max_body, req, res, "explain", p)) return;
  ExplainOptions o;
  o.x = int(p.x);
  o.y = int(p.y);
  o.spp = 1;
  o.camera = p.camera;
  send_json(res, 200, explain_json(*p.scene, explain_pixel(*p.scene, o)));
}

// Before any route: the Host must be ours (DNS rebinding), and a POST must be JSON from our own
// origin (a plain cross-site form or fetch cannot send application/json without a preflight,
// which this server never approves); errors and exceptions answer JSON.
void add_guards(httplib::Server& server, const std::vector<std::string>& hosts) {
  server.set_pre_routing_handler([hosts](const httplib::Request& req, httplib::Response& res) {
    const std::string host = req.get_header_value("Host");
    if (!hosts.empty() && std::find(hosts.begin(), hosts.end(), host) == hosts.end()) {
      send_error(res, 403, "unexpected Host header");
      return httplib::Server::HandlerResponse::Handled;
    }
    // httplib 0.11 answers any number of byte ranges, one copy of the body each: a hostile
    // Range header could multiply a response by a thousand. Images are small; no ranges.
    if (req.has_header("Range")) {
      send_error(res, 416, "byte ranges are not served");
      return httplib::Server::HandlerResponse::Handled;
    }
    if (req.method == "POST") {
      const std::string type = req.get_header_value("Content-Type");
      if (type.rfind("application/json", 0) != 0) {
        send_error(res, 415, "POST bodies must be application/json");
        return httplib::Server::HandlerResponse::Handled;
      }
      if (req.has_header("Origin") && req.get_header_value("Origin") != "http://" + host) {
        send_error(res, 403, "cross-origin requests are refused");
        return httplib::Server::HandlerResponse::Handled;
      }
    }
    return httplib::Server::HandlerResponse::Unhandled;
  });

  server.set_error_handler([](const httplib::Request&, httplib::Response& res) {
    if (!res.body.empty()) return;  // a route's own message
    const char* what = res.status == 404   ? "not found"
                       : res.status == 413 ? "request too large"
                       : res.status == 405 ? "method not allowed"
                                           : "bad request";
    send_error(res, res.status, what);
  });
  server.set_exception_handler([](const httplib::Request&, httplib::Response& res,
                                  std::exception_ptr) { send_error(res, 500, "internal error"); });
}

// The page, the state and the latest image.
void add_page_routes(httplib::Server& server, PreviewLoop& loop) {
  server.Get("/", [](const httplib::Request&, httplib::Response& res) {
    const std::string_view page = page_html();
    res.set_header("Cache-Control", "no-store");
    res.set_header("Content-Security-Policy",
                   "default-src 'self'; img-src 'self' data: blob:; style-src 'unsafe-inline'; "
                   "script-src 'unsafe-inline'");
    res.set_content(page.data(), page.size(), "text/html; charset=utf-8");
  });

  server.Get("/state", [&loop](const httplib::Request&, httplib::Response& res) {
    send_json(res, 200, state_json(loop.state(), loop.scene_path()));
  });

  server.Get("/image.png", [&loop](const httplib::Request& req, httplib::Response& res) {
    const PreviewState s = loop.state();
    if (!s.png) return send_error(res, 503, "no image yet");
    res.set_header("Cache-Control", "no-store");
    res.set_header("X-Raycast-Frame", std::to_string(s.frame));
    if (req.has_param("download")) {
      const std::string stem = std::filesystem::path(loop.scene_path()).stem().string();
      std::string name;
      for (const char c : stem)  // a header-safe file name
        name += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_') ? c : '_';
      res.set_header("Content-Disposition", "attachment; filename=\"" + name + ".png\"");
    }
    res.set_content(*s.png, "image/png");
  });
}

// Server-sent events: one "state" event per change. Every stream reads the one shared state, so
// many pages cost no more rendering; the number of streams is bounded (each holds a thread).
void add_event_route(httplib::Server& server, PreviewLoop& loop, int max_streams) {
  auto streams = std::make_shared<std::atomic<int>>(0);
  server.Get("/events",
             [&loop, streams, max_streams](const httplib::Request&, httplib::Response& res) {
               if (streams->fetch_add(1) >= max_streams) {
                 streams->fetch_sub(1);
                 return send_error(res, 503, "too many open pages");
               }
               auto seen = std::make_shared<std::uint64_t>(0);
               res.set_header("Cache-Control", "no-store");
               res.set_chunked_content_provider(
                   "text/event-stream",
                   [&loop, seen](std::size_t, httplib::DataSink& sink) {
                     if (loop.stopping()) return false;
                     PreviewState s;
                     std::string message;
                     if (loop.wait_newer(*seen, std::chrono::seconds(5), s)) {
                       *seen = s.version;
                       message = "event: state\ndata: " + state_json(s, loop.scene_path()) + "\n\n";
                     } else {
                       message = ": keep-alive\n\n";  // also finds closed connections
                     }
                     if (loop.stopping()) return false;
                     return sink.write(message.data(), message.size());
                   },
                   [streams](bool) { streams->fetch_sub(1); });
             });
}

// The requests that change the view or ask about a pixel: camera, integrator, pick, explain.
void add_request_routes(httplib::Server& server, PreviewLoop& loop, std::size_t max_body) {
  server.Post("/camera", [&loop, max_body](const httplib::Request& req, httplib::Response& res) {
    guarded(res, [&] {
      CameraDesc current;
      loop.scene(&current);
      loop.set_camera(parse_camera_request(req.body.substr(0, max_body + 1), current));
      send_json(res, 200, state_json(loop.state(), loop.scene_path()));
    });
  });

  server.Post("/camera/reset", [&loop](const httplib::Request&, httplib::Response& res) {
    loop.reset_camera();
    send_json(res, 200, state_json(loop.state(), loop.scene_path()));
  });

  server.Post("/camera/save", [&loop](const httplib::Request&, httplib::Response& res) {
    guarded(res, [&] {
      CameraDesc camera;
      if (!loop.scene(&camera)) return send_error(res, 409, "the scene has not loaded yet");
      const WriteResult written = write_camera(loop.scene_path(), camera);
      std::ostringstream out;
      out << "{\"written\":" << json_string(written.path)
          << ",\"sidecar\":" << (written.sidecar ? "true" : "false")
          << ",\"reason\":" << json_string(written.reason) << "}";
      send_json(res, 200, out.str());
    });
  });

  server.Post("/integrator",
              [&loop, max_body](const httplib::Request& req, httplib::Response& res) {
                guarded(res, [&] {
                  const YamlDocument request = parse_request_object(req.body, max_body);
                  const SourceContext ctx{"request", "."};
                  Fields f(ctx, request.root(), "request");
                  const std::string name = f.string("integrator");
                  f.finish();
                  if (const std::optional<RenderMode> mode = integrator_named(name)) {
                    loop.set_integrator(*mode);
                    return send_json(res, 200, state_json(loop.state(), loop.scene_path()));
                  }
                  send_error(res, 400, std::string("integrator must be ") + kIntegratorNames);
                });
              });

  server.Post("/pick", [&loop, max_body](const httplib::Request& req, httplib::Response& res) {
    guarded(res, [&] {
      PixelRequest p;
      if (!read_pixel_request(loop, max_body, req, res, "pick", p)) return;
      send_json(
          res, 200,
          pick_json(*p.scene, p.camera, p.scene->image.width, p.scene->image.height, p.x, p.y));
    });
  });

  server.Post("/explain", [&loop, max_body](const httplib::Request& req, httplib::Response& res) {
    guarded(res, [&] { answer_explain(loop, max_body, req, res); });
  });
}

}  // namespace

void add_routes(httplib::Server& server, PreviewLoop& loop, const std::vector<std::string>& hosts,
                const RouteLimits& limits) {
  server.set_payload_max_length(limits.max_body_bytes);
  add_guards(server, hosts);
  add_page_routes(server, loop);
  add_event_route(server, loop, limits.max_event_streams);
  add_request_routes(server, loop, limits.max_body_bytes);
}

}  // namespace raycast::serve
