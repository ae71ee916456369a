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

// Checked before a byte is sent: -o names a folder, or a path one can be made at.
void prepare_output_folder(const fs::path& out_dir) {
  std::error_code ec;
  if (fs::exists(out_dir, ec) && !fs::is_directory(out_dir, ec)) {
    throw UsageError("-o " + out_dir.string() + ": exists and is not a folder");
  }
  fs::create_directories(out_dir, ec);
  if (ec) throw UsageError("-o " + out_dir.string() + ": cannot create the folder: " + ec.message());
}

// The looks a gallery renders: the daemon's presets, then toon's effect looks.
struct GalleryLooks {
  std::vector<Look> looks;
  std::size_t presets = 0;
  // Per look, why it cannot render: a preset this toon's schema does not
  // know still gets its column, its renders failing with the reason.
  std::vector<std::string> problem;
  json preset_answer;  // the daemon's GET /presets

  json preset_params(const Look& look) const {
    if (!look.is_preset || !preset_answer.contains(look.name)) return json();
    const json& preset = preset_answer[look.name];
    return preset.is_object() && preset.contains("params") ? preset["params"] : json();
  }
};

GalleryLooks gallery_looks(json presets, const proto::ParamSchema& schema) {
  GalleryLooks out;
  out.looks = gallery::preset_looks(presets, schema);
  out.presets = out.looks.size();
  for (const Look& look : gallery::effect_looks()) out.looks.push_back(look);
  out.problem.resize(out.looks.size());
  for (std::size_t i = 0; i < out.presets; ++i) {
    try {
      gallery::validate_look(out.looks[i], schema);
    } catch (const UsageError& e) {
      out.problem[i] = e.what();
    }
  }
  out.preset_answer = std::move(presets);
  return out;
}

// One gallery run: every look on every model, a thumbnail of each for the
// contact sheet, and the page's record of each render.
class Gallery {
 public:
  Gallery(const Options& options, const proto::ParamSchema& schema, Connection& conn, GalleryLooks looks,
          std::size_t models)
      : options_(options),
        schema_(schema),
        conn_(conn),
        looks_(std::move(looks)),
        total_(models * looks_.looks.size()),
        factor_(gallery::thumbnail_factor(options.size)) {}

  std::size_t total() const { return total_; }
  const GalleryLooks& looks() const { return looks_; }

  void render_model(const gallery::ModelFolder& model);
  // The contact sheet and index.html; false when either could not be written.
  bool write_sheet_and_page(const std::string& renderer) const;
  // The summary line; the exit status.
  int finish(bool written_ok) const;

 private:
  std::string upload(const gallery::ModelFolder& model, const std::string& model_text_path, gallery::ModelFrame& frame,
                     std::string& error);
  void skip_model(gallery::PageModel page_model);
  gallery::PageRender render_look(const gallery::ModelFolder& model, const fs::path& model_dir,
                                  const gallery::PageModel& page_model, std::size_t li, const std::string& model_id,
                                  const gallery::ModelView& view, const gallery::ModelFrame& frame,
                                  const std::error_code& mkdir_ec);
  std::string render_to_file(const json& params, const fs::path& file, std::optional<image::Image>& thumb) const;

  const Options& options_;
  const proto::ParamSchema& schema_;
  Connection& conn_;
  GalleryLooks looks_;
  std::size_t total_;
  int factor_;
  std::vector<std::vector<std::optional<image::Image>>> thumbs_;
  std::vector<gallery::PageModel> page_;
  std::size_t done_ = 0, failures_ = 0;
};

// The model's bundle as sent (a .glb written beside its renders where the
// gallery sends one, so the page's commands render what was uploaded);
// its id, or "" with `error` set.
std::string Gallery::upload(const gallery::ModelFolder& model, const std::string& model_text_path,
                            gallery::ModelFrame& frame, std::string& error) {
  BundleScan scan = scan_obj_bundle(model.obj_path);
  for (const std::string& w : scan.warnings) std::cerr << "toon: " << model.name << ": warning: " << w << "\n";
  frame = gallery::frame_from_obj(scan.files.front().content);
  if (model.as_glb) {
    BundleFile glb{fs::path(model_text_path).filename().string(), model_text_path, glb_from_obj(scan)};
    std::error_code ec;
    fs::create_directories(fs::path(model_text_path).parent_path(), ec);
    error = ec ? "cannot create " + fs::path(model_text_path).parent_path().string() + ": " + ec.message()
               : write_file(glb.disk_path, glb.content);
    scan.files = {std::move(glb)};
  }
  return error.empty() ? upload_model(conn_, model, scan, error) : std::string();
}

// One line for a model that could not be sent, rather than one per look.
void Gallery::skip_model(gallery::PageModel page_model) {
  done_ += looks_.looks.size();
  failures_ += looks_.looks.size();
  std::cerr << "[" << done_ << "/" << total_ << "] " << page_model.name << ": " << page_model.error << "; its "
            << looks_.looks.size() << " renders are skipped\n";
  for (const Look& look : looks_.looks) {
    page_model.renders.push_back(
        gallery::PageRender{look.name, look.description, {}, look.params, {}, "not rendered: " + page_model.error});
  }
  page_.push_back(std::move(page_model));
}

