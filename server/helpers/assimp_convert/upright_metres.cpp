#include "helpers/assimp_convert/upright_metres.h"

#include <cmath>
#include <cstdio>
#include <optional>

namespace toond::assimp_convert {
namespace {

template <typename T>
std::optional<T> metadata(const aiScene& scene, const char* key) {
  T value{};
  if (scene.mMetaData && scene.mMetaData->Get(key, value)) return value;
  return std::nullopt;
}

// FBX stores the unit as a float or a double depending on the writer.
std::optional<double> unit_scale_factor(const aiScene& scene) {
  if (const auto d = metadata<double>(scene, "UnitScaleFactor")) return d;
  if (const auto f = metadata<float>(scene, "UnitScaleFactor")) return *f;
  return std::nullopt;
}

struct Axis {
  int index = 0;  // 0 x, 1 y, 2 z of the file
  int sign = 1;
};

std::optional<Axis> axis(const aiScene& scene, const char* name) {
  const auto index = metadata<int32_t>(scene, name);
  const auto sign = metadata<int32_t>(scene, (std::string(name) + "Sign").c_str());
  if (!index || *index < 0 || *index > 2) return std::nullopt;
  return Axis{*index, sign && *sign < 0 ? -1 : 1};
}

const char* axis_name(Axis a) {
  static const char* names[2][3] = {{"-X", "-Y", "-Z"}, {"+X", "+Y", "+Z"}};
  return names[a.sign > 0 ? 1 : 0][a.index];
}

// The matrix taking the file's right, up and front axes to toond's +X, +Y
// and +Z; nullopt when the file names no axes, or names one twice.
std::optional<aiMatrix4x4> axis_turn(const aiScene& scene, std::string& said) {
  const auto right = axis(scene, "CoordAxis");
  const auto up = axis(scene, "UpAxis");
  const auto front = axis(scene, "FrontAxis");
  if (!right || !up || !front) return std::nullopt;
  if (right->index == up->index || up->index == front->index || right->index == front->index) return std::nullopt;
  aiMatrix4x4 turn;  // identity
  const Axis rows[3] = {*right, *up, *front};
  for (int row = 0; row < 3; ++row) {
    for (int column = 0; column < 3; ++column)
      turn[row][column] = column == rows[row].index ? float(rows[row].sign) : 0.0f;
  }
  if (turn.IsIdentity()) return std::nullopt;
  said = std::string("turned from ") + axis_name(*up) + " up to +Y up";
  return turn;
}

}  // namespace

std::vector<std::string> make_upright_metres(aiScene& scene) {
  std::vector<std::string> said;
  aiMatrix4x4 change;  // identity
  std::string turn_said;
  if (const auto turn = axis_turn(scene, turn_said)) {
    change = *turn;
    said.push_back(turn_said);
  }
  if (const auto centimetres = unit_scale_factor(scene);
      centimetres && std::isfinite(*centimetres) && *centimetres > 0.0 && *centimetres != 100.0) {
    const float metres = static_cast<float>(*centimetres / 100.0);
    aiMatrix4x4 scale;
    aiMatrix4x4::Scaling(aiVector3D(metres), scale);
    change = scale * change;
    char unit[32];
    std::snprintf(unit, sizeof unit, "%g", *centimetres);
    said.push_back(std::string("scaled to metres (the file's unit is ") + unit + " cm)");
  }
  if (!said.empty()) scene.mRootNode->mTransformation = change * scene.mRootNode->mTransformation;
  return said;
}

}  // namespace toond::assimp_convert
