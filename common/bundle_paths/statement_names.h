#pragma once
// The file names OBJ and MTL statements give, read one way for `toon` (which
// sends the files) and the daemon (which looks them up): exporters write
// unescaped spaces, options after the name, quotes and absolute paths, and
// readers disagree about all of them.
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace toond::bundle_paths {

// The files a `mtllib` line (the text after the keyword) names: each word,
// `\ ` escaping a blank (tinyobjloader and Blender write `my\ file.mtl`) —
// unless the line holds several words and `exists` says the whole line, with
// its blanks, names a file: `mtllib my model.mtl` with an unescaped blank.
std::vector<std::string> mtllib_names(std::string_view rest_of_line,
                                      const std::function<bool(const std::string&)>& exists);

struct TextureName {
  std::string name;
  // The last resort: the fullest reading's file name without its folders,
  // since exporters often write the artist's absolute path while the file
  // itself travels beside the MTL.
  bool file_name_only = false;
};

// The names a texture statement (the text after map_Kd, bump, ...) may
// mean, to be tried in order. Options (-bm 2, -o 0.1 0.2, -imfchan r, ...)
// are dropped wherever they stand. When several words remain, the whole run
// of them with its blanks comes first, then the last word alone; a reading
// in matching quotes is meant whole. Empty when the statement names nothing.
std::vector<TextureName> texture_names(std::string_view rest_of_line);

// The names a texture path written inside a model file (FBX, COLLADA, 3DS:
// no options, no quoting) may mean: the path as written, then its file name
// alone when it has folders. Empty when `path` is.
std::vector<TextureName> path_names(std::string_view path);

}  // namespace toond::bundle_paths
