#include "serve/preview_loop.h"

#include <exception>
#include <new>
#include <vector>

#include "io/scene_error.h"
#include "load/loader.h"
#include "render/renderer.h"
#include "render_output.h"
#include "serve/png_memory.h"

namespace raycast::serve {

namespace {

/// One pass of the refinement: its image size and samples (spp 0: the scene's own settings).
struct Pass {
  int width, height, spp;
};

/// A quarter-resolution 1-sample image, then full resolution at 1, 4, 16, ... samples below the
/// scene's, then the scene's own settings (its samples or its adaptive antialiasing).
std::vector<Pass> plan_passes(const Scene& scene) {
  const int w = scene.image.width, h = scene.image.height, samples = scene.image.samples;
  const bool adaptive = scene.render.antialias.method != AntialiasMethod::kNone;
  std::vector<Pass> passes;
  if (w >= 8 && h >= 8) passes.push_back({w / 4, h / 4, 1});
  if (adaptive || samples > 1) {
    passes.push_back({w, h, 1});
    for (int s = 4; !adaptive && s < samples; s *= 4) passes.push_back({w, h, s});
  }
  passes.push_back({0, 0, 0});
  return passes;
}

double ms_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace

PreviewLoop::PreviewLoop(std::string scene_path, int threads)
    : path_(std::move(scene_path)), threads_(threads) {}

PreviewLoop::~PreviewLoop() { stop(); }

void PreviewLoop::start() {
  {
    std::lock_guard lock(mutex_);
    restarted_ = std::chrono::steady_clock::now();
    watch_list_ = {path_};
    watch_list_changed_ = true;
  }
  watcher_.watch({path_});  // stamped before the first load
  loop_thread_ = std::thread([this] { run(); });
  watch_thread_ = std::thread([this] { watch(); });
}

void PreviewLoop::stop() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
    cancel_ = true;
  }
  work_.notify_all();
  changed_.notify_all();
  if (loop_thread_.joinable()) loop_thread_.join();
  if (watch_thread_.joinable()) watch_thread_.join();
}

PreviewState PreviewLoop::state() const {
  std::lock_guard lock(mutex_);
  return state_;
}

bool PreviewLoop::stopping() const {
  std::lock_guard lock(mutex_);
  return stopping_;
}

bool PreviewLoop::wait_newer(std::uint64_t seen, std::chrono::milliseconds timeout,
                             PreviewState& out) const {
  std::unique_lock lock(mutex_);
  const bool newer = changed_.wait_for(lock, timeout, [&] {
    return stopping_ || state_.version > seen;
  }) && state_.version > seen;
  out = state_;
  return newer;
}

void PreviewLoop::set_camera(const CameraDesc& camera) {
  std::lock_guard lock(mutex_);
  camera_override_ = camera;
  restart_locked();
}

void PreviewLoop::reset_camera() {
  std::lock_guard lock(mutex_);
  camera_override_.reset();
  restart_locked();
}

void PreviewLoop::set_integrator(RenderMode integrator) {
  std::lock_guard lock(mutex_);
  integrator_override_ = integrator;
  restart_locked();
}

std::shared_ptr<const Scene> PreviewLoop::scene(CameraDesc* camera) const {
  std::lock_guard lock(mutex_);
  if (camera) *camera = camera_locked();
  return scene_;
}

CameraDesc PreviewLoop::camera_locked() const {
  return camera_override_ ? *camera_override_ : scene_camera_;
}

void PreviewLoop::restart_locked() {
  restart_wanted_ = true;
  cancel_ = true;
  restarted_ = std::chrono::steady_clock::now();
  state_.final = false;
  state_.camera = camera_locked();
  state_.camera_overridden = camera_override_.has_value();
  state_.integrator = render_mode_name(
      integrator_override_.value_or(scene_ ? scene_->render.integrator : RenderMode::kWhitted));
  publish_locked();
  work_.notify_all();
}

void PreviewLoop::publish_locked() {
  ++state_.version;
  changed_.notify_all();
}

void PreviewLoop::watch() {
  for (;;) {
    {
      std::unique_lock lock(mutex_);
      work_.wait_for(lock, std::chrono::milliseconds(100), [&] { return stopping_; });
      if (stopping_) return;
      if (watch_list_changed_) {
        watcher_.watch(watch_list_);
        watch_list_changed_ = false;
      }
    }
    if (watcher_.changed()) {
      std::lock_guard lock(mutex_);
      reload_wanted_ = true;
      cancel_ = true;
      restarted_ = std::chrono::steady_clock::now();
      work_.notify_all();
    }
  }
}

