#include "svg_writer.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <string_view>

#include "screen/font.h"
#include "png_writer.h"
#include "robot_image.h"

namespace rb::render {

namespace {

constexpr int kScreenW = Canvas::kWidth;
constexpr int kScreenH = Canvas::kHeight;
/// The canvas does not draw lines with a coordinate beyond this (see Canvas::line).
constexpr int kFarCoordinate = 100000;
/// Appends strings to the document. Appending piece by piece (instead of chains of operator+)
/// avoids temporaries, and a false -Wrestrict of GCC 12 on `"literal" + std::string`.
template <typename... Parts>
void put(std::string& out, const Parts&... parts) {
  (out.append(std::string_view(parts)), ...);
}

/// A coordinate or length with at most two decimals, "." as the decimal point whatever the
/// locale, and no "-0", so SVG files diff cleanly.
std::string num(double v) {
  if (!std::isfinite(v)) return "0";
  char buf[64];
  auto res = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, 2);
  // Trim trailing zeros and a bare decimal point before making the string.
  char* end = res.ptr;
  while (end > buf && end[-1] == '0') --end;
  if (end > buf && end[-1] == '.') --end;
  std::string_view s(buf, static_cast<size_t>(end - buf));
  if (s.empty() || s == "-0") return std::string(1, '0');
  return std::string(s);
}

std::string hexColour(Colour c) {
  static constexpr char kHex[] = "0123456789abcdef";
  uint32_t rgb = colourToRgb(c);
  std::string s = "#";
  for (int shift = 20; shift >= 0; shift -= 4) s += kHex[(rgb >> shift) & 0xF];
  return s;
}

/// Where the centre of a brush stroke of width w lies relative to a pixel's integer
/// coordinate: the canvas's round brush is centred on the pixel for odd widths and on its
/// top-left corner for even widths (it covers w/2 pixels before and w/2 - 1 after).
double strokeOffset(int width) { return width >= 2 && width % 2 == 0 ? 0.0 : 0.5; }

std::string pointList(const std::vector<Point>& pts, double offset) {
  std::string s;
  for (const Point& p : pts) {
    if (!s.empty()) s += ' ';
    put(s, num(p.x + offset), ",", num(p.y + offset));
  }
  return s;
}

/// The robot's trail has a point for every pixel it moved; points in the middle of a straight
/// run (collinear with their neighbours, same direction) add nothing to the polyline's shape and
/// are dropped, so a square is five points, not five hundred.
std::vector<Point> straightened(const std::vector<Point>& pts) {
  std::vector<Point> out;
  out.reserve(pts.size());
  for (const Point& p : pts) {
    if (!out.empty() && out.back() == p) continue;
    if (out.size() >= 2) {
      const Point& a = out[out.size() - 2];
      const Point& b = out.back();
      int64_t ux = b.x - a.x, uy = b.y - a.y, vx = p.x - b.x, vy = p.y - b.y;
      if (ux * vy - uy * vx == 0 && ux * vx + uy * vy > 0) {
        out.back() = p;
        continue;
      }
    }
    out.push_back(p);
  }
  return out;
}

/// Text for an XML attribute or element: escapes markup; the canvas's bytes are Latin-1, so
/// bytes above 127 become the Unicode characters they stand for; control characters, which
/// XML cannot hold, become U+FFFD.
std::string xmlText(const std::string& s) {
  std::string out;
  for (unsigned char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default:
        if (c < 0x20 || c == 0x7F) out += "&#xFFFD;";
        else if (c >= 0x80) put(out, "&#", std::to_string(c), ";");
        else out += static_cast<char>(c);
    }
  }
  return out;
}

/// Appends the SVG elements of one display-list entry.
class SvgBuilder {
 public:
  explicit SvgBuilder(std::string& out) : out_(out) {}

  void op(const DrawOp& op) {
    switch (op.kind) {
      case DrawOp::Clear: background(op.colour); break;
      case DrawOp::Line: line(op); break;
      case DrawOp::Rect: rect(op); break;
      case DrawOp::Ellipse: ellipse(op); break;
      case DrawOp::Polygon: polygon(op); break;
      case DrawOp::Pixel: pixel(op); break;
      case DrawOp::Text: text(op); break;
      case DrawOp::Trail: trail(op); break;
      case DrawOp::Raster: break;  // the caller embeds the raster instead
    }
  }

  void background(Colour c) {
    put(out_, "<rect x=\"0\" y=\"0\" width=\"", num(kScreenW), "\" height=\"", num(kScreenH),
        "\" fill=\"", hexColour(c), "\"/>\n");
  }

 private:
  static constexpr const char* kRound = " stroke-linecap=\"round\" stroke-linejoin=\"round\"";

  void stroke(Colour c, int width) {
    put(out_, " stroke=\"", hexColour(c), "\" stroke-width=\"", num(std::max(width, 1)), "\"");
  }
  void fill(std::optional<Colour> c) { put(out_, " fill=\"", c ? hexColour(*c) : std::string("none"), "\""); }
  void box(const char* element, double x, double y, double w, double h) {
    put(out_, "<", element, " x=\"", num(x), "\" y=\"", num(y), "\" width=\"", num(w), "\" height=\"", num(h), "\"");
  }

