#include "commands.h"

#include <httplib.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "bundle_scan.h"
#include "connection.h"
#include "gallery_command.h"
#include "param_schema.h"
#include "reply.h"
#include "sheet_output.h"

namespace toond::cli {
namespace {

using nlohmann::json;

int health(const Options& options) {
  Connection conn(options.server);
  httplib::Result result = conn.get("/healthz");
  if (!result) return conn.network_failure(result);
  const json body = json::parse(result->body, nullptr, false);
  // A daemon that is up but unwell may still describe itself; show that
  // rather than a bare status code.
  if (!body.is_object() || !body.contains("status")) return error_reply(*result);
  std::cout << body.dump(2) << "\n";
  const bool ok = result->status == 200 && body["status"] == "ok";
  if (!ok) std::cerr << "toon: toond at " << options.server << " is not healthy\n";
  return ok ? 0 : 1;
}

int upload(const Options& options) {
  const BundleScan scan = scan_obj_bundle(options.obj_path);
  print_warnings(scan.warnings);
  if (!options.quiet) std::cerr << "toon: uploading " << bundle_summary(scan) << "\n";

  Connection conn(options.server);
  std::string query;
  if (!options.scene.empty()) query += "&scene=" + options.scene;
  if (!options.smooth_angle.empty()) query += "&smooth_angle=" + options.smooth_angle;
  if (!options.up.empty()) query += "&up=" + options.up;
  if (!options.textures.empty()) query += "&textures=" + httplib::detail::encode_query_param(options.textures);
  const std::string path = query.empty() ? "/models" : "/models?" + query.substr(1);
  httplib::Result result = conn.post_multipart(path, bundle_parts(scan));
  if (!result) return conn.network_failure(result);
  if (result->status != 200 && result->status != 201) return error_reply(*result);

  const json body = json::parse(result->body, nullptr, false);
  if (!body.is_object() || !body.contains("id")) {
    std::cerr << "toon: unexpected answer from toond (status " << result->status << ", no model id)\n";
    return 1;
  }
  if (options.quiet) {
    if (body.contains("warnings") && body["warnings"].is_array()) {
      for (const json& warning : body["warnings"]) {
        std::cerr << "toon: server warning: " << (warning.is_string() ? warning.get<std::string>() : warning.dump())
                  << "\n";
      }
    }
    const json& id = body["id"];
    std::cout << (id.is_string() ? id.get<std::string>() : id.dump()) << "\n";
  } else {
    std::cout << body.dump(2) << "\n";
  }
  return 0;
}

int info(const Options& options) {
  Connection conn(options.server);
  httplib::Result result = conn.get("/models/" + options.model_id);
  if (!result) return conn.network_failure(result);
  if (result->status != 200) return error_reply(*result);
  const json body = json::parse(result->body, nullptr, false);
  std::cout << (body.is_discarded() ? result->body : body.dump(2)) << "\n";
  return 0;
}

// The PNG is written beside its destination and renamed into place, so a
// failed or interrupted render never leaves a truncated image under the
// name a script will pick up. The temporary file is opened before the
// request, so an unwritable -o is reported before a long render.
class OutputFile {
 public:
  explicit OutputFile(const std::string& destination) : destination_(destination) {
    if (destination_ == "-") {
      if (::isatty(STDOUT_FILENO)) {
        throw UsageError("-o -: standard output is a terminal; redirect it to a file");
      }
      return;
    }
    if (std::filesystem::is_directory(destination_)) {
      throw UsageError("-o " + destination_ + ": is a directory");
    }
    temporary_ = destination_ + ".part-" + std::to_string(::getpid());
    out_.open(temporary_, std::ios::binary | std::ios::trunc);
    if (!out_) throw UsageError("-o " + destination_ + ": cannot write there: " + std::strerror(errno));
  }
  ~OutputFile() {
    if (!temporary_.empty() && !committed_) {
      out_.close();
      std::error_code ec;
      std::filesystem::remove(temporary_, ec);
    }
  }
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  // Returns an empty string on success, otherwise what went wrong.
  std::string commit(const std::string& bytes) {
    if (destination_ == "-") {
      std::cout.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
      std::cout.flush();
      return std::cout ? std::string() : std::string("writing to standard output failed");
    }
    out_.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out_.close();
    if (!out_) return "writing " + temporary_ + " failed";
    std::error_code ec;
    std::filesystem::rename(temporary_, destination_, ec);
    if (ec) return "cannot rename " + temporary_ + " to " + destination_ + ": " + ec.message();
    committed_ = true;
    return {};
  }

