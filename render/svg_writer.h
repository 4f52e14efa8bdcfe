#pragma once
// The screen as SVG 1.1, made from the canvas's display list so that lines, shapes, text and the
// robot's pen trail stay vectors. When the list holds something with no vector form (a flood
// fill, scrolling text, restoreScr, or a list too long to keep), the picture is the screen's
// pixels as an embedded PNG instead. The robot goes on top either way.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "arena_view.h"
#include "screen/canvas.h"

namespace rb::render {

/// True when the display list cannot reproduce the screen (it holds a DrawOp::Raster), so the
/// SVG must embed the raster.
bool needsRaster(const std::vector<DrawOp>& ops);

/// The link an embedded raster's <image> gets for the 800 x 600 screen `pixels` (without the
/// robot). Called only when the SVG embeds them.
using RasterHref = std::function<std::string(const Pixels& pixels)>;

/// The pixels as a PNG (encodePng, with libpng) in a data: URL: what rb render embeds.
std::string pngDataHref(const Pixels& pixels);

/// The SVG document: width 800 * scale, height 600 * scale (scale clamped to 1..kMaxScale),
/// viewBox in screen pixels. Deterministic: the same canvas and robot give the same bytes.
/// Throws std::runtime_error when the embedded PNG cannot be encoded (out of memory).
/// `shown`, when given, is what is shown instead of the canvas (flip is on: the screen at the last
/// flip), embedded as pixels. `href` makes the link of embedded pixels (the browser's host
/// encodes its PNG in the page, after the run).
std::string renderSvg(const Canvas& canvas, const RobotView& robot, int scale,
                      const Pixels* shown = nullptr, const RasterHref& href = pngDataHref);

/// Standard base64 with padding (RFC 4648), for data: URLs.
std::string base64Encode(const std::vector<uint8_t>& bytes);

}  // namespace rb::render
