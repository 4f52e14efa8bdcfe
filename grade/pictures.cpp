#include "pictures.h"

#include <algorithm>
#include <cmath>

namespace rb::grade {

namespace {

constexpr int kWidth = 800, kHeight = 600;

/// Paints every pixel whose centre lies within `halfWidth` of the segment a-b.
void stroke(render::RgbImage& img, P2 a, P2 b, double halfWidth, uint32_t colour) {
  int x0 = std::max(0, static_cast<int>(std::floor(std::min(a.x, b.x) - halfWidth)));
  int x1 = std::min(img.width - 1, static_cast<int>(std::ceil(std::max(a.x, b.x) + halfWidth)));
  int y0 = std::max(0, static_cast<int>(std::floor(std::min(a.y, b.y) - halfWidth)));
  int y1 = std::min(img.height - 1, static_cast<int>(std::ceil(std::max(a.y, b.y) + halfWidth)));
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x)
      if (distanceToSegment({static_cast<double>(x), static_cast<double>(y)}, a, b) <= halfWidth)
        img.set(x, y, colour);
}

void strokeLines(render::RgbImage& img, const Polylines& lines, double halfWidth, uint32_t colour) {
  for (const Polyline& l : lines) {
    if (l.size() == 1) stroke(img, l[0], l[0], halfWidth, colour);
    for (size_t i = 1; i < l.size(); ++i) stroke(img, l[i - 1], l[i], halfWidth, colour);
  }
}

void ring(render::RgbImage& img, P2 c, double r, uint32_t colour) {
  int x0 = std::max(0, static_cast<int>(c.x - r - 2)), x1 = std::min(img.width - 1, static_cast<int>(c.x + r + 2));
  int y0 = std::max(0, static_cast<int>(c.y - r - 2)), y1 = std::min(img.height - 1, static_cast<int>(c.y + r + 2));
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x)
      if (std::abs(std::hypot(x - c.x, y - c.y) - r) <= 0.75) img.set(x, y, colour);
}

uint32_t fade(uint32_t rgb) {
  auto lighten = [](uint32_t c) { return 255 - (255 - c) / 4; };
  uint32_t r = lighten(rgb >> 16 & 0xFF), g = lighten(rgb >> 8 & 0xFF), b = lighten(rgb & 0xFF);
  return r << 16 | g << 8 | b;
}

}  // namespace

render::RgbImage feedbackPicture(const PictureInput& in) {
  render::RgbImage img;
  img.width = kWidth;
  img.height = kHeight;
  img.rgb.assign(static_cast<size_t>(kWidth) * kHeight * 3, 0xFF);
  if (in.background && in.background->width == kWidth && in.background->height == kHeight)
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x) img.set(x, y, fade(in.background->pixel(x, y)));
  strokeLines(img, in.reference, 3.5, kReferenceColour);
  if (in.referenceEnd) ring(img, *in.referenceEnd, in.robotRadius, kReferenceColour);
  strokeLines(img, in.student, 1.0, kStudentColour);
  if (in.studentEnd) ring(img, *in.studentEnd, in.robotRadius, kStudentColour);
  return img;
}

}  // namespace rb::grade
