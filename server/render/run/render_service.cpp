#include "render/run/render_service.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <iostream>

#include "gpu/gpu_error.h"
#include "gpu/program_cache.h"
#include "gpu/shader_source.h"
#include "render/frame/gpu_model_cache.h"
#include "toond_shader_files.h"

namespace toond::render {
namespace {

std::string embedded_shader(const std::string& name) {
  const std::string_view text = toond::shader_files::find(name);
  if (text.empty()) throw gpu::GpuError("no embedded shader named " + name);
  return std::string(text);
}

std::unique_ptr<gpu::ShaderSources> shader_sources(const std::string& shader_dir) {
  if (shader_dir.empty()) return std::make_unique<gpu::FixedShaderSources>(embedded_shader);
  return std::make_unique<gpu::ShaderDirectory>(shader_dir);
}

}  // namespace

RenderService::RenderService(const Options& options) : options_(options) {
  worker_count_ = std::max<std::size_t>(1, options_.render_threads) + (options_.long_render_cost > 0 ? 1 : 0);
  const std::size_t workers = worker_count_;
  forgets_.resize(workers);
  cache_use_.resize(workers);
  // One at a time: the first context's description is the service's, and a
  // failure stops the ones already running.
  for (std::size_t worker = 0; worker < workers; ++worker) {
    std::promise<void> started;
    std::future<void> ready = started.get_future();
    threads_.emplace_back(&RenderService::run, this, worker, std::move(started));
    try {
      ready.get();
    } catch (...) {
      stop();
      throw;
    }
  }
}

RenderService::~RenderService() { stop(); }

void RenderService::stop() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  for (std::thread& thread : threads_) {
    if (thread.joinable()) thread.join();
  }
}

scene::Skinning RenderService::skinning() const {
  if (options_.skinning) return *options_.skinning;
  return gpu::software_rasterizer(gl_info_.renderer) ? scene::Skinning::Cpu : scene::Skinning::VertexStage;
}

bool RenderService::is_long(double cost) const {
  return options_.long_render_cost > 0 && cost >= options_.long_render_cost;
}

std::future<RenderOutput> RenderService::submit(RenderJob job) {
  Task task;
  task.job = std::move(job);
  auto future = task.promise.get_future();
  {
    std::lock_guard lock(mutex_);
    FairQueue<Task>& lane = lane_for(task.job.schedule.cost);
    if (lane.size() >= options_.queue_capacity) throw QueueFull();
    const std::string client = task.job.schedule.client;
    lane.push(client, std::move(task));
  }
  // Every thread looks: the one woken might serve the other lane only.
  wake_.notify_all();
  return future;
}

std::vector<std::future<RenderOutput>> RenderService::submit_all(std::vector<RenderJob> jobs) {
  std::vector<Task> tasks(jobs.size());
  std::vector<std::future<RenderOutput>> futures;
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    tasks[i].job = std::move(jobs[i]);
    futures.push_back(tasks[i].promise.get_future());
  }
  {
    std::lock_guard lock(mutex_);
    // A sheet's frames share its price, so they share a lane; admitted as one
    // request, they may take the lane past its capacity.
    FairQueue<Task>& lane = lane_for(tasks.empty() ? 0.0 : tasks.front().job.schedule.cost);
    if (lane.size() >= options_.queue_capacity) throw QueueFull();
    for (Task& task : tasks) {
      const std::string client = task.job.schedule.client;
      lane.push(client, std::move(task));
    }
  }
  wake_.notify_all();
  return futures;
}

void RenderService::forget(const std::string& model_key) {
  {
    std::lock_guard lock(mutex_);
    for (std::vector<std::string>& keys : forgets_) keys.push_back(model_key);
  }
  wake_.notify_all();
}

std::size_t RenderService::queue_depth() const {
  std::lock_guard lock(mutex_);
  return queued();
}

bool RenderService::serves_long_lane(std::size_t worker) const {
  return options_.long_render_cost > 0 && worker + 1 == worker_count_;
}

// The long lane's thread takes long jobs only: a short job there would
// load its model into a second context (twice the GPU memory) and draw at
// the long lane's low CPU priority.
bool RenderService::has_work_for(std::size_t worker) const {
  return serves_long_lane(worker) ? !long_lane_.empty() : !short_lane_.empty();
}

RenderService::Task RenderService::take_for(std::size_t worker) {
  if (serves_long_lane(worker)) return long_lane_.pop();
  ++short_drawing_;
  return short_lane_.pop();
}

RenderService::ShortTurn::~ShortTurn() {
  if (service_) service_->short_render_done();
}

void RenderService::short_render_done() {
  {
    std::lock_guard lock(mutex_);
    --short_drawing_;
  }
  short_idle_.notify_all();
}

void RenderService::yield_to_short_renders() {
  std::unique_lock lock(mutex_);
  short_idle_.wait_for(lock, kLongLaneYield, [&] { return stopping_ || (short_lane_.empty() && short_drawing_ == 0); });
}

