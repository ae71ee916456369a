#pragma once
// The way a render request goes, from its typed parameters to the bytes of
// its answer:
//   resolve  models, scene, clips, size limits, bundle images  (resolve.h)
//   pose     each frame's pose of each object                  (pose.h)
//   price    refused over --max-render-cost; lane and pacing   (price.h)
//   queue    the frames to the render threads, back to back    (queue.h)
//   assemble one image, a sheet, an animation, pixel art        (assemble.h)
//   encode   PNG (a layer's, a sheet's with its atlas) or WebP  (encode.h)
// A single image is a sheet of one frame: the same stages, one frame. The
// way in is render_entry.h: it resolves a request and answers it from its
// result cache or by these stages; the HTTP layer parses the request and
// writes the answer; nothing here knows HTTP.
#include <chrono>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pipeline/encode.h"
#include "pipeline/pose.h"
#include "pipeline/price.h"
#include "pipeline/render_limits.h"
#include "pipeline/request.h"
#include "pipeline/resolve.h"
#include "pipeline/svg_render.h"
#include "render/run/render_service.h"
#include "scene/store/model_library.h"

namespace toond::pipeline {

// What the stages draw on: the daemon's models, render threads, clip
// framings and limits.
struct Services {
  scene::ModelLibrary& library;
  render::RenderService& renderer;
  ClipFramings& framings;
  const RenderLimits& limits;
  std::chrono::milliseconds deadline;  // --render-timeout: how long a render may wait and draw
  LineDrawings& lines;                 // output svg's edges and lane (svg_render.h)
};

// A finished render: its answer's bytes and what its headers report.
struct Rendered {
  Encoded encoded;
  std::vector<render::PassTiming> timings;  // the render threads', pass by pass, over every frame
  std::string plan;                         // PassPlan::describe()
  std::vector<render::LodUse> lods;
  int samples = 1;
  RenderPrice price;
  bool long_lane = false;  // whether it waited in the long lane
  double pose_ms = 0;      // posing on the request's thread; 0: nothing was posed
  double queue_ms = 0;     // waiting for a render thread
  double render_ms = 0;    // the render threads' own time
  double encode_ms = 0;
};

// A sheet's atlas alone (?atlas=json): posed and framed, nothing drawn.
nlohmann::ordered_json sheet_atlas(const Request& request, Services& services);

// A sheet's atlas as the file the request asks for (?atlas=json or godot,
// sheet_answer.h), when it needs nothing drawn (needs_drawing is false).
Encoded sheet_file(const Request& request, Services& services);

// Poses, prices, queues, assembles and encodes a resolved request (output
// svg: draws it as vectors, svg_render.h). `client`
// (the connection's address) takes turns with other clients in the queue.
// Throws CostRefused over --max-render-cost, QueueFull when the lane is
// full, RequestError 503 deadline_exceeded, render::RenderAborted when a
// paced render was stopped at its deadline, and whatever the render
// threads throw.
Rendered render(Request request, const std::string& client, Services& services);

}  // namespace toond::pipeline
