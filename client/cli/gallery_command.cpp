#include "gallery_command.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "connection.h"
#include "gallery_looks.h"
#include "gallery_page.h"
#include "gallery_sheet.h"
#include "glb_from_obj.h"
#include "image/png_codec.h"
#include "param_schema.h"
#include "reply.h"
#include "request_error.h"

namespace toond::cli {
namespace {

namespace fs = std::filesystem;
using gallery::Look;
using nlohmann::json;

// Written beside the destination and renamed into place, so an interrupted
// run never leaves a truncated file under the final name. Returns "" or
// what went wrong.
std::string write_file(const fs::path& destination, const std::string& bytes) {
  const fs::path temporary = destination.string() + ".part-" + std::to_string(::getpid());
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) return "cannot write " + temporary.string() + ": " + std::strerror(errno);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) {
      std::error_code ec;
      fs::remove(temporary, ec);
      return "writing " + temporary.string() + " failed";
    }
  }
  std::error_code ec;
  fs::rename(temporary, destination, ec);
  if (ec) {
    fs::remove(temporary, ec);
    return "cannot rename " + temporary.string() + " to " + destination.string() + ": " + ec.message();
  }
  return {};
}

std::string reply_problem(const httplib::Response& response) {
  return describe_error_reply(response.status, response.body, response.get_header_value("Retry-After"));
}

// Uploads one model folder's bundle; returns its id, or sets `error`.
std::string upload_model(Connection& conn, const gallery::ModelFolder& model, const BundleScan& scan,
                         std::string& error) {
  std::cerr << "toon: uploading " << model.name << ": " << bundle_summary(scan) << "\n";
  httplib::Result result = conn.post_multipart("/models", bundle_parts(scan));
  if (!result) {
    error = conn.describe_failure(result);
    return {};
  }
  if (result->status != 200 && result->status != 201) {
    error = "upload failed: " + reply_problem(*result);
    return {};
  }
  const json body = json::parse(result->body, nullptr, false);
  if (!body.is_object() || !body.contains("id") || !body["id"].is_string()) {
    error = "upload failed: no model id in toond's answer";
    return {};
  }
  if (body.contains("warnings") && body["warnings"].is_array()) {
    for (const json& w : body["warnings"]) {
      std::cerr << "toon: " << model.name << ": server warning: " << (w.is_string() ? w.get<std::string>() : w.dump())
                << "\n";
    }
  }
  return body["id"].get<std::string>();
}

std::string gl_renderer(Connection& conn) {
  httplib::Result result = conn.get("/healthz");
  if (!result || result->status != 200) return {};
  const json body = json::parse(result->body, nullptr, false);
  if (body.is_object() && body.contains("gl") && body["gl"].is_object() && body["gl"].contains("renderer") &&
      body["gl"]["renderer"].is_string()) {
    return body["gl"]["renderer"].get<std::string>();
  }
  return {};
}

}  // namespace