std::size_t RenderService::gpu_models_loaded() const {
  std::lock_guard lock(mutex_);
  std::size_t n = 0;
  for (const CacheUse& use : cache_use_) n += use.models;
  return n;
}

std::size_t RenderService::gpu_model_bytes() const {
  std::lock_guard lock(mutex_);
  std::size_t n = 0;
  for (const CacheUse& use : cache_use_) n += use.bytes;
  return n;
}

namespace {

// The long lane's thread runs at the lowest CPU priority, so its own work
// (recording draws, vertex work on a CPU rasteriser) gives way to the short
// lane's. It does not reach llvmpipe's raster threads, which every context
// shares (yield_to_short_renders covers those). Lowering one's own
// priority needs no privilege.
void lower_cpu_priority() {
  if (setpriority(PRIO_PROCESS, static_cast<id_t>(gettid()), 19) != 0) {
    std::cerr << "toond: could not lower the long render lane's CPU priority; it shares the CPU evenly\n";
  }
}

}  // namespace

void RenderService::run(std::size_t worker, std::promise<void> started) {
  if (serves_long_lane(worker)) lower_cpu_priority();
  std::optional<gpu::EglContext> context;
  std::unique_ptr<gpu::ShaderSources> sources;
  try {
    sources = shader_sources(options_.shader_dir);
    context.emplace(gpu::EglContext::Options{options_.gpu_index});
    if (worker == 0) gl_info_ = context->info();
  } catch (...) {
    started.set_exception(std::current_exception());
    return;
  }
  std::promise<void>* not_yet_started = &started;
  while (serve(worker, std::move(sources), not_yet_started)) {
    not_yet_started = nullptr;
    ++gpu_resets_;
    {
      std::lock_guard lock(mutex_);
      cache_use_[worker] = {};
    }
    std::cerr << "toond: the GL context was lost; making a new one (models are uploaded again as they are used)\n";
    // The lost context's objects went with it: the caches were dropped by
    // serve(); now the context itself.
    context.reset();
    for (;;) {
      try {
        sources = shader_sources(options_.shader_dir);
        context.emplace(gpu::EglContext::Options{options_.gpu_index});
        break;
      } catch (const std::exception& e) {
        std::cerr << "toond: cannot make a new GL context: " << e.what() << "; retrying in 1 s\n";
        fail_queued(std::make_exception_ptr(
            gpu::GpuReset(std::string("the GL context was lost and a new one could not be made yet: ") + e.what())));
        std::unique_lock lock(mutex_);
        if (wake_.wait_for(lock, std::chrono::seconds(1), [&] { return stopping_; })) return;
      }
    }
  }
}

bool RenderService::context_lost(std::size_t renders) const {
  if (options_.simulate_reset_every > 0 && renders % options_.simulate_reset_every == 0) return true;
  return glGetGraphicsResetStatus() != GL_NO_ERROR;
}

void RenderService::fail_queued(const std::exception_ptr& error) {
  std::vector<Task> failed;
  {
    std::lock_guard lock(mutex_);
    failed = short_lane_.take_all();
    for (Task& task : long_lane_.take_all()) failed.push_back(std::move(task));
  }
  for (Task& task : failed) task.promise.set_exception(error);
}

// What one render thread draws with on its current context.
struct RenderService::Worker {
  Worker(std::size_t thread_index, std::unique_ptr<gpu::ShaderSources> sources, const Options& options)
      : index(thread_index),
        programs(std::move(sources)),
        models(options.gpu_model_capacity, options.gpu_model_bytes),
        renderer(programs) {
    renderer.set_frames_in_flight(options.frames_in_flight > 1);
  }
  std::size_t index;
  gpu::ProgramCache programs;
  GpuModelCache models;
  Renderer renderer;
  std::size_t renders = 0;
};

// A task taken from the queue whose frame is recorded, or whose start
// failed: it is answered once finished.
struct RenderService::Started {
  Task task;
  std::unique_ptr<ShortTurn> turn;  // a short task counts as drawing until answered
  std::size_t number = 0;           // the thread's renders when it started
  std::unique_ptr<PendingFrame> frame;
  std::exception_ptr failure;
  std::optional<PassTiming> posing;  // pose_vertices, where the CPU posed
};

void RenderService::record_cache_use(const Worker& worker) {
  std::lock_guard lock(mutex_);
  cache_use_[worker.index] = {worker.models.size(), worker.models.bytes()};
}

