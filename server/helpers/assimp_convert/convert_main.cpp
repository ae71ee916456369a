// toond-assimp-convert: reads one model file of a format assimp knows (FBX,
// COLLADA, 3DS, 3MF, OFF and the others listed by scene/import/assimp_import.h) for
// the daemon, in a process of its own, and answers it as a binary glTF
// that the daemon reads with its own glTF importer, checks included.
//   toond-assimp-convert --format EXT --memory-mb N --cpu-seconds S < file
// Standard output: the .glb. Standard error: on success, one line per thing
// the answer does not carry or that was converted or mended, each starting
// "note: ", then "frame_rate: CLIP FPS" for each clip keyed by frame; on
// failure, the reason. Exit status 0 on success, 1 when the file cannot
// be read, 2 on a usage error.
#include <cstdio>
#include <memory>
#include <new>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <assimp/Exporter.hpp>
#include <assimp/Importer.hpp>

#include "helpers/assimp_convert/animation_timing.h"
#include "helpers/assimp_convert/format_materials.h"
#include "helpers/assimp_convert/morph_weight_channels.h"
#include "helpers/assimp_convert/reading_report.h"
#include "helpers/assimp_convert/scene_reading.h"
#include "helpers/assimp_convert/upright_metres.h"
#include "helpers/process/resource_limits.h"
#include "helpers/process/stdio_bytes.h"

namespace {

using namespace toond;

struct Options {
  helper_process::ResourceLimits limits;
  std::string format;
};

bool known_format(const std::string& format) {
  if (format.empty() || format.size() > 16) return false;
  for (const char c : format) {
    if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9'))) return false;
  }
  return true;
}

std::optional<Options> parse_options(int argc, char** argv) {
  Options options;
  if (argc % 2 != 1) return std::nullopt;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    const std::string value = argv[i + 1];
    if (flag == "--format" && known_format(value)) {
      options.format = value;
    } else if (const auto count = helper_process::parse_count(value); count && flag == "--memory-mb") {
      options.limits.memory_mb = *count;
    } else if (count && flag == "--cpu-seconds") {
      options.limits.cpu_seconds = *count;
    } else {
      return std::nullopt;
    }
  }
  if (options.format.empty() || options.limits.memory_mb == 0 || options.limits.cpu_seconds == 0) return std::nullopt;
  return options;
}

int fail(const std::string& why) {
  std::fprintf(stderr, "%s\n", why.c_str());
  return 1;
}

std::string as_glb(const aiScene& scene) {
  Assimp::Exporter exporter;
  const aiExportDataBlob* blob = exporter.ExportToBlob(&scene, "glb2");
  if (!blob) throw std::runtime_error(std::string("cannot write it as glTF: ") + exporter.GetErrorString());
  return std::string(static_cast<const char*>(blob->data), blob->size);
}

int convert(const Options& options) {
  const std::string input = helper_process::read_all_stdin();
  if (input.empty()) return fail("the file is empty");
  Assimp::Importer importer;
  std::vector<std::string> notes;
  assimp_convert::read_scene(importer, input, options.format, notes);
  const std::size_t over_four = assimp_convert::keep_four_influences(importer);
  const std::unique_ptr<aiScene> scene(importer.GetOrphanedScene());
  const auto add = [&notes](std::vector<std::string> more) {
    for (std::string& note : more) notes.push_back(std::move(note));
  };
  if (options.format == "b3d") add(assimp_convert::count_b3d_frames_from_zero(*scene));
  const std::vector<std::string> frame_rates = assimp_convert::frame_rate_lines(*scene, options.format);
  add(assimp_convert::give_clips_a_speed(*scene));
  add(assimp_convert::make_upright_metres(*scene));
  if (options.format == "fbx") assimp_convert::let_textures_replace_colours(*scene);
  if (options.format == "3mf") assimp_convert::linearise_display_colours(*scene);
  if (options.format == "md3") assimp_convert::name_md3_materials_by_surface(*scene);
  add(assimp_convert::not_carried(*scene, over_four));
  const std::string glb = assimp_convert::with_morph_weight_channels(as_glb(*scene), *scene, notes);
  if (!helper_process::write_all_stdout(glb)) return fail("cannot write the answer");
  for (const std::string& note : notes) std::fprintf(stderr, "note: %s\n", note.c_str());
  for (const std::string& line : frame_rates) std::fprintf(stderr, "%s\n", line.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const auto options = parse_options(argc, argv);
  if (!options) {
    std::fprintf(stderr, "usage: toond-assimp-convert --format EXT --memory-mb N --cpu-seconds S < file\n");
    return 2;
  }
  helper_process::apply_resource_limits(options->limits);
  try {
    return convert(*options);
  } catch (const std::bad_alloc&) {
    return fail("reading it needs more than the memory limit of " + std::to_string(options->limits.memory_mb) + " MB");
  } catch (const std::exception& e) {
    return fail(e.what());
  }
}
