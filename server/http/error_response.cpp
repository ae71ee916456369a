#include "http/error_response.h"

#include <filesystem>
#include <iostream>

#include <nlohmann/json.hpp>

#include "http/import_limit_flag.h"
#include "limit_error.h"
#include "pipeline/render_failure.h"
#include "request_error.h"
#include "scene/reading/import_error.h"
#include "scene/reading/import_limits.h"
#include "scene/store/store_error.h"

namespace toond::http {

void write_error(httplib::Response& res, int status, const std::string& code, const std::string& message,
                 const std::string& path) {
  res.status = status;
  nlohmann::json body = {{"error", {{"code", code}, {"message", message}, {"path", path}}}};
  res.set_content(dump_for_client(body), "application/json");
}

void write_limit_error(httplib::Response& res, int status, const std::string& code, const std::string& limit,
                       const std::string& message, const std::string& path) {
  res.status = status;
  nlohmann::json body = {{"error", {{"code", code}, {"message", message}, {"path", path}, {"limit", limit}}}};
  res.set_content(dump_for_client(body), "application/json");
}

std::string dump_for_client(const nlohmann::json& body) {
  // Messages quote what the client sent; bytes that are not UTF-8 become
  // U+FFFD instead of making the answer itself fail.
  return body.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

namespace {

// The store's refusals and failures. Their messages name no server path;
// the detail that does goes to the daemon's log.
void write_store_error(httplib::Response& res, const scene::StoreError& e) {
  using Kind = scene::StoreError::Kind;
  switch (e.kind()) {
    case Kind::LargerThanStore:
      write_limit_error(res, 413, "limit_exceeded", "--max-store-mb",
                        std::string(e.what()) + " (--max-store-mb); nothing was stored");
      return;
    case Kind::FullOfModelsInUse:
      // Renders let their models go within --render-timeout.
      res.set_header("Retry-After", "5");
      write_error(res, 507, "storage_full",
                  std::string(e.what()) + " (--max-store-mb); nothing was stored, retry shortly");
      return;
    case Kind::VolumeFull:
      std::cerr << "toond: model store: " << e.detail() << "\n";
      write_error(res, 507, "storage_full",
                  std::string(e.what()) +
                      ": nothing was stored; stored models still render (the operator frees or grows the volume, "
                      "or bounds the store below its size with --max-store-mb)");
      return;
    case Kind::Busy:
      // The pass that holds the lock is a few file operations long; one
      // that outlasts StoreOptions::lock_wait is a hung replica's.
      std::cerr << "toond: model store: " << e.what() << "\n";
      res.set_header("Retry-After", "5");
      write_error(res, 503, "busy", std::string(e.what()) + "; nothing was stored, retry shortly");
      return;
    case Kind::Failed:
      break;
  }
  std::cerr << "toond: model store: " << (e.detail().empty() ? e.what() : e.detail()) << "\n";
  write_error(res, 500, "internal", e.what());
}

// A shader (edited under --shader-dir) that does not compile: "toon.frag:12:
// syntax error, …" up front, the driver's whole log beside it, and the
// line (of the file: with_defines keeps numbering) when known.
void write_shader_error(httplib::Response& res, const pipeline::RenderFailure& e) {
  const pipeline::RenderFailure::Shader& shader = e.shader();
  std::string message = shader.file;
  if (shader.line) message += ":" + std::to_string(*shader.line);
  message += ": " + (shader.first_error.empty() ? std::string("does not compile") : shader.first_error);
  nlohmann::json error = {{"code", "shader_error"}, {"message", message}, {"path", shader.file}, {"log", shader.log}};
  if (shader.line) error["line"] = *shader.line;
  res.status = 500;
  res.set_content(dump_for_client({{"error", error}}), "application/json");
}

// The render threads' and the GPU's failures, as the pipeline's entry says
// them.
void write_render_failure(httplib::Response& res, const pipeline::RenderFailure& e) {
  using Kind = pipeline::RenderFailure::Kind;
  switch (e.kind()) {
    case Kind::DeadlineExceeded:
      res.set_header("Retry-After", "5");
      write_error(res, 503, "deadline_exceeded",
                  "the render's deadline (--render-timeout) passed while it waited in the queue");
      return;
    case Kind::Aborted:
      res.set_header("Retry-After", "5");
      write_error(res, 503, "render_aborted",
                  std::string(e.what()) +
                      ": it ran past --render-timeout; a smaller size, fewer samples or fewer outline passes draw "
                      "sooner (the answer's X-Toond-Cost header and --max-render-cost price a request)");
      return;
    case Kind::QueueFull:
      res.set_header("Retry-After", "1");
      write_error(res, 503, "busy", std::string(e.what()) + "; retry shortly");
      return;
    case Kind::ShaderError:
      std::cerr << "toond: " << e.what() << "\n";
      write_shader_error(res, e);
      return;
    case Kind::GpuReset:
      std::cerr << "toond: " << e.what() << "\n";
      res.set_header("Retry-After", "1");
      write_error(res, 503, "gpu_reset", e.what());
      return;
    case Kind::GpuError:
      break;
  }
  std::cerr << "toond: GPU error: " << e.what() << "\n";
  write_error(res, 500, "gpu_error", e.what());
}

}  // namespace

void write_exception(httplib::Response& res, std::exception_ptr ep) {
  try {
    std::rethrow_exception(ep);
  } catch (const LimitError& e) {
    write_limit_error(res, e.status(), e.code(), e.limit(), e.what(), e.path());
  } catch (const scene::ImportLimitError& e) {
    const std::string_view flag = import_limit_flag(e.limit());
    write_limit_error(res, 422, "limit_exceeded", std::string(flag), e.message_naming(flag), e.file());
  } catch (const RequestError& e) {
    if (e.status() == 503) res.set_header("Retry-After", "5");
    write_error(res, e.status(), e.code(), e.what(), e.path());
  } catch (const scene::ImportError& e) {
    write_error(res, 422, "bad_bundle", e.what(), e.file());
  } catch (const scene::StoreError& e) {
    write_store_error(res, e);
  } catch (const pipeline::RenderFailure& e) {
    write_render_failure(res, e);
  } catch (const std::filesystem::filesystem_error& e) {
    // Its text names the files it was about: the daemon's own paths.
    std::cerr << "toond: internal error: " << e.what() << "\n";
    write_error(res, 500, "internal", "a file operation failed (" + e.code().message() + ")");
  } catch (const std::exception& e) {
    std::cerr << "toond: internal error: " << e.what() << "\n";
    write_error(res, 500, "internal", e.what());
  } catch (...) {
    std::cerr << "toond: internal error of unknown type\n";
    write_error(res, 500, "internal", "unknown error");
  }
}

}  // namespace toond::http
