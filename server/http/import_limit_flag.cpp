#include "http/import_limit_flag.h"

namespace toond::http {

std::string_view import_limit_flag(scene::ImportLimit limit) {
  switch (limit) {
    case scene::ImportLimit::Vertices:
      return "--max-vertices";
    case scene::ImportLimit::Triangles:
      return "--max-triangles";
    case scene::ImportLimit::TexturePixels:
      return "--max-texture-pixels";
    case scene::ImportLimit::Seconds:
      return "--max-import-seconds";
  }
  return "";
}

}  // namespace toond::http