  void line(const DrawOp& op) {
    if (op.points.size() < 2) return;
    const Point a = op.points[0], b = op.points[1];
    if (std::max({std::abs(a.x), std::abs(a.y), std::abs(b.x), std::abs(b.y)}) > kFarCoordinate) return;
    double o = strokeOffset(op.width);
    put(out_, "<line x1=\"", num(a.x + o), "\" y1=\"", num(a.y + o), "\" x2=\"", num(b.x + o), "\" y2=\"",
        num(b.y + o), "\"");
    stroke(op.colour, op.width);
    put(out_, " stroke-linecap=\"round\"/>\n");
  }

  void rect(const DrawOp& op) {
    if (op.points.size() < 2) return;
    const Point a = op.points[0], b = op.points[1];
    const double x = a.x, y = a.y, w = b.x - a.x + 1, h = b.y - a.y + 1;
    const bool outline = op.width > 0;
    if (outline && (2 * op.width >= w || 2 * op.width >= h)) {
      // The outline grows inward until it fills the whole box.
      box("rect", x, y, w, h);
      fill(op.colour);
    } else if (outline) {
      // A stroke is centred on the path: inset the path by half the width so the stroke lies
      // inside the box like the canvas's outline.
      double half = op.width / 2.0;
      box("rect", x + half, y + half, w - op.width, h - op.width);
      fill(op.fill);
      stroke(op.colour, op.width);
    } else if (op.fill) {
      box("rect", x, y, w, h);
      fill(op.fill);
    } else {
      return;
    }
    put(out_, "/>\n");
  }

  void ellipse(const DrawOp& op) {
    if (op.points.size() < 2) return;
    const Point a = op.points[0], b = op.points[1];
    // The canvas fills pixels whose centres lie in the ellipse grown by half a pixel.
    const double cx = (a.x + b.x) / 2.0 + 0.5, cy = (a.y + b.y) / 2.0 + 0.5;
    const double rx = (b.x - a.x) / 2.0 + 0.5, ry = (b.y - a.y) / 2.0 + 0.5;
    const bool outline = op.width > 0;
    auto element = [&](double erx, double ery) {
      put(out_, "<ellipse cx=\"", num(cx), "\" cy=\"", num(cy), "\" rx=\"", num(erx), "\" ry=\"", num(ery), "\"");
    };
    if (outline && (rx - op.width <= 0 || ry - op.width <= 0)) {
      // The ring is as wide as the ellipse: no inside is left.
      element(rx, ry);
      fill(op.colour);
    } else if (outline) {
      double half = op.width / 2.0;
      element(rx - half, ry - half);
      fill(op.fill);
      stroke(op.colour, op.width);
    } else if (op.fill) {
      element(rx, ry);
      fill(op.fill);
    } else {
      return;
    }
    put(out_, "/>\n");
  }

  void polygon(const DrawOp& op) {
    if (op.points.empty()) return;
    // The fill samples pixel centres while the outline is brush strokes, which may be centred
    // differently: two elements keep both exact.
    if (op.fill && op.points.size() >= 3) {
      put(out_, "<polygon points=\"", pointList(op.points, 0.5), "\"");
      fill(op.fill);
      put(out_, " fill-rule=\"evenodd\"/>\n");
    }
    if (op.width > 0) {
      put(out_, "<polygon points=\"", pointList(op.points, strokeOffset(op.width)), "\" fill=\"none\"");
      stroke(op.colour, op.width);
      put(out_, kRound, "/>\n");
    }
  }

  void pixel(const DrawOp& op) {
    if (op.points.empty()) return;
    const Point p = op.points[0];
    if (!Canvas::inside(p.x, p.y)) return;
    box("rect", p.x, p.y, 1, 1);
    fill(op.colour);
    put(out_, "/>\n");
  }

  void text(const DrawOp& op) {
    if (op.points.size() < 2 || op.text.empty()) return;
    // The canvas measured the text's cells with the embedded font: the box, the baseline and
    // the width are exact; the glyphs are the viewer's (Courier New, Liberation Mono, ...).
    const Point p = op.points[0], q = op.points[1];
    const TextStyle& style = op.style;
    const double length = q.x - p.x, height = q.y - p.y;
    if (style.background) {
      box("rect", p.x, p.y, length, height);
      fill(style.background);
      put(out_, "/>\n");
    }
    put(out_, "<text x=\"", num(p.x), "\" y=\"", num(p.y + op.ascent), "\" font-family=\"",
        cssFontFamily(style.font.face), "\" font-size=\"", num(style.font.pixelSize), "\" textLength=\"",
        num(length), "\" lengthAdjust=\"spacingAndGlyphs\" xml:space=\"preserve\"");
    fill(op.colour);
    if (style.font.bold) put(out_, " font-weight=\"bold\"");
    if (style.font.italic) put(out_, " font-style=\"italic\"");
    if (style.underline || style.strikeout)
      put(out_, " text-decoration=\"", style.underline ? "underline" : "",
          style.underline && style.strikeout ? " " : "", style.strikeout ? "line-through" : "", "\"");
    put(out_, ">", xmlText(op.text), "</text>\n");
  }

