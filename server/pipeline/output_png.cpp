#include "pipeline/output_png.h"

#include <cstdio>

#include <nlohmann/json.hpp>

#include "image/layer_png.h"
#include "render/plan/pass_plan.h"
#include "request_error.h"

namespace toond::pipeline {
namespace {

using Objects = std::vector<render::JobObject>;

bool ids_by_object(const render::RenderParams& params) { return render::id_source(params) == render::IdSource::Object; }

int id_count(const render::RenderParams& params, const Objects& objects) {
  if (ids_by_object(params)) return static_cast<int>(objects.size());
  return static_cast<int>(objects.front().model->materials.size());
}

// What each index of an id layer stands for, in index order from 1.
nlohmann::json id_mapping(const render::RenderParams& params, const Objects& objects) {
  nlohmann::json ids = nlohmann::json::array();
  if (ids_by_object(params)) {
    for (std::size_t i = 0; i < objects.size(); ++i) {
      ids.push_back({{"id", i + 1}, {"object", i}, {"model", params.objects[i].model}});
    }
  } else {
    const auto& materials = objects.front().model->materials;
    for (std::size_t m = 0; m < materials.size(); ++m) {
      ids.push_back({{"id", m + 1}, {"material", materials[m].name}});
    }
  }
  return {{"background", 0}, {"by", ids_by_object(params) ? "object" : "material"}, {"ids", ids}};
}

std::string depth_range_header(const image::DepthRange& range) {
  char text[96];
  std::snprintf(text, sizeof text, "near=%.9g; far=%.9g", range.near_depth, range.far_depth);
  return text;
}

nlohmann::json depth_description(const image::DepthRange& range) {
  return {{"near", range.near_depth},
          {"far", range.far_depth},
          {"units", "scene"},
          {"encoding", "linear: near 0, far 65534"},
          {"background", 65535}};
}

}  // namespace

OutputDescription describe_output(const render::RenderParams& params, const Objects& objects) {
  OutputDescription description;
  description.output = params.output;
  if (params.output != render::Output::Id || objects.empty()) return description;
  description.id_count = id_count(params, objects);
  if (description.id_count > image::kMaxLayerIds) {
    throw RequestError(422, "too_many_ids",
                       "/output: an id layer numbers at most 255 " +
                           std::string(ids_by_object(params) ? "objects" : "materials") + "; this one has " +
                           std::to_string(description.id_count),
                       "/output");
  }
  description.id_mapping = id_mapping(params, objects).dump();
  return description;
}

OutputPng encode_output(const render::RenderOutput& out, const OutputDescription& output,
                        const image::PngOptions& options) {
  image::TextChunks text = options.text;
  switch (output.output) {
    case render::Output::Color:
    case render::Output::Lines:
    case render::Output::Svg:  // drawn as vectors (svg_render.h), never read back: not reached
      return {image::encode_png(out.image, options), {}};
    case render::Output::Depth: {
      const image::DepthRange range = image::visible_depth_range(out.layer);
      text.emplace_back("toond:depth", depth_description(range).dump());
      return {image::encode_depth_png(out.layer, range, options.compression_level, text),
              {{"X-Toond-Depth-Range", depth_range_header(range)}}};
    }
    case render::Output::Normal:
      return {image::encode_normal_png(out.layer, options.compression_level, text), {}};
    case render::Output::Id:
      text.emplace_back("toond:ids", output.id_mapping);
      return {image::encode_id_png(out.layer, output.id_count, options.compression_level, text), {}};
  }
  return {};
}

}  // namespace toond::pipeline
