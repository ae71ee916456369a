#pragma once
// The render threads. Each owns an EGL context and every GL object made on
// it (its own programs and GPU copies of the models); HTTP handlers hand
// jobs to whichever is free through one bounded queue and wait on a future.
// A full queue refuses at once (the caller answers 503 + Retry-After)
// instead of letting requests pile up behind a slow render.
// The queue has two lanes: jobs priced as long (render_cost.h) wait in
// their own, served by one extra render thread that the short lane's
// threads never lend themselves to, so a long render holds up only other
// long ones. In each lane the clients take turns (fair_queue.h).
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include <vector>

#include "gpu/egl_context.h"
#include "gpu/shader_source.h"
#include "render/plan/frame_plan.h"
#include "render/plan/render_params.h"
#include "render/plan/schedule.h"
#include "render/run/fair_queue.h"
#include "render/run/renderer.h"
#include "scene/animation/pose.h"
#include "scene/mesh/model.h"

namespace toond::render {

// One object of a job's frame.
struct JobObject {
  std::string model_key;  // GPU cache key: the model id, or "demo"
  std::shared_ptr<const scene::Model> model;
  glm::dmat4 transform{1.0};  // model → scene coordinates
  // The model's joints and morph weights in the request's pose
  // (scene/animation/pose.h); null: at rest.
  std::shared_ptr<const scene::SkinPose> pose;
};

// One frame to draw: its objects (at least one; a lone model has the
// identity) in their poses, the plan made of them before it was queued,
// which the render thread executes, and when and how it is drawn.
struct RenderJob {
  std::vector<JobObject> objects{};
  FramePlan plan{};
  Schedule schedule{};
};

// Set on a job's future when its deadline passed before it was started.
// Whoever set the deadline words the answer (the daemon names its flag).
class DeadlineExceeded : public std::runtime_error {
 public:
  DeadlineExceeded() : std::runtime_error("the render's deadline passed while it waited in the queue") {}
};

// Thrown by submit() when the queue is full.
class QueueFull : public std::runtime_error {
 public:
  QueueFull() : std::runtime_error("render queue is full") {}
};

class RenderService {
 public:
  // How long a long render's thread waits between chunks for short renders
  // to finish before it goes on regardless.
  static constexpr std::chrono::milliseconds kLongLaneYield{100};

  struct Options {
    std::optional<int> gpu_index;
    std::size_t queue_capacity = 32;
    // Render threads, each with its own context. On llvmpipe a second one
    // records a frame's vertices while the first's frame is rasterized.
    std::size_t render_threads = 1;
    // Jobs priced at this many Msamples or more wait in the long lane, which
    // one more render thread (and context) of its own serves, and serves
    // only them. 0: one lane for all.
    double long_render_cost = 0;
    std::size_t gpu_model_capacity = 8;                  // models kept on the GPU
    std::size_t gpu_model_bytes = std::size_t{1} << 30;  // and their GPU memory at most
    // Empty: the shaders embedded at build time. Otherwise GLSL is read from
    // this folder and recompiled before a render when a file changed; a
    // broken edit fails that one render with a ShaderCompileError and the
    // previous programs keep serving.
    std::string shader_dir;
    // Testing aid for the lost-context path (--simulate-gpu-reset): every
    // Nth render acts as if the GL context had been lost. 0: never.
    std::size_t simulate_reset_every = 0;
    // Where poses move vertices (--skinning); unset: in the vertex stage on
    // a GPU, on the CPU on a software rasterizer, whose vertex stage is
    // this CPU too and runs again for every pass (docs/animation.md).
    std::optional<scene::Skinning> skinning;
    // 2: each render thread records the next frame before it waits for the
    // last one's pixels, which come back through a pixel buffer and a
    // fence (render/run/pending_frame.h); 1: every frame is read back before
    // the next one starts (--frames-in-flight).
    int frames_in_flight = 1;
  };

  // Starts the threads and waits until their contexts exist. Throws
  // GpuError when one cannot be made.
  explicit RenderService(const Options& options);
  ~RenderService();
  RenderService(const RenderService&) = delete;
  RenderService& operator=(const RenderService&) = delete;

  const gpu::GlInfo& gl_info() const { return gl_info_; }
  // Where a request's pose should move the vertices (Options::skinning).
  scene::Skinning skinning() const;