int run_gallery(const Options& options) {
  const proto::ParamSchema& schema = proto::ParamSchema::render_params();

  // Everything that can be checked here is, before a byte is sent: the look
  // table against the schema, the model folders, the output folder.
  for (const Look& look : gallery::effect_looks()) gallery::validate_look(look, schema);
  const gallery::ModelSelection selection =
      gallery::select_models(options.models_dir, options.all_models, options.only);
  for (const std::string& note : selection.notes) std::cerr << "toon: note: " << note << "\n";

  const fs::path out_dir = options.output;
  {
    std::error_code ec;
    if (fs::exists(out_dir, ec) && !fs::is_directory(out_dir, ec)) {
      throw UsageError("-o " + out_dir.string() + ": exists and is not a folder");
    }
    fs::create_directories(out_dir, ec);
    if (ec) throw UsageError("-o " + out_dir.string() + ": cannot create the folder: " + ec.message());
  }

  Connection conn(options.server);
  httplib::Result presets_result = conn.get("/presets");
  if (!presets_result) return conn.network_failure(presets_result);
  if (presets_result->status != 200) return error_reply(*presets_result);
  const json presets = json::parse(presets_result->body, nullptr, false);
  if (!presets.is_object()) {
    std::cerr << "toon: unexpected answer from toond for GET /presets (not a JSON object)\n";
    return 1;
  }
  const std::string renderer = gl_renderer(conn);

  std::vector<Look> looks = gallery::preset_looks(presets, schema);
  const std::size_t preset_count = looks.size();
  for (const Look& look : gallery::effect_looks()) looks.push_back(look);

  // A preset this toon's schema does not know still gets its column; its
  // renders fail with the reason.
  std::vector<std::string> look_problem(looks.size());
  for (std::size_t i = 0; i < preset_count; ++i) {
    try {
      gallery::validate_look(looks[i], schema);
    } catch (const UsageError& e) {
      look_problem[i] = e.what();
    }
  }

  const std::size_t total = selection.models.size() * looks.size();
  std::cerr << "toon: rendering " << looks.size() << " looks (" << preset_count << " presets, "
            << looks.size() - preset_count << " effects) on " << selection.models.size()
            << (selection.models.size() == 1 ? " model" : " models") << " at " << options.size << "×" << options.size
            << ": " << total << " renders\n";

  const int factor = gallery::thumbnail_factor(options.size);
  const int thumb_size = options.size / factor;
  std::vector<std::vector<std::optional<image::Image>>> thumbs;
  std::vector<gallery::PageModel> page;
  std::size_t done = 0, failures = 0;

  for (const gallery::ModelFolder& model : selection.models) {
    const fs::path model_dir = out_dir / model.name;
    // A .glb made here is kept beside its renders, so the page's commands
    // render what was uploaded.
    const std::string model_text_path =
        model.as_glb ? (model_dir / model.obj_path.filename().replace_extension(".glb")).generic_string()
                     : (fs::path(options.models_dir) / model.folder / model.obj_path.filename()).generic_string();
    gallery::PageModel page_model{model.name, model_text_path, {}, {}};
    auto& row = thumbs.emplace_back(looks.size());

    std::string model_id;
    gallery::ModelFrame frame;
    try {
      BundleScan scan = scan_obj_bundle(model.obj_path);
      for (const std::string& w : scan.warnings) std::cerr << "toon: " << model.name << ": warning: " << w << "\n";
      frame = gallery::frame_from_obj(scan.files.front().content);
      if (model.as_glb) {
        BundleFile glb{fs::path(model_text_path).filename().string(), model_text_path, glb_from_obj(scan)};
        std::error_code ec;
        fs::create_directories(model_dir, ec);
        page_model.error =
            ec ? "cannot create " + model_dir.string() + ": " + ec.message() : write_file(glb.disk_path, glb.content);
        scan.files = {std::move(glb)};
      }
      if (page_model.error.empty()) model_id = upload_model(conn, model, scan, page_model.error);
    } catch (const std::exception& e) {
      page_model.error = e.what();
    }
    if (!page_model.error.empty()) {
      // One line for the model rather than one per look.
      done += looks.size();
      failures += looks.size();
      std::cerr << "[" << done << "/" << total << "] " << model.name << ": " << page_model.error << "; its "
                << looks.size() << " renders are skipped\n";
      for (const Look& look : looks) {
        page_model.renders.push_back(
            gallery::PageRender{look.name, look.description, {}, look.params, {}, "not rendered: " + page_model.error});
      }
      page.push_back(std::move(page_model));
      continue;
    }

    const gallery::ModelView view = gallery::view_for_model(model.folder, schema);
    std::error_code mkdir_ec;
    fs::create_directories(model_dir, mkdir_ec);

    for (std::size_t li = 0; li < looks.size(); ++li) {
      const Look& look = looks[li];
      std::cerr << "[" << ++done << "/" << total << "] " << model.name << "/" << look.name << "\n";
      const json preset_params = look.is_preset && presets.contains(look.name) && presets[look.name].is_object() &&
                                         presets[look.name].contains("params")
                                     ? presets[look.name]["params"]
                                     : json();
      const json params = gallery::render_params(look, preset_params, view, frame, options.size, model_id, schema);
      const std::string file_name = look.name + ".png";
      gallery::PageRender render{
          look.name, look.description, {}, params, gallery::render_command(model_text_path, params, file_name), {}};

      std::string error = look_problem[li];
      if (error.empty() && mkdir_ec) error = "cannot create " + model_dir.string() + ": " + mkdir_ec.message();
      if (error.empty()) {
        try {
          schema.validate(params);
        } catch (const RequestError& e) {
          error = std::string("invalid render parameters: ") + e.what();
        }
      }
      if (error.empty()) {
        httplib::Result result = conn.post_json("/render", params);
        if (!result) {
          error = conn.describe_failure(result);
        } else if (result->status != 200) {
          error = reply_problem(*result);
        } else if (result->get_header_value("Content-Type").rfind("image/png", 0) != 0) {
          error = "expected image/png from toond, got '" + result->get_header_value("Content-Type") + "'";
        } else {
          try {
            const image::Image img = image::decode_png(result->body);
            error = write_file(model_dir / file_name, result->body);
            if (error.empty()) {
              // A sprite sheet is several cells' worth: shrunk further to fit one.
              const int tiles = std::max(1, std::max(img.width, img.height) / options.size);
              row[li] = gallery::make_thumbnail(img, factor * tiles);
              render.image = model.name + "/" + file_name;
            }
          } catch (const std::exception& e) {
            error = std::string("toond's PNG does not decode: ") + e.what();
          }
        }
      }
      if (!error.empty()) {
        ++failures;
        render.error = error;
        std::cerr << "toon: " << model.name << "/" << look.name << " failed: " << error << "\n";
        std::error_code ec;
        fs::remove(model_dir / file_name, ec);  // no stale image from an earlier run
      }
      page_model.renders.push_back(std::move(render));
    }
    page.push_back(std::move(page_model));
  }

  bool written_ok = true;
  std::vector<std::vector<const image::Image*>> grid;
  for (const auto& row : thumbs) {
    auto& cells = grid.emplace_back();
    for (const auto& t : row) cells.push_back(t ? &*t : nullptr);
  }
  const std::string sheet_name = "contact-sheet.png";
  std::string sheet_error;
  try {
    sheet_error = write_file(out_dir / sheet_name,
                             image::encode_png(gallery::assemble_contact_sheet(grid, thumb_size, thumb_size)));
  } catch (const std::exception& e) {
    sheet_error = e.what();
  }
  if (!sheet_error.empty()) {
    std::cerr << "toon: contact sheet: " << sheet_error << "\n";
    written_ok = false;
  }

  gallery::PageInfo info;
  info.contact_sheet = sheet_error.empty() ? sheet_name : "";
  info.server = options.server;
  info.renderer = renderer;
  info.size = options.size;
  if (std::string e = write_file(out_dir / "index.html", gallery::gallery_page(info, page)); !e.empty()) {
    std::cerr << "toon: index.html: " << e << "\n";
    written_ok = false;
  }

  if (failures) {
    std::cerr << "toon: " << failures << " of " << total << " renders failed (see above); ";
  } else {
    std::cerr << "toon: ";
  }
  std::cerr << "wrote " << total - failures << (total - failures == 1 ? " image" : " images")
            << (written_ok ? ", contact-sheet.png and index.html" : "") << " in " << out_dir.string() << "\n";
  return failures || !written_ok ? 1 : 0;
}

}  // namespace toond::cli
