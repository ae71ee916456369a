#include "support/webp_frames.h"

#include <cstring>
#include <memory>
#include <stdexcept>

#include <webp/demux.h>

namespace toond::test {

WebpFrames decode_webp_frames(const std::string& bytes) {
  WebPAnimDecoderOptions options;
  if (!WebPAnimDecoderOptionsInit(&options)) throw std::runtime_error("libwebp: demux version mismatch");
  // Straight (not premultiplied) RGBA, the byte order of image::Image.
  options.color_mode = MODE_RGBA;
  options.use_threads = 0;
  WebPData data{reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()};
  std::unique_ptr<WebPAnimDecoder, decltype(&WebPAnimDecoderDelete)> decoder(WebPAnimDecoderNew(&data, &options),
                                                                             &WebPAnimDecoderDelete);
  if (!decoder) throw std::runtime_error("libwebp cannot read the animation");
  WebPAnimInfo info;
  if (!WebPAnimDecoderGetInfo(decoder.get(), &info)) throw std::runtime_error("libwebp: no animation info");
  WebpFrames out;
  out.loop_count = static_cast<int>(info.loop_count);
  while (WebPAnimDecoderHasMoreFrames(decoder.get())) {
    std::uint8_t* canvas = nullptr;
    int timestamp = 0;
    if (!WebPAnimDecoderGetNext(decoder.get(), &canvas, &timestamp)) {
      throw std::runtime_error("libwebp cannot decode frame " + std::to_string(out.frames.size()));
    }
    image::Image frame;
    frame.width = static_cast<int>(info.canvas_width);
    frame.height = static_cast<int>(info.canvas_height);
    frame.rgba.assign(canvas, canvas + static_cast<std::size_t>(frame.width) * frame.height * 4);
    out.frames.push_back(std::move(frame));
    out.end_ms.push_back(timestamp);
  }
  return out;
}

}  // namespace toond::test
