#include "curses_palette.h"

#include <algorithm>

namespace rb::render {

namespace {

int red(uint32_t rgb) { return static_cast<int>((rgb >> 16) & 0xFF); }
int green(uint32_t rgb) { return static_cast<int>((rgb >> 8) & 0xFF); }
int blue(uint32_t rgb) { return static_cast<int>(rgb & 0xFF); }

/// Squared distance with the usual weights for how strongly the eye tells the channels apart.
int distance(int r1, int g1, int b1, int r2, int g2, int b2) {
  int dr = r1 - r2, dg = g1 - g2, db = b1 - b2;
  return 3 * dr * dr + 4 * dg * dg + 2 * db * db;
}

constexpr int kCubeLevels[6] = {0, 95, 135, 175, 215, 255};

int cubeStep(int v) {
  int best = 0;
  for (int i = 1; i < 6; ++i)
    if (std::abs(kCubeLevels[i] - v) < std::abs(kCubeLevels[best] - v)) best = i;
  return best;
}

// The ANSI colours as terminals commonly show them (the VGA values).
constexpr uint32_t kAnsi[16] = {0x000000, 0xAA0000, 0x00AA00, 0xAA5500, 0x0000AA, 0xAA00AA,
                                0x00AAAA, 0xAAAAAA, 0x555555, 0xFF5555, 0x55FF55, 0xFFFF55,
                                0x5555FF, 0xFF55FF, 0x55FFFF, 0xFFFFFF};

}  // namespace

int nearestXterm256(uint32_t rgb) {
  int r = red(rgb), g = green(rgb), b = blue(rgb);
  int qr = cubeStep(r), qg = cubeStep(g), qb = cubeStep(b);
  int cube = 16 + 36 * qr + 6 * qg + qb;
  int cubeDist = distance(r, g, b, kCubeLevels[qr], kCubeLevels[qg], kCubeLevels[qb]);
  // The grey ramp: 24 steps from 8 to 238.
  int avg = (r + g + b) / 3;
  int gi = std::clamp((avg - 3) / 10, 0, 23);
  int level = 8 + 10 * gi;
  int greyDist = distance(r, g, b, level, level, level);
  return greyDist < cubeDist ? 232 + gi : cube;
}

int nearestAnsi(uint32_t rgb, int count) {
  int r = red(rgb), g = green(rgb), b = blue(rgb);
  int best = 0, bestDist = 1 << 30;
  // Always among all sixteen: a light colour is nearest its bright ANSI twin, which an
  // 8-colour terminal shows as the base colour (yellow, not the grey "white").
  for (int i = 0; i < 16; ++i) {
    int d = distance(r, g, b, red(kAnsi[i]), green(kAnsi[i]), blue(kAnsi[i]));
    if (d < bestDist) {
      bestDist = d;
      best = i;
    }
  }
  return count >= 16 ? best : best % 8;
}

}  // namespace rb::render
