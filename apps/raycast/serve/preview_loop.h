#pragma once
// The progressive render loop of `raycast serve`: one thread that renders the scene pass by pass
// (a quarter-resolution 1-sample image first, then full resolution at 1, 4, 16, ... samples, and
// last the scene's own settings, exactly what `raycast render` computes) and publishes each pass
// as a PNG. Every page reads the same published state, so open pages never add rendering work.
// A change of the scene's files, the camera or the integrator cancels the pass under way and
// starts again from the fast first image.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "scene/scene.h"
#include "serve/file_watcher.h"

namespace raycast::serve {

/// What the pages see: the last published image and where the loop is.
struct PreviewState {
  std::uint64_t version = 0;               // bumped on every change below
  std::uint64_t frame = 0;                 // bumped on every published image
  std::shared_ptr<const std::string> png;  // the last image (kept when a reload fails)
  int width = 0, height = 0;               // of the full image (the first pass is smaller)
  int pass = 0, passes = 0;                // the pass the image came from (1-based) and of how many
  int image_width = 0, image_height = 0;   // of this pass's image
  int spp = 0;                             // this pass's samples per pixel (0: adaptive)
  bool final = false;                      // the image is the scene's full-quality render
  std::string error;                       // the last reload's error ("file:line:column: ...")
  std::string integrator;                  // whitted, raycast, depth, normal or id
  bool camera_overridden = false;          // the page moved the camera (not yet saved)
  CameraDesc camera;                       // the camera in use
  double first_ms = 0, final_ms = 0;       // since the last restart: first image, final image
  std::uint64_t reloads = 0;               // successful reloads of the scene file
};

class PreviewLoop {
 public:
  /// Loads nothing yet; start() begins. `threads` > 0 caps the render's threads.
  PreviewLoop(std::string scene_path, int threads);
  ~PreviewLoop();
  PreviewLoop(const PreviewLoop&) = delete;
  PreviewLoop& operator=(const PreviewLoop&) = delete;

  void start();
  void stop();

  PreviewState state() const;
  bool stopping() const;
  /// Waits until the state's version exceeds `seen` (true) or the timeout passes or the loop
  /// stops (false); `out` is the current state either way.
  bool wait_newer(std::uint64_t seen, std::chrono::milliseconds timeout, PreviewState& out) const;

  // The view the pages ask for; each restarts the refinement.
  void set_camera(const CameraDesc& camera);
  void reset_camera();
  void set_integrator(RenderMode integrator);

  /// The scene as last loaded (null before the first successful load) and the camera in use.
  std::shared_ptr<const Scene> scene(CameraDesc* camera) const;
  const std::string& scene_path() const { return path_; }

 private:
  void run();
  void watch();  // the watcher thread: polls the files every 100 ms
  void reload();
  void restart_locked();  // under mutex_: cancel the pass under way, begin again at pass 1
  void publish_locked();  // under mutex_: bump the version, wake the pages
  CameraDesc camera_locked() const;

  const std::string path_;
  const int threads_;
  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;  // pages wait on it
  std::condition_variable work_;             // the loop and the watcher wait on it
  PreviewState state_;
  std::shared_ptr<Scene> scene_;  // its camera field is set by the loop before each pass
  CameraDesc scene_camera_;       // the scene file's camera (or the default framing)
  std::optional<CameraDesc> camera_override_;
  std::optional<RenderMode> integrator_override_;
  bool reload_wanted_ = true;
  bool restart_wanted_ = false;
  bool stopping_ = false;
  int next_pass_ = 0;  // 0-based index of the next pass to render
  std::chrono::steady_clock::time_point restarted_;
  std::atomic<bool> cancel_{false};
  FileWatcher watcher_;  // used by the watcher thread only, but re-aimed by reload()
  std::vector<std::string> watch_list_;  // under mutex_: what the watcher should watch
  bool watch_list_changed_ = false;
  std::thread loop_thread_, watch_thread_;
};

}  // namespace raycast::serve
