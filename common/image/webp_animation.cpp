#include "image/webp_animation.h"

#include <memory>
#include <stdexcept>

#include <webp/encode.h>
#include <webp/mux.h>

namespace toond::image {
namespace {

struct AnimEncoderDelete {
  void operator()(WebPAnimEncoder* encoder) const { WebPAnimEncoderDelete(encoder); }
};
using AnimEncoder = std::unique_ptr<WebPAnimEncoder, AnimEncoderDelete>;

// A WebPPicture owns its pixel buffer once a frame is imported into it.
class Picture {
 public:
  Picture() {
    if (!WebPPictureInit(&picture_)) throw std::runtime_error("libwebp: WebPPictureInit failed (version mismatch)");
  }
  ~Picture() { WebPPictureFree(&picture_); }
  Picture(const Picture&) = delete;
  Picture& operator=(const Picture&) = delete;
  WebPPicture* get() { return &picture_; }

 private:
  WebPPicture picture_;
};

// The assembled bytes, allocated by libwebp and freed by it.
class Data {
 public:
  Data() { WebPDataInit(&data_); }
  ~Data() { WebPDataClear(&data_); }
  Data(const Data&) = delete;
  Data& operator=(const Data&) = delete;
  WebPData* get() { return &data_; }

 private:
  WebPData data_;
};

[[noreturn]] void fail(WebPAnimEncoder* encoder, const char* what) {
  const char* why = WebPAnimEncoderGetError(encoder);
  throw std::runtime_error(std::string("libwebp: ") + what + (why && *why ? std::string(": ") + why : ""));
}

}  // namespace

std::string encode_webp_animation(std::span<const Image> frames, const WebpAnimationOptions& options) {
  if (frames.empty()) throw std::invalid_argument("an animation needs at least one frame");
  if (!options.durations_ms.empty() && options.durations_ms.size() != frames.size()) {
    throw std::invalid_argument("an animation needs one duration per frame");
  }
  const int width = frames.front().width;
  const int height = frames.front().height;

  WebPAnimEncoderOptions anim_options;
  if (!WebPAnimEncoderOptionsInit(&anim_options)) throw std::runtime_error("libwebp: mux version mismatch");
  anim_options.anim_params.loop_count = options.loop_count;
  anim_options.anim_params.bgcolor = 0;  // transparent, like the sheet's empty pixels
  anim_options.allow_mixed = 0;          // never lossy
  AnimEncoder encoder(WebPAnimEncoderNew(width, height, &anim_options));
  if (!encoder) throw std::runtime_error("libwebp: cannot create the animation encoder");

  WebPConfig config;
  if (!WebPConfigInit(&config) || !WebPConfigLosslessPreset(&config, options.effort)) {
    throw std::runtime_error("libwebp: bad lossless configuration");
  }
  // Lossless alone may still rewrite the RGB of fully transparent pixels
  // to compress better; `exact` keeps them, so a decoded frame is the
  // frame given, byte for byte.
  config.exact = 1;

  int timestamp_ms = 0;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const Image& frame = frames[i];
    if (frame.width != width || frame.height != height) {
      throw std::invalid_argument("the frames of an animation must all have the same size");
    }
    Picture picture;
    picture.get()->use_argb = 1;
    picture.get()->width = width;
    picture.get()->height = height;
    if (!WebPPictureImportRGBA(picture.get(), frame.rgba.data(), width * 4)) {
      throw std::runtime_error("libwebp: cannot import a frame (out of memory)");
    }
    if (!WebPAnimEncoderAdd(encoder.get(), picture.get(), timestamp_ms, &config)) {
      fail(encoder.get(), "cannot add a frame");
    }
    timestamp_ms += options.durations_ms.empty() ? options.frame_ms : options.durations_ms[i];
  }
  // A last call without a frame gives the last frame its duration.
  if (!WebPAnimEncoderAdd(encoder.get(), nullptr, timestamp_ms, nullptr)) fail(encoder.get(), "cannot end");
  Data data;
  if (!WebPAnimEncoderAssemble(encoder.get(), data.get())) fail(encoder.get(), "cannot assemble");
  return std::string(reinterpret_cast<const char*>(data.get()->bytes), data.get()->size);
}

}  // namespace toond::image