void Gallery::render_model(const gallery::ModelFolder& model) {
  const fs::path model_dir = fs::path(options_.output) / model.name;
  const std::string model_text_path =
      model.as_glb ? (model_dir / model.obj_path.filename().replace_extension(".glb")).generic_string()
                   : (fs::path(options_.models_dir) / model.folder / model.obj_path.filename()).generic_string();
  gallery::PageModel page_model{model.name, model_text_path, {}, {}};
  thumbs_.emplace_back(looks_.looks.size());
  std::string model_id;
  gallery::ModelFrame frame;
  try {
    model_id = upload(model, model_text_path, frame, page_model.error);
  } catch (const std::exception& e) {
    page_model.error = e.what();
  }
  if (!page_model.error.empty()) return skip_model(std::move(page_model));
  const gallery::ModelView view = gallery::view_for_model(model.folder, schema_);
  std::error_code mkdir_ec;
  fs::create_directories(model_dir, mkdir_ec);
  for (std::size_t li = 0; li < looks_.looks.size(); ++li) {
    page_model.renders.push_back(render_look(model, model_dir, page_model, li, model_id, view, frame, mkdir_ec));
  }
  page_.push_back(std::move(page_model));
}

gallery::PageRender Gallery::render_look(const gallery::ModelFolder& model, const fs::path& model_dir,
                                         const gallery::PageModel& page_model, std::size_t li,
                                         const std::string& model_id, const gallery::ModelView& view,
                                         const gallery::ModelFrame& frame, const std::error_code& mkdir_ec) {
  const Look& look = looks_.looks[li];
  std::cerr << "[" << ++done_ << "/" << total_ << "] " << model.name << "/" << look.name << "\n";
  const json params =
      gallery::render_params(look, looks_.preset_params(look), view, frame, options_.size, model_id, schema_);
  const std::string file_name = look.name + ".png";
  gallery::PageRender render{
      look.name, look.description, {}, params, gallery::render_command(page_model.obj_path, params, file_name), {}};
  std::string error = looks_.problem[li];
  if (error.empty() && mkdir_ec) error = "cannot create " + model_dir.string() + ": " + mkdir_ec.message();
  if (error.empty()) {
    try {
      schema_.validate(params);
    } catch (const RequestError& e) {
      error = std::string("invalid render parameters: ") + e.what();
    }
  }
  if (error.empty()) error = render_to_file(params, model_dir / file_name, thumbs_.back()[li]);
  if (error.empty()) {
    render.image = model.name + "/" + file_name;
    return render;
  }
  ++failures_;
  render.error = error;
  std::cerr << "toon: " << model.name << "/" << look.name << " failed: " << error << "\n";
  std::error_code ec;
  fs::remove(model_dir / file_name, ec);  // no stale image from an earlier run
  return render;
}

// Renders `params` into `file` and its thumbnail; "" or what went wrong.
std::string Gallery::render_to_file(const json& params, const fs::path& file,
                                    std::optional<image::Image>& thumb) const {
  httplib::Result result = conn_.post_json("/render", params);
  if (!result) return conn_.describe_failure(result);
  if (result->status != 200) return reply_problem(*result);
  if (result->get_header_value("Content-Type").rfind("image/png", 0) != 0) {
    return "expected image/png from toond, got '" + result->get_header_value("Content-Type") + "'";
  }
  try {
    const image::Image img = image::decode_png(result->body);
    if (std::string error = write_file(file, result->body); !error.empty()) return error;
    // A sprite sheet is several cells' worth: shrunk further to fit one.
    const int tiles = std::max(1, std::max(img.width, img.height) / options_.size);
    thumb = gallery::make_thumbnail(img, factor_ * tiles);
    return {};
  } catch (const std::exception& e) {
    return std::string("toond's PNG does not decode: ") + e.what();
  }
}

bool Gallery::write_sheet_and_page(const std::string& renderer) const {
  const fs::path out_dir = options_.output;
  bool written_ok = true;
  std::vector<std::vector<const image::Image*>> grid;
  for (const auto& row : thumbs_) {
    auto& cells = grid.emplace_back();
    for (const auto& t : row) cells.push_back(t ? &*t : nullptr);
  }
  const std::string sheet_name = "contact-sheet.png";
  const int thumb_size = options_.size / factor_;
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
  info.server = options_.server;
  info.renderer = renderer;
  info.size = options_.size;
  if (std::string e = write_file(out_dir / "index.html", gallery::gallery_page(info, page_)); !e.empty()) {
    std::cerr << "toon: index.html: " << e << "\n";
    written_ok = false;
  }
  return written_ok;
}

int Gallery::finish(bool written_ok) const {
  if (failures_) {
    std::cerr << "toon: " << failures_ << " of " << total_ << " renders failed (see above); ";
  } else {
    std::cerr << "toon: ";
  }
  std::cerr << "wrote " << total_ - failures_ << (total_ - failures_ == 1 ? " image" : " images")
            << (written_ok ? ", contact-sheet.png and index.html" : "") << " in " << options_.output << "\n";
  return failures_ || !written_ok ? 1 : 0;
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
  prepare_output_folder(options.output);

  Connection conn(options.server);
  httplib::Result presets_result = conn.get("/presets");
  if (!presets_result) return conn.network_failure(presets_result);
  if (presets_result->status != 200) return error_reply(*presets_result);
  json presets = json::parse(presets_result->body, nullptr, false);
  if (!presets.is_object()) {
    std::cerr << "toon: unexpected answer from toond for GET /presets (not a JSON object)\n";
    return 1;
  }
  const std::string renderer = gl_renderer(conn);
  Gallery gallery(options, schema, conn, gallery_looks(std::move(presets), schema), selection.models.size());
  const GalleryLooks& looks = gallery.looks();
  std::cerr << "toon: rendering " << looks.looks.size() << " looks (" << looks.presets << " presets, "
            << looks.looks.size() - looks.presets << " effects) on " << selection.models.size()
            << (selection.models.size() == 1 ? " model" : " models") << " at " << options.size << "×" << options.size
            << ": " << gallery.total() << " renders\n";
  for (const gallery::ModelFolder& model : selection.models) gallery.render_model(model);
  return gallery.finish(gallery.write_sheet_and_page(renderer));
}

}  // namespace toond::cli