 private:
  std::string destination_;
  std::string temporary_;
  std::ofstream out_;
  bool committed_ = false;
};

// A stored model renders through POST /models/{id}/render, which a load
// balancer in front of several replicas hashes on (docker/nginx/); anything
// else, and an id of the wrong shape (the server names the error), through
// POST /render.
std::string render_route(const json& params) {
  const auto model = params.find("model");
  if (model == params.end() || !model->is_string()) return "/render";
  const std::string& id = model->get_ref<const std::string&>();
  const bool id_shaped =
      id.size() >= 16 && id.size() <= 64 && id.find_first_not_of("0123456789abcdef") == std::string::npos;
  return id_shaped ? "/models/" + id + "/render" : "/render";
}

// The clips of a stored model, as the daemon lists them: what turns a
// range given in frames into seconds.
json clips_of_model(const Options& options, const std::string& model_id) {
  Connection conn(options.server);
  const httplib::Result result = conn.get("/models/" + model_id);
  if (!result) throw std::runtime_error(conn.describe_failure(result));
  const json body = json::parse(result->body, nullptr, false);
  if (result->status != 200) {
    const json* message = body.is_object() && body.contains("error") ? &body["error"]["message"] : nullptr;
    throw UsageError("model " + model_id + ": " +
                     (message && message->is_string() ? message->get<std::string>() : result->body));
  }
  return body.is_object() && body.contains("animation") ? body["animation"].value("clips", json::array())
                                                        : json::array();
}

// One render request, its query (render_answer_for) on the route; a local
// model goes up with it.
httplib::Result post_render(Connection& conn, const Options& options, const json& params, const BundleScan& scan,
                            const std::string& query) {
  if (options.obj_path.empty()) return conn.post_json(render_route(params) + query, params);
  std::cerr << "toon: uploading " << bundle_summary(scan) << "\n";
  httplib::MultipartFormDataItems items = bundle_parts(scan);
  items.push_back({"params", params.dump(), "", "application/json"});
  return conn.post_multipart("/render" + query, items);
}

bool answered_as(const httplib::Response& res, const RenderAnswer& answer) {
  const std::string type = res.get_header_value("Content-Type");
  std::string expected;
  for (const std::string& t : answer.content_types) {
    if (type.rfind(t, 0) == 0) return true;
    expected += (expected.empty() ? "" : " or ") + t;
  }
  std::cerr << "toon: expected " << expected << " from toond, got '" << type << "'\n";
  return false;
}

// Written as it came, whatever the file is called (the caller names it),
// and said so on stderr.
int write_answer(OutputFile& file, const std::string& name, const httplib::Response& res, const RenderAnswer& answer) {
  if (std::string problem = file.commit(res.body); !problem.empty()) {
    std::cerr << "toon: " << problem << "\n";
    return 1;
  }
  const std::string type = res.get_header_value("Content-Type");
  const bool webp = type.rfind("image/webp", 0) == 0;
  std::cerr << "toon: wrote " << (name == "-" ? "standard output" : name);
  if (!answer.what.empty())
    std::cerr << " (" << answer.what;
  else if (webp)
    std::cerr << " (animated WebP";
  else if (type.rfind("image/svg+xml", 0) == 0)
    std::cerr << " (SVG line drawing";
  else if (auto size = png_size(res.body))
    std::cerr << " (" << size->first << "x" << size->second;
  else
    std::cerr << " (not a PNG?";
  std::cerr << ", " << human_bytes(res.body.size()) << ")";
  if (std::string timing = res.get_header_value("Server-Timing"); !timing.empty()) {
    std::cerr << "; server timing: " << timing;
  }
  std::cerr << "\n";
  if (webp && name.ends_with(".png")) {
    std::cerr << "toon: note: " << name << " holds a WebP (sheet.animate), not a PNG; name it .webp\n";
  }
  return 0;
}

int render(const Options& options) {
  // Everything that can be checked locally is, before a byte is sent (a
  // range in frames asks for the model's clips first).
  const json params = build_render_params(options, proto::ParamSchema::render_params(),
                                          [&](const std::string& id) { return clips_of_model(options, id); });
  BundleScan scan;
  if (!options.obj_path.empty()) {
    scan = scan_obj_bundle(options.obj_path);
    print_warnings(scan.warnings);
  }
  // -o walk.aseprite, walk.tres, walk.json ask for the sheet's file; a
  // .tres gets the sheet's PNG beside it, asked for next.
  const RenderAnswer answer = render_answer_for(options.output);
  OutputFile output(options.output);
  std::optional<OutputFile> png;
  if (!answer.companion_png.empty()) png.emplace(answer.companion_png);

  Connection conn(options.server);
  httplib::Result result = post_render(conn, options, params, scan, answer.query);
  if (!result) return conn.network_failure(result);
  if (result->status != 200) return error_reply(*result);
  if (!answered_as(*result, answer)) return 1;
  if (!png) return write_answer(output, options.output, *result, answer);
  const RenderAnswer image = render_answer_for(answer.companion_png);
  httplib::Result png_result = post_render(conn, options, params, scan, "");
  if (!png_result) return conn.network_failure(png_result);
  if (png_result->status != 200) return error_reply(*png_result);
  if (!answered_as(*png_result, image)) return 1;
  if (int status = write_answer(output, options.output, *result, answer); status != 0) return status;
  return write_answer(*png, answer.companion_png, *png_result, image);
}

}  // namespace

int run_command(const Options& options) {
  try {
    switch (options.verb) {
      case Verb::health:
        return health(options);
      case Verb::upload:
        return upload(options);
      case Verb::info:
        return info(options);
      case Verb::render:
        return render(options);
      case Verb::gallery:
        return run_gallery(options);
      case Verb::none:
        break;
    }
    std::cerr << usage_text(Verb::none);
    return 2;
  } catch (const UsageError& e) {
    std::cerr << "toon: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "toon: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace toond::cli
