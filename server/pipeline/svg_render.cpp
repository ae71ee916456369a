#include "pipeline/svg_render.h"

#include <chrono>
#include <sstream>

#include "pipeline/pipeline.h"
#include "pipeline/plan.h"
#include "render/vector/line_drawing.h"

namespace toond::pipeline {
namespace {

using Clock = std::chrono::steady_clock;

double ms_between(Clock::time_point from, Clock::time_point to) {
  return std::chrono::duration<double, std::milli>(to - from).count();
}

bool poses_any(const ObjectPoses& poses) {
  for (const auto& pose : poses) {
    if (pose) return true;
  }
  return false;
}

// The kinds of line drawn, for X-Toond-Passes: "vector(silhouette,creases)".
std::string drawn_kinds(const render::FramePlan& plan) {
  const render::vector::LineChoice c = render::vector::line_choice(plan);
  std::string kinds;
  const auto add = [&](bool on, const char* name) {
    if (on) kinds += (kinds.empty() ? "" : ",") + std::string(name);
  };
  add(c.silhouettes, "silhouette");
  add(c.creases, "creases");
  add(c.intersections, "intersections");
  add(c.boundaries, "boundary");
  add(c.keep_hidden, "hidden");
  return "vector(" + kinds + ")";
}

std::string stats_header(const render::vector::LineStats& s) {
  std::ostringstream out;
  out << "candidates=" << s.candidates << "; occluders=" << s.occluders << "; occluder_tests=" << s.occluder_tests
      << "; pieces=" << s.pieces << "; paths=" << s.paths;
  out.precision(3);
  out << std::fixed << "; view_ms=" << s.view_ms << "; grid_ms=" << s.grid_ms << "; visibility_ms=" << s.visibility_ms
      << "; strokes_ms=" << s.strokes_ms;
  return out.str();
}

// The frame drawn as vectors, its objects in their poses.
render::vector::LineDrawing draw_frame(const Request& request, const ObjectPoses& poses, const render::FramePlan& plan,
                                       render::vector::EdgeCache& edges, Clock::time_point deadline,
                                       std::vector<render::LodUse>& lods) {
  std::vector<std::shared_ptr<const scene::Model>> models;
  for (const render::JobObject& o : request.objects) models.push_back(o.model);
  for (const render::ObjectPlan& o : plan.objects) lods.push_back(o.lod);
  return render::vector::draw_lines(plan, planned_objects(request, poses), models, edges, deadline);
}

// The drawing's text, or past kStreamedSvgBytes the drawing kept to be
// written as the answer goes out (its svg stage then counts no time).
Encoded svg_answer(render::vector::LineDrawing& drawing) {
  Encoded encoded;
  encoded.content_type = "image/svg+xml";
  encoded.stage = "svg";
  encoded.headers.emplace_back("X-Toond-Lines", stats_header(drawing.stats));
  if (render::vector::estimated_svg_bytes(drawing.svg) <= kStreamedSvgBytes) {
    encoded.body = render::vector::write_svg(drawing.svg);
    return encoded;
  }
  auto svg = std::make_shared<const render::vector::SvgDrawing>(std::move(drawing.svg));
  encoded.stream = std::make_shared<const StreamedBody>(
      StreamedBody{[svg](const BodySend& send) { render::vector::write_svg(*svg, send, kStreamedPieceBytes); }});
  return encoded;
}

}  // namespace

Rendered render_svg(Request request, const std::string& client, Services& services) {
  // Drawn on the full mesh: a coarser level, which only saves a rasteriser
  // samples, would put its own folds into the lines.
  request.params.lod_auto = false;
  Rendered rendered;
  const auto posing = Clock::now();
  // The drawing reads the posed vertices, so they are posed on the CPU
  // whatever the render threads would do.
  const std::vector<ObjectPoses> poses = pose_frames(request, services.framings, scene::Skinning::Cpu);
  if (poses_any(poses.front())) rendered.pose_ms = ms_between(posing, Clock::now());
  const std::vector<render::FramePlan> plans = plan_frames(request, poses);
  rendered.price = price_of(plans);
  check_render_cost(request, poses, rendered.price, services.limits);

  const auto submitted = Clock::now();
  const auto deadline = submitted + services.deadline;
  if (request.pins) request.pins->lease();
  const auto turn = services.lines.lane.wait_turn(client, deadline, services.deadline);
  const auto started = Clock::now();
  rendered.queue_ms = ms_between(submitted, started);
  render::vector::LineDrawing drawing =
      draw_frame(request, poses.front(), plans.front(), services.lines.edges, deadline, rendered.lods);
  const auto drawn = Clock::now();
  rendered.render_ms = ms_between(started, drawn);
  rendered.timings.push_back({.pass = "lines", .ms = rendered.render_ms, .gpu = false, .cpu_ms = rendered.render_ms});
  rendered.plan = drawn_kinds(plans.front());

  rendered.encoded = svg_answer(drawing);
  rendered.encode_ms = ms_between(drawn, Clock::now());
  return rendered;
}

}  // namespace toond::pipeline
