#pragma once
// Reading a glTF model's accessors, with every offset, stride and count
// checked against the bytes that are really there: the file is untrusted
// and tinygltf leaves these checks to its user.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
struct Accessor;
}  // namespace tinygltf

namespace toond::scene {

class GltfAccessorReader {
 public:
  // The bytes of buffer view `view`, when something other than the plain
  // buffer slice holds them (a decompressed view); an empty function or
  // nullopt means the buffer slice.
  using ViewOverride = std::function<std::optional<std::span<const std::uint8_t>>(int view)>;

  // `file` is the bundle path named in errors.
  GltfAccessorReader(const tinygltf::Model& model, std::string file, ViewOverride view_override = {});

  // Accessor `index`, or an ImportError naming `role` when there is none.
  const tinygltf::Accessor& accessor(int index, const std::string& role) const;

  // The accessor's elements as doubles, `components` per element (the
  // accessor must have exactly that many, or one of `also_allowed`; missing
  // ones are filled from `fill`). Integer components are normalised when the
  // accessor says so, taken as they are otherwise. Sparse substitutions are
  // applied. Throws ImportError on any reference or range that does not fit.
  std::vector<double> read(int index, const std::string& role, int components, std::vector<int> also_allowed = {},
                           double fill = 1.0) const;

  // An index accessor (unsigned byte, short or int scalars).
  std::vector<std::uint32_t> read_indices(int index, const std::string& role) const;

  // The bytes of buffer view `view` (an image's, say), checked against its
  // buffer; `role` names the reader in errors.
  std::span<const std::uint8_t> view(int view, const std::string& role) const;

 private:
  struct Layout;
  Layout layout_of(int index, const std::string& role, int view, std::size_t offset, std::size_t count,
                   std::size_t element_size, std::size_t stride) const;

  const tinygltf::Model& model_;
  std::string file_;
  ViewOverride view_override_;
};

// Components per element of an accessor type (SCALAR 1 ... MAT4 16), 0 for
// an unknown type.
int gltf_component_count(int type);
// Bytes per component of a component type, 0 for an unknown one.
std::size_t gltf_component_size(int component_type);

}  // namespace toond::scene