  std::future<RenderOutput> submit(RenderJob job);
  // Whether a job of this cost waits in the long lane.
  bool is_long(double cost) const;
  // The frames of one request (a sprite sheet), queued one after another
  // with nothing between them, so a render thread draws them back to back
  // with the model and programs it just used. Admitted like one job: it
  // needs a free place in the queue, then all of them go in.
  std::vector<std::future<RenderOutput>> submit_all(std::vector<RenderJob> jobs);
  // Drops the model's GPU copies (after DELETE /models/{id}).
  void forget(const std::string& model_key);
  std::size_t queue_depth() const;
  // What the GPU model caches hold now, all threads together (for GET /metrics).
  std::size_t gpu_models_loaded() const;
  std::size_t gpu_model_bytes() const;
  // Lost GL contexts replaced by a new one since start.
  std::size_t gpu_resets() const { return gpu_resets_.load(); }
  // Frames started while the same thread's previous frame was still on
  // its way back (Options::frames_in_flight 2): the overlap the switch is for.
  std::size_t overlapped_frames() const { return overlapped_frames_.load(); }

 private:
  struct Task {
    RenderJob job;
    std::promise<RenderOutput> promise;
  };
  // What one render thread's GPU model cache holds.
  struct CacheUse {
    std::size_t models = 0;
    std::size_t bytes = 0;
  };
  void run(std::size_t worker, std::promise<void> started);
  // Under mutex_: whether `worker` has a job to take, and taking it.
  bool has_work_for(std::size_t worker) const;
  Task take_for(std::size_t worker);
  bool serves_long_lane(std::size_t worker) const;
  // Between a long render's chunks: waits while short renders are queued
  // or drawing, at most kLongLaneYield, so they need not wait behind its
  // chunks (a CPU rasteriser draws all contexts' work in arrival order), and
  // it still moves on under a steady stream of them.
  void yield_to_short_renders();
  // A short-lane worker's task ended (under no lock).
  void short_render_done();
  // Calls short_render_done() when it goes, for a short-lane task (null:
  // a long one).
  class ShortTurn {
   public:
    explicit ShortTurn(RenderService* service) : service_(service) {}
    ~ShortTurn();
    ShortTurn(const ShortTurn&) = delete;
    ShortTurn& operator=(const ShortTurn&) = delete;

   private:
    RenderService* service_;
  };
  std::size_t queued() const { return short_lane_.size() + long_lane_.size(); }
  // Each lane is held to the queue's capacity on its own: a long sheet's
  // many frames waiting in the long lane must not turn short renders away.
  FairQueue<Task>& lane_for(double cost) { return is_long(cost) ? long_lane_ : short_lane_; }
  // Serves tasks on the current context until the service stops (false) or
  // the context is lost (true). Sets `started` once the caches exist.
  bool serve(std::size_t worker, std::unique_ptr<gpu::ShaderSources> sources, std::promise<void>* started);
  struct Worker;
  struct Started;
  // Takes a task's turn and records its frame; nothing when it was past its
  // deadline (answered already).
  std::optional<Started> start_task(Task task, Worker& worker);
  // Finishes a started task's frame and answers it; true when the context
  // was lost (the task is answered with GpuReset).
  bool answer(Started& started, Worker& worker);
  void answer_lost(Started& started);
  void record_cache_use(const Worker& worker);
  bool context_lost(std::size_t renders) const;
  // Fails every queued render with `error` (the context could not be made).
  void fail_queued(const std::exception_ptr& error);
  void stop();  // lets every thread finish what was accepted, and joins them

  Options options_;
  gpu::GlInfo gl_info_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  FairQueue<Task> short_lane_;
  FairQueue<Task> long_lane_;
  std::size_t short_drawing_ = 0;  // short-lane tasks taken and not yet done
  std::condition_variable short_idle_;
  // Per render thread, under mutex_: models to drop before its next task,
  // and what its cache held after its last one.
  std::vector<std::vector<std::string>> forgets_;
  std::vector<CacheUse> cache_use_;
  bool stopping_ = false;
  std::atomic<std::size_t> gpu_resets_{0};
  std::atomic<std::size_t> overlapped_frames_{0};
  std::size_t worker_count_ = 1;  // render threads, the long lane's included (its is the last)
  std::vector<std::thread> threads_;
};

}  // namespace toond::render
