#pragma once
// Move-only owners of GL object names. Nothing outside this file calls
// glCreate*/glGen*/glDelete*: every GL object toond makes is one of these,
// so an exception anywhere in a pass cannot leak GPU memory.
#include <utility>

#include "gpu/gl.h"

namespace toond::gpu {

template <class Traits>
class GlObject {
 public:
  GlObject() = default;  // the empty state: owns nothing
  template <class... Args>
  static GlObject create(Args... args) {
    return GlObject(Traits::create(args...));
  }
  ~GlObject() { reset(); }
  GlObject(const GlObject&) = delete;
  GlObject& operator=(const GlObject&) = delete;
  GlObject(GlObject&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
  GlObject& operator=(GlObject&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = std::exchange(other.id_, 0);
    }
    return *this;
  }

  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }
  // Gives up ownership without deleting (e.g. when the context is already gone).
  GLuint release() { return std::exchange(id_, 0); }
  void reset() {
    if (id_ != 0) Traits::destroy(id_);
    id_ = 0;
  }

 private:
  explicit GlObject(GLuint id) : id_(id) {}
  GLuint id_ = 0;
};

namespace traits {
struct Buffer {
  static GLuint create() {
    GLuint id = 0;
    glCreateBuffers(1, &id);
    return id;
  }
  static void destroy(GLuint id) { glDeleteBuffers(1, &id); }
};
struct VertexArray {
  static GLuint create() {
    GLuint id = 0;
    glCreateVertexArrays(1, &id);
    return id;
  }
  static void destroy(GLuint id) { glDeleteVertexArrays(1, &id); }
};
struct Texture {
  static GLuint create(GLenum target) {
    GLuint id = 0;
    glCreateTextures(target, 1, &id);
    return id;
  }
  static void destroy(GLuint id) { glDeleteTextures(1, &id); }
};
struct Renderbuffer {
  static GLuint create() {
    GLuint id = 0;
    glCreateRenderbuffers(1, &id);
    return id;
  }
  static void destroy(GLuint id) { glDeleteRenderbuffers(1, &id); }
};
struct Framebuffer {
  static GLuint create() {
    GLuint id = 0;
    glCreateFramebuffers(1, &id);
    return id;
  }
  static void destroy(GLuint id) { glDeleteFramebuffers(1, &id); }
};
struct Shader {
  static GLuint create(GLenum stage) { return glCreateShader(stage); }
  static void destroy(GLuint id) { glDeleteShader(id); }
};
struct Program {
  static GLuint create() { return glCreateProgram(); }
  static void destroy(GLuint id) { glDeleteProgram(id); }
};
struct Query {
  static GLuint create(GLenum target) {
    GLuint id = 0;
    glCreateQueries(target, 1, &id);
    return id;
  }
  static void destroy(GLuint id) { glDeleteQueries(1, &id); }
};
}  // namespace traits

using Buffer = GlObject<traits::Buffer>;
using VertexArray = GlObject<traits::VertexArray>;
using Texture = GlObject<traits::Texture>;
using Renderbuffer = GlObject<traits::Renderbuffer>;
using Framebuffer = GlObject<traits::Framebuffer>;
using Shader = GlObject<traits::Shader>;
using ProgramObject = GlObject<traits::Program>;
using Query = GlObject<traits::Query>;

// A fence after every command issued so far (glFenceSync); GLsync is a
// pointer, not a name, so it has its own owner.
class Fence {
 public:
  Fence() : sync_(glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0)) {}
  ~Fence() {
    if (sync_ != nullptr) glDeleteSync(sync_);
  }
  Fence(const Fence&) = delete;
  Fence& operator=(const Fence&) = delete;

  GLsync get() const { return sync_; }  // null when glFenceSync failed

 private:
  GLsync sync_;
};

}  // namespace toond::gpu
