#pragma once
// The vertex attribute locations of shaders/attributes.glsl, which every
// vertex stage includes; GpuModel binds its buffer's fields to these.
namespace toond::render {

enum VertexAttribute : unsigned {
  kPositionAttribute = 0,
  kNormalAttribute = 1,
  kTexcoordAttribute = 2,
  kOutlineOffsetAttribute = 3,
  kTangentAttribute = 4,
  kColorAttribute = 5,
};

}  // namespace toond::render