bool RenderService::serve(std::size_t index, std::unique_ptr<gpu::ShaderSources> sources, std::promise<void>* started) {
  Worker worker(index, std::move(sources), options_);
  if (started) started->set_value();
  // With frames in flight, the task whose pixels are on their way back.
  std::optional<Started> in_flight;
  for (;;) {
    std::optional<Task> task;
    std::vector<std::string> forgotten;
    {
      std::unique_lock lock(mutex_);
      // A frame in flight is not kept waiting for work: the next task is
      // started before it is finished, or it is finished now.
      if (!in_flight) {
        wake_.wait(lock, [&] { return stopping_ || has_work_for(index) || !forgets_[index].empty(); });
      }
      // A model deleted before this task was taken is gone for it too.
      forgotten.swap(forgets_[index]);
      if (forgotten.empty() && has_work_for(index)) task = take_for(index);
      // Work already accepted is finished before the thread stops.
      if (forgotten.empty() && !task && !in_flight) return false;
    }
    if (!forgotten.empty()) {
      for (const std::string& key : forgotten) worker.models.forget(key);
      record_cache_use(worker);
      continue;
    }
    std::optional<Started> next;
    if (task) next = start_task(std::move(*task), worker);
    if (in_flight && next && next->frame) ++overlapped_frames_;
    if (in_flight) {
      if (answer(*in_flight, worker)) {
        if (next) answer_lost(*next);
        return true;
      }
      in_flight.reset();
    }
    if (!next) continue;
    if (next->frame && next->frame->readback) {
      in_flight = std::move(next);
    } else if (answer(*next, worker)) {
      return true;
    }
  }
}

std::optional<RenderService::Started> RenderService::start_task(Task task, Worker& worker) {
  Started started;
  started.turn = std::make_unique<ShortTurn>(serves_long_lane(worker.index) ? nullptr : this);
  const Schedule& schedule = task.job.schedule;
  if (schedule.deadline && std::chrono::steady_clock::now() > *schedule.deadline) {
    task.promise.set_exception(std::make_exception_ptr(DeadlineExceeded()));
    return std::nullopt;
  }
  started.number = ++worker.renders;
  try {
    // With --shader-dir: pick up edited shader files (a stat per file
    // when nothing changed; nothing at all for the embedded shaders).
    const gpu::ProgramCache::Reload reload = worker.programs.refresh();
    if (!reload.files.empty()) {
      std::cerr << "toond: reloaded";
      for (const auto& f : reload.files) std::cerr << " " << f;
      std::cerr << " (" << reload.programs << " program" << (reload.programs == 1 ? "" : "s") << " rebuilt)\n";
    }
    // Load them all first: references stay valid while the cache holds
    // them, and a scene larger than the cache must not evict its own
    // objects mid-way (see GpuModelCache::get's `pinned`).
    std::vector<RenderObject> objects;
    std::vector<std::string> pinned;
    for (const JobObject& o : task.job.objects) pinned.push_back(o.model_key);
    // Posing vertices on the CPU happens here, on this thread (the
    // Server-Timing entry pose_vertices).
    const auto posing = std::chrono::steady_clock::now();
    bool posed_on_cpu = false;
    for (const JobObject& o : task.job.objects) {
      GpuModel& model = worker.models.get(o.model_key, *o.model, pinned);
      model.apply_pose(o.pose, *o.model);
      posed_on_cpu = posed_on_cpu || (o.pose && o.pose->cpu_sums);
      objects.push_back({model, *o.model, o.transform, o.pose});
    }
    const double posing_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - posing).count();
    if (posed_on_cpu) started.posing = PassTiming{"pose_vertices", posing_ms, false, posing_ms};
    record_cache_use(worker);
    std::optional<DrawPacing> pacing;
    if (schedule.pacing.paced() && schedule.deadline) {
      std::function<void()> between_chunks;
      if (serves_long_lane(worker.index)) between_chunks = [this] { yield_to_short_renders(); };
      pacing.emplace(schedule.pacing.chunk_triangles, schedule.pacing.band_texels, *schedule.deadline,
                     std::move(between_chunks));
    }
    started.frame = worker.renderer.start(objects, task.job.plan, pacing ? &*pacing : nullptr);
  } catch (...) {
    started.failure = std::current_exception();
    // A failed render fails that request only; drain GL errors now, so
    // neither the frame in flight nor the next one takes them for its own.
    while (glGetError() != GL_NO_ERROR) {
    }
  }
  started.task = std::move(task);
  return started;
}

bool RenderService::answer(Started& started, Worker& worker) {
  std::optional<RenderOutput> output;
  std::exception_ptr failure = started.failure;
  if (!failure) {
    try {
      output = worker.renderer.finish(std::move(started.frame));
      if (started.posing) output->timings.insert(output->timings.begin(), *started.posing);
    } catch (...) {
      failure = std::current_exception();
      while (glGetError() != GL_NO_ERROR) {
      }
    }
  }
  // Whatever a lost context drew is not trusted, success or not: the
  // request fails with a retryable error and everything starts over on a
  // new context.
  if (context_lost(started.number)) {
    answer_lost(started);
    return true;
  }
  if (failure) {
    started.task.promise.set_exception(failure);
  } else {
    started.task.promise.set_value(std::move(*output));
  }
  return false;
}

void RenderService::answer_lost(Started& started) {
  started.task.promise.set_exception(std::make_exception_ptr(
      gpu::GpuReset("the GL context was lost during this render; the daemon made a new one, retry")));
}

}  // namespace toond::render
