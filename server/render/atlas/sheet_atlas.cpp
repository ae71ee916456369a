#include "render/atlas/sheet_atlas.h"

#include <cstdio>
#include <map>

namespace toond::render {
namespace {

using json = nlohmann::ordered_json;

// Aseprite's file name format `{frame}`: the frame's index, which is how
// Phaser looks a tag's frames up.
std::string frame_name(int index) { return std::to_string(index); }

// Where `point` projects in the tile, 0..1 across and down.
json anchor_of(const CameraSetup& camera, const glm::dvec3& point) {
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

std::string degrees(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// The frames one tag plays: an animated sheet's row (one clip, pitch and
// direction), or a turntable's frames of one pitch.
bool same_track(const SheetFrame& a, const SheetFrame& b) {
  if (a.clip >= 0) return a.clip == b.clip && a.y == b.y;
  return a.pitch_deg == b.pitch_deg;
}

// "Walk_45" (clip and yaw), "turn" for a turntable; "_p30" added when the
// sheet has several pitches.
std::string track_name(const SheetFrame& first, const SheetParams& sheet) {
  std::string name =
      first.clip >= 0 ? sheet.clips[static_cast<std::size_t>(first.clip)].name + "_" + degrees(first.yaw_deg) : "turn";
  if (sheet.pitches_deg.size() > 1) name += "_p" + degrees(first.pitch_deg);
  return name;
}

struct Tracks {
  json tags = json::array();         // meta.frameTags, Aseprite's
  json animations = json::object();  // Pixi's: tag name → frame names
};

// A name a track already has (a clip listed twice, yaws that come round
// again) gets " (2)", " (3)", …: engines keep one animation per name.
std::string unique_name(const std::string& name, std::map<std::string, int>& uses) {
  const int n = ++uses[name];
  return n == 1 ? name : name + " (" + std::to_string(n) + ")";
}

Tracks tracks_of(const SheetLayout& layout, const SheetParams& sheet) {
  Tracks tracks;
  std::map<std::string, int> uses;
  for (std::size_t i = 0; i < layout.frames.size();) {
    const SheetFrame& first = layout.frames[i];
    std::size_t end = i;
    json names = json::array();
    while (end < layout.frames.size() && same_track(first, layout.frames[end])) {
      names.push_back(frame_name(layout.frames[end].index));
      ++end;
    }
    const std::string name = unique_name(track_name(first, sheet), uses);
    json tag = {{"name", name}, {"from", first.index}, {"to", layout.frames[end - 1].index}, {"direction", "forward"}};
    if (first.clip >= 0) {
      const SheetClip& clip = sheet.clips[static_cast<std::size_t>(first.clip)];
      // Aseprite's count of plays, a string, written only when set (not
      // set: the tag loops); a one-shot plays once.
      if (!clip.loop) tag["repeat"] = "1";
      tag["clip"] = clip.name;
      tag["yaw"] = first.yaw_deg;
    }
    tag["pitch"] = first.pitch_deg;
    tracks.tags.push_back(std::move(tag));
    tracks.animations[name] = std::move(names);
    i = end;
  }
  return tracks;
}

}  // namespace

nlohmann::ordered_json sheet_atlas(const SheetLayout& layout, const RenderParams& params,
                                   std::span<const FramePlan> plans, const std::string& image_name) {
  const SceneFrame& scene = *plans.front().scene;
  const glm::dvec3 foot((scene.bounds.min.x + scene.bounds.max.x) * 0.5, scene.bounds.min.y,
                        (scene.bounds.min.z + scene.bounds.max.z) * 0.5);
  const json size = {{"w", layout.tile_width}, {"h", layout.tile_height}};
  const SheetParams& sheet = *params.sheet;
  json frames = json::object();
  json framing;
  for (std::size_t i = 0; i < layout.frames.size(); ++i) {
    const SheetFrame& frame = layout.frames[i];
    const FramePlan& plan = plans[i];
    if (framing.is_null()) framing = framing_of(plan.params.camera, plan.camera);
    const json anchor = anchor_of(plan.camera, foot);
    json entry = {
        {"frame", {{"x", frame.x}, {"y", frame.y}, {"w", layout.tile_width}, {"h", layout.tile_height}}},
        {"rotated", false},
        {"trimmed", false},
        {"spriteSourceSize", {{"x", 0}, {"y", 0}, {"w", layout.tile_width}, {"h", layout.tile_height}}},
        {"sourceSize", size},
        {"duration", frame.duration_ms},
        {"anchor", anchor},
        {"pivot", anchor},
        {"index", frame.index},
        {"yaw", frame.yaw_deg},
        {"pitch", frame.pitch_deg},
    };
    if (frame.clip >= 0) {
      entry["clip"] = sheet.clips[static_cast<std::size_t>(frame.clip)].name;
      entry["time"] = frame.time;
    }
    frames[frame_name(frame.index)] = std::move(entry);
  }
  Tracks tracks = tracks_of(layout, sheet);
  json meta = {
      {"app", "toond"},
      {"version", "1"},
      {"image", image_name},
      {"format", "RGBA8888"},
      {"size", {{"w", layout.width}, {"h", layout.height}}},
      {"scale", "1"},
      {"frameTags", std::move(tracks.tags)},
      {"padding", layout.padding},
      {"columns", layout.columns},
      {"rows", layout.rows},
      {"frames_per_pitch", sheet.frames},
      {"yaw_start", sheet.yaw_start_deg},
      {"yaw_step", sheet.yaw_step_deg},
      {"pitches", sheet.pitches_deg},
      {"camera", framing},
  };
  return {{"frames", std::move(frames)}, {"animations", std::move(tracks.animations)}, {"meta", std::move(meta)}};
}

}  // namespace toond::render
