#include "render/sheet_atlas.h"

#include <cstdio>

namespace toond::render {
namespace {

using nlohmann::json;

std::string frame_name(int index) {
  char name[16];
  std::snprintf(name, sizeof name, "frame_%03d", index);
  return name;
}

// Where `point` projects in the tile, 0..1 across and down.
json pivot_of(const CameraSetup& camera, const glm::dvec3& point) {
  const glm::dvec4 clip = camera.projection * camera.view * glm::dvec4(point, 1.0);
  return {{"x", (clip.x / clip.w + 1.0) * 0.5}, {"y", (1.0 - clip.y / clip.w) * 0.5}};
}

json framing_of(const CameraParams& params, const CameraSetup& camera) {
  json framing = {{"projection", params.projection == Projection::Orthographic ? "orthographic" : "perspective"},
                  {"distance", camera.distance}};
  if (params.projection == Projection::Orthographic) {
    framing["half_height"] = camera.half_height;
  } else {
    framing["fov"] = params.fov_deg;
  }
  return framing;
}

// Aseprite's tags: one per clip, pitch and direction, over its row's frames
// ("walk_45", "walk_45_p30" when the sheet has several pitches).
json frame_tags(const SheetLayout& layout, const SheetParams& sheet) {
  json tags = json::array();
  const auto tag_name = [&](const SheetFrame& frame) {
    char angle[32];
    std::snprintf(angle, sizeof angle, "%g", frame.yaw_deg);
    std::string name = sheet.clips[static_cast<std::size_t>(frame.clip)].name + "_" + angle;
    if (sheet.pitches_deg.size() > 1) {
      std::snprintf(angle, sizeof angle, "%g", frame.pitch_deg);
      name += std::string("_p") + angle;
    }
    return name;
  };
  for (std::size_t i = 0; i < layout.frames.size();) {
    const SheetFrame& first = layout.frames[i];
    std::size_t end = i;
    while (end < layout.frames.size() && layout.frames[end].y == first.y) ++end;
    tags.push_back({{"name", tag_name(first)},
                    {"from", first.index},
                    {"to", layout.frames[end - 1].index},
                    {"direction", "forward"},
                    {"clip", sheet.clips[static_cast<std::size_t>(first.clip)].name},
                    {"yaw", first.yaw_deg},
                    {"pitch", first.pitch_deg}});
    i = end;
  }
  return tags;
}

}  // namespace

json sheet_atlas(const SheetLayout& layout, const RenderParams& params, const SceneFrame& scene,
                 const std::string& image_name) {
  const double aspect = static_cast<double>(layout.tile_width) / layout.tile_height;
  const glm::dvec3 foot((scene.bounds.min.x + scene.bounds.max.x) * 0.5, scene.bounds.min.y,
                        (scene.bounds.min.z + scene.bounds.max.z) * 0.5);
  const json size = {{"w", layout.tile_width}, {"h", layout.tile_height}};
  json frames = json::object();
  json framing;
  for (const SheetFrame& frame : layout.frames) {
    const RenderParams one = frame_params(params, layout, frame);
    const CameraSetup camera = fit_camera(one.camera, scene.bounds, aspect, scene.outline);
    if (framing.is_null()) framing = framing_of(one.camera, camera);
    frames[frame_name(frame.index)] = {
        {"frame", {{"x", frame.x}, {"y", frame.y}, {"w", layout.tile_width}, {"h", layout.tile_height}}},
        {"rotated", false},
        {"trimmed", false},
        {"spriteSourceSize", {{"x", 0}, {"y", 0}, {"w", layout.tile_width}, {"h", layout.tile_height}}},
        {"sourceSize", size},
        {"pivot", pivot_of(camera, foot)},
        {"index", frame.index},
        {"yaw", frame.yaw_deg},
        {"pitch", frame.pitch_deg},
    };
    if (frame.clip >= 0) {
      json& entry = frames[frame_name(frame.index)];
      entry["clip"] = params.sheet->clips[static_cast<std::size_t>(frame.clip)].name;
      entry["time"] = frame.time;
      entry["duration"] = frame.duration_ms;
    }
  }
  const SheetParams& sheet = *params.sheet;
  json meta = {
      {"app", "toond"},
      {"version", "1"},
      {"image", image_name},
      {"format", "RGBA8888"},
      {"size", {{"w", layout.width}, {"h", layout.height}}},
      {"scale", "1"},
      {"padding", layout.padding},
      {"columns", layout.columns},
      {"rows", layout.rows},
      {"frames_per_pitch", sheet.frames},
      {"yaw_start", sheet.yaw_start_deg},
      {"yaw_step", sheet.yaw_step_deg},
      {"pitches", sheet.pitches_deg},
      {"camera", framing},
  };
  if (!sheet.clips.empty()) meta["frameTags"] = frame_tags(layout, sheet);
  return {{"frames", frames}, {"meta", meta}};
}

}  // namespace toond::render