  void trail(const DrawOp& op) {
    // A trail of one point drew nothing: the pen went down but the robot did not move.
    if (op.points.size() < 2) return;
    put(out_, "<polyline points=\"", pointList(straightened(op.points), strokeOffset(op.width)),
        "\" fill=\"none\"");
    stroke(op.colour, op.width);
    put(out_, kRound, "/>\n");
  }

  std::string& out_;
};

void robotElements(std::string& out, const RobotView& robot) {
  const RobotImage shape(robot);
  if (shape.empty()) return;
  // Pixel (x, y) is the unit square from (x, y): the robot's centre pixel's centre is x + 0.5.
  const double cx = shape.centreX() + 0.5, cy = shape.centreY() + 0.5;
  // The stroke lies inside the rim: a circle through the middle of the ring, and the heading
  // line (butt ends) from the centre to that circle, where it meets the ring.
  // A robot smaller than the stroke is a disc.
  const double stroke = std::min(kRobotStroke, shape.radius());
  const double mid = shape.radius() - stroke / 2;
  const std::string colour = hexColour(robot.colour);
  const std::string width = num(stroke);
  put(out, "<!-- the robot: its outline and a line toward its heading -->\n");
  put(out, "<circle cx=\"", num(cx), "\" cy=\"", num(cy), "\" r=\"", num(mid),
      "\" fill=\"none\" stroke=\"", colour, "\" stroke-width=\"", width, "\"/>\n");
  put(out, "<line x1=\"", num(cx), "\" y1=\"", num(cy), "\" x2=\"", num(cx + shape.headingX() * mid),
      "\" y2=\"", num(cy + shape.headingY() * mid), "\" stroke=\"", colour, "\" stroke-width=\"", width,
      "\"/>\n");
}

}  // namespace

bool needsRaster(const std::vector<DrawOp>& ops) {
  return std::any_of(ops.begin(), ops.end(), [](const DrawOp& op) { return op.kind == DrawOp::Raster; });
}

std::string base64Encode(const std::vector<uint8_t>& bytes) {
  static constexpr char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  size_t i = 0;
  for (; i + 3 <= bytes.size(); i += 3) {
    uint32_t v = static_cast<uint32_t>(bytes[i]) << 16 | static_cast<uint32_t>(bytes[i + 1]) << 8 | bytes[i + 2];
    for (int shift = 18; shift >= 0; shift -= 6) out += kAlphabet[(v >> shift) & 0x3F];
  }
  size_t rest = bytes.size() - i;
  if (rest > 0) {
    uint32_t v = static_cast<uint32_t>(bytes[i]) << 16;
    if (rest == 2) v |= static_cast<uint32_t>(bytes[i + 1]) << 8;
    out += kAlphabet[(v >> 18) & 0x3F];
    out += kAlphabet[(v >> 12) & 0x3F];
    out += rest == 2 ? kAlphabet[(v >> 6) & 0x3F] : '=';
    out += '=';
  }
  return out;
}

std::string renderSvg(const Canvas& canvas, const RobotView& robot, int scale,
                      const Pixels* shown, const RasterHref& href) {
  scale = std::clamp(scale, 1, kMaxScale);
  std::string out;
  put(out, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n",
      "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" "
      "version=\"1.1\" width=\"", std::to_string(kScreenW * scale), "\" height=\"",
      std::to_string(kScreenH * scale), "\" viewBox=\"0 0 ", std::to_string(kScreenW), " ",
      std::to_string(kScreenH), "\">\n");
  const std::vector<DrawOp>& ops = canvas.displayList();
  SvgBuilder builder(out);
  if (shown || needsRaster(ops)) {
    if (shown)
      out += "<!-- flip is on: this picture is the screen as it was at the last flip, as an "
             "embedded PNG. -->\n";
    else
      out += "<!-- The screen was changed in a way that has no vector form (flood fill, scrolling "
             "text, restoreScr, or more drawing than the display list keeps): this picture is the "
             "screen's pixels as an embedded PNG. -->\n";
    put(out, "<image x=\"0\" y=\"0\" width=\"", std::to_string(kScreenW), "\" height=\"",
        std::to_string(kScreenH),
        "\" image-rendering=\"optimizeSpeed\" style=\"image-rendering:pixelated\" "
        "preserveAspectRatio=\"none\" xlink:href=\"", href(shown ? *shown : canvas.pixels()), "\"/>\n");
  } else {
    // The list starts at the last clearScr; before any, the screen is the initial background.
    if (ops.empty() || ops.front().kind != DrawOp::Clear) builder.background(canvas.background());
    for (const DrawOp& op : ops) builder.op(op);
  }
  robotElements(out, robot);
  out += "</svg>\n";
  return out;
}

}  // namespace rb::render