void PreviewLoop::reload() {
  std::shared_ptr<Scene> scene;
  std::string error;
  std::string error_file;
  try {
    scene = std::make_shared<Scene>(load_scene_file(path_));
  } catch (const SceneError& e) {
    error = e.what();
    error_file = e.file();
  } catch (const std::bad_alloc&) {
    error = path_ + ": out of memory while loading the scene";
  } catch (const std::exception& e) {
    error = path_ + ": " + e.what();
  }
  std::lock_guard lock(mutex_);
  if (scene) {
    scene_ = std::move(scene);
    scene_camera_ = camera_or_default(*scene_);
    state_.error.clear();
    ++state_.reloads;
    watch_list_ = {path_};
    watch_list_.insert(watch_list_.end(), scene_->marks.files.begin(), scene_->marks.files.end());
    state_.width = scene_->image.width;
    state_.height = scene_->image.height;
    restart_locked();
  } else {
    // Keep the last good scene and image; watch what it named and the file at fault too.
    state_.error = error;
    if (!error_file.empty()) watch_list_.push_back(error_file);
    publish_locked();
  }
  watch_list_changed_ = true;
}

void PreviewLoop::run() {
  std::vector<Pass> passes;
  for (;;) {
    std::shared_ptr<Scene> scene;
    RenderOptions options;
    Pass pass{};
    int index = 0;
    {
      std::unique_lock lock(mutex_);
      work_.wait(lock, [&] {
        return stopping_ || reload_wanted_ || restart_wanted_ ||
               (scene_ && next_pass_ < int(passes.size()));
      });
      if (stopping_) return;
      if (reload_wanted_) {
        reload_wanted_ = false;
        lock.unlock();
        reload();
        continue;
      }
      if (!scene_) {  // a view change before any scene loaded: nothing to restart yet
        restart_wanted_ = false;
        continue;
      }
      if (restart_wanted_) {
        restart_wanted_ = false;
        next_pass_ = 0;
        passes = plan_passes(*scene_);
        state_.first_ms = state_.final_ms = 0;
      }
      cancel_ = false;
      scene = scene_;
      // Only this thread touches the camera field; the pages read state_.camera.
      scene->camera = camera_locked();
      index = next_pass_;
      pass = passes[std::size_t(index)];
      options.width = pass.width;
      options.height = pass.height;
      options.spp = pass.spp;
      options.threads = threads_;
      options.integrator = integrator_override_;
      options.progress = false;
      options.cancel = &cancel_;
    }
    std::shared_ptr<const std::string> png;
    std::string error;
    int image_width = 0, image_height = 0;
    try {
      Image image = render(*scene, options);
      if (cancel_) continue;
      if (render_mode(*scene, options) == RenderMode::kDepth)
        cli::normalize_depth(image);  // as `raycast render` writes depth to PNG
      image_width = image.width;
      image_height = image.height;
      png = std::make_shared<const std::string>(encode_png(image));
    } catch (const SceneError& e) {  // an image texture that cannot be read
      error = e.what();
    } catch (const std::bad_alloc&) {
      error = path_ + ": out of memory while rendering";
    } catch (const std::exception& e) {
      error = path_ + ": " + e.what();
    }
    std::lock_guard lock(mutex_);
    if (restart_wanted_ || reload_wanted_ || scene != scene_) continue;  // stale
    if (!error.empty()) {
      state_.error = error;
      next_pass_ = int(passes.size());
      publish_locked();
      continue;
    }
    const bool final = index + 1 == int(passes.size());
    ++state_.frame;
    state_.png = std::move(png);
    state_.pass = index + 1;
    state_.passes = int(passes.size());
    state_.image_width = image_width;
    state_.image_height = image_height;
    state_.spp = pass.spp > 0                                               ? pass.spp
                 : scene->render.antialias.method != AntialiasMethod::kNone ? 0
                                                                            : scene->image.samples;
    state_.final = final;
    if (index == 0) state_.first_ms = ms_since(restarted_);
    if (final) state_.final_ms = ms_since(restarted_);
    next_pass_ = index + 1;
    publish_locked();
  }
}

}  // namespace raycast::serve
