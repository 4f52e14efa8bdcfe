#include "sixel_image.h"

#include <sixel.h>

#include <cstdint>
#include <vector>

namespace rb::render {

namespace {

int append(char* data, int size, void* priv) {
  static_cast<std::string*>(priv)->append(data, static_cast<size_t>(size));
  return 0;
}

}  // namespace

std::string sixelImage(const RgbImage& image, int width, int height) {
  if (width <= 0 || height <= 0 || image.width <= 0 || image.height <= 0) return "";
  std::vector<unsigned char> rgb(static_cast<size_t>(width) * static_cast<size_t>(height) * 3);
  for (int y = 0; y < height; ++y) {
    int sy = static_cast<int>(static_cast<int64_t>(y) * image.height / height);
    for (int x = 0; x < width; ++x) {
      int sx = static_cast<int>(static_cast<int64_t>(x) * image.width / width);
      uint32_t c = image.pixel(sx, sy);
      unsigned char* p = rgb.data() + (static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)) * 3;
      p[0] = static_cast<unsigned char>(c >> 16);
      p[1] = static_cast<unsigned char>(c >> 8);
      p[2] = static_cast<unsigned char>(c);
    }
  }
  std::string out;
  sixel_output_t* output = nullptr;
  if (SIXEL_FAILED(sixel_output_new(&output, append, &out, nullptr))) return "";
  sixel_dither_t* dither = nullptr;
  bool ok = SIXEL_SUCCEEDED(sixel_dither_new(&dither, 256, nullptr)) &&
            SIXEL_SUCCEEDED(sixel_dither_initialize(dither, rgb.data(), width, height,
                                                    SIXEL_PIXELFORMAT_RGB888, SIXEL_LARGE_AUTO,
                                                    SIXEL_REP_AUTO, SIXEL_QUALITY_AUTO));
  if (ok) {
    // RobotBASIC's screens have few colours: no dithering, so lines stay crisp.
    sixel_dither_set_diffusion_type(dither, SIXEL_DIFFUSE_NONE);
    ok = SIXEL_SUCCEEDED(sixel_encode(rgb.data(), width, height, 3, dither, output));
  }
  if (dither) sixel_dither_unref(dither);
  sixel_output_unref(output);
  return ok ? out : std::string();
}

}  // namespace rb::render
