#pragma once
// The one way into the render pipeline from outside it. The HTTP routes
// resolve a request's completed parameters here, then ask for its answer:
// a sheet's file drawn from nothing, the result cache's copy of an
// identical request answered before, or a render by the stages of
// pipeline.h. The entry owns the result cache and what the stages share
// (clips' framings, line drawings' edges and lane), holds the daemon's model
// store, model library and render threads, and says what the render
// threads hold for /healthz and /metrics. Nothing here knows HTTP, and
// nothing this header includes reaches EGL or GL: the render threads' and
// the GPU's failures come out as RenderFailure.
#include <chrono>
#include <cstddef>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "pipeline/render_limits.h"
#include "pipeline/render_observer.h"
#include "pipeline/result_cache.h"
#include "pipeline/sheet_file.h"

namespace toond::render {
class RenderService;
}
namespace toond::scene {
class ModelLibrary;
class ModelStore;
}  // namespace toond::scene

namespace toond::pipeline {

// Who asks for a render: the connection's address (it takes turns with
// other clients in the queue), when its request arrived (a render's seconds
// count from there) and what counts its renders.
struct Caller {
  std::string client;
  std::chrono::steady_clock::time_point arrived;
  RenderObserver& observer;
};

struct Answer {
  enum class From {
    File,   // a sheet's file that needs nothing drawn (?atlas=json, godot): its body and headers alone
    Cache,  // an identical request's render, from the result cache
    Render  // rendered now, and kept in the result cache
  };
  std::shared_ptr<const CachedRender> render;
  From from = From::Render;
  std::string server_timing;  // From::Render: its stages (rendered_answer.h)
};

// A request resolved against the stored models (RenderEntry::resolve),
// which stay pinned in the store until it is answered or dropped.
class ResolvedRender {
 public:
  ResolvedRender(ResolvedRender&&) noexcept;
  ResolvedRender& operator=(ResolvedRender&&) noexcept;
  ~ResolvedRender();

 private:
  friend class RenderEntry;
  struct State;
  explicit ResolvedRender(std::unique_ptr<State> state);
  std::unique_ptr<State> state_;
};

class RenderEntry {
 public:
  struct Settings {
    RenderLimits limits{};
    std::chrono::milliseconds deadline{60000};  // --render-timeout: how long a render may wait and draw
    std::size_t result_cache_bytes = 0;         // 0: no result cache, every request renders
  };

  RenderEntry(scene::ModelStore& store, scene::ModelLibrary& library, render::RenderService& renderer,
              const Settings& settings);
  ~RenderEntry();
  RenderEntry(const RenderEntry&) = delete;
  RenderEntry& operator=(const RenderEntry&) = delete;

  // `completed`: parameters ParamSchema::validate_and_complete() checked and
  // filled (presets expanded), looked up against the stored models
  // (resolve.h, which says what it throws).
  ResolvedRender resolve(const nlohmann::json& completed);

  // The answer `sheet` picks (sheet_query of the route) of a resolved
  // request. Throws as check_sheet_answer (sheet_answer.h) and render()
  // (pipeline.h) do, the render threads' and the GPU's failures as
  // RenderFailure.
  Answer answer(ResolvedRender resolved, const SheetAnswer& sheet, const Caller& caller);

  // A model deleted or let go from the store leaves this replica's memory
  // and GPU now; other replicas drop it at their next lookup.
  void forget(const std::string& model_id);

  // The GL the render threads draw with: vendor, renderer, version,
  // glsl_version and platform.
  nlohmann::json gl_document() const;
  std::size_t queue_depth() const;
  std::size_t gpu_resets() const;
  std::size_t overlapped_frames() const;
  std::size_t gpu_models_loaded() const;
  std::size_t gpu_model_bytes() const;
  // Null when there is none (Settings::result_cache_bytes 0).
  const ResultCache* result_cache() const { return results_.get(); }

 private:
  struct Shared;  // what the stages share: clips' framings, line drawings

  scene::ModelStore& store_;
  scene::ModelLibrary& library_;
  render::RenderService& renderer_;
  const Settings settings_;
  std::unique_ptr<Shared> shared_;
  std::unique_ptr<ResultCache> results_;
};

}  // namespace toond::pipeline
