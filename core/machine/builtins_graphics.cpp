// Graphics built-ins: they draw on the Machine's canvas with its current colour and line width.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <functional>

#include "machine/builtins_impl.h"
#include "base/runtime_error.h"

namespace rb::builtins {

namespace {

using K = BuiltinKind;

Point point(Args& a, int i) { return {a.coordinate(i), a.coordinate(i + 1)}; }

int widthArg(Args& a, int i) {
  int64_t w = a.integer(i);
  if (w < 1 || w > 100) throw RuntimeError(a.describe(i) + " must be a line width from 1 to 100");
  return static_cast<int>(w);
}

/// Outline (default: the current colour) and optional fill of the shape commands.
std::pair<std::optional<Colour>, std::optional<Colour>> shapeColours(Machine& m, Args& a, int from) {
  std::optional<Colour> outline = a.has(from) ? a.colour(from) : m.canvas().foreground;
  std::optional<Colour> fill;
  if (a.has(from + 1)) fill = a.colour(from + 1);
  return {outline, fill};
}

Value clearScr(Machine& m, Args& a) {
  m.canvas().clear(a.has(0) ? a.colour(0) : colours::kWhite);
  return {};
}

Value setColor(Machine& m, Args& a) {
  m.canvas().foreground = a.colour(0);
  if (a.has(1)) m.canvas().textBackground = a.colour(1);
  return {};
}

Value lineWidth(Machine& m, Args& a) {
  m.canvas().lineWidth = widthArg(a, 0);
  return {};
}

Value gotoXY(Machine& m, Args& a) {
  m.canvas().pen = point(a, 0);
  return {};
}

Value lineTo(Machine& m, Args& a) {
  Canvas& c = m.canvas();
  Point to = point(a, 0);
  int w = a.has(2) ? widthArg(a, 2) : c.lineWidth;
  Colour col = a.has(3) ? a.colour(3) : c.foreground;
  c.line(c.pen, to, w, col);
  c.pen = to;
  return {};
}

Value line(Machine& m, Args& a) {
  Canvas& c = m.canvas();
  Point to = point(a, 2);
  int w = a.has(4) ? widthArg(a, 4) : c.lineWidth;
  Colour col = a.has(5) ? a.colour(5) : c.foreground;
  c.line(point(a, 0), to, w, col);
  c.pen = to;
  return {};
}

/// How a shape command gives its box: two corners, or a top-left corner and a size.
enum class Box { Corners, CornerSize };

/// rectangle, rectangleWH, circle, circleWH: the box from the first four arguments, then the
/// optional outline and fill colours.
template <Box form, bool ellipse>
Value shape(Machine& m, Args& a) {
  Point p = point(a, 0);
  Point q = form == Box::Corners ? point(a, 2) : Point{p.x + a.coordinate(2), p.y + a.coordinate(3)};
  auto [outline, fill] = shapeColours(m, a, 4);
  Canvas& c = m.canvas();
  if (ellipse) c.ellipse(p, q, c.lineWidth, outline, fill);
  else c.rectangle(p, q, c.lineWidth, outline, fill);
  return {};
}

/// eRectangle, eCircle: the edge only of the shape in the box with corners (x1, y1), (x2, y2),
/// in a width (default: the line width) and a colour (default: the current colour) of its own.
template <bool ellipse>
Value edgeShape(Machine& m, Args& a) {
  Canvas& c = m.canvas();
  Point p = point(a, 0), q = point(a, 2);
  int w = a.has(4) ? widthArg(a, 4) : c.lineWidth;
  Colour col = a.has(5) ? a.colour(5) : c.foreground;
  if (ellipse) c.ellipse(p, q, w, col, std::nullopt);
  else c.rectangle(p, q, w, col, std::nullopt);
  return {};
}

/// The most corners one polygon statement draws.
constexpr size_t kMaxPolygonCorners = 65536;

/// The x, y pairs of an array of numbers (any shape, in storage order), rounded to pixels.
std::vector<Point> arrayPairs(Args& a) {
  const ArrObj& arr = a[0].arr();
  if (arr.items.size() % 2 != 0 || arr.items.size() < 4)
    throw RuntimeError(a.describe(0) + " must hold at least two x, y pairs");
  // Filling costs the corners times the screen's rows: a bound keeps one statement's time in
  // proportion to what a time limit allows (a screen has 800 x 600 pixels).
  if (arr.items.size() / 2 > kMaxPolygonCorners)
    throw RuntimeError(a.describe(0) + " has " + std::to_string(arr.items.size() / 2) + " corners; at most " +
                       std::to_string(kMaxPolygonCorners) + " are drawn in one statement");
  std::vector<Point> pts;
  pts.reserve(arr.items.size() / 2);
  for (size_t i = 0; i + 1 < arr.items.size(); i += 2) {
    const Value& x = arr.items[i];
    const Value& y = arr.items[i + 1];
    if (!x.isNumeric() || !y.isNumeric()) throw RuntimeError(a.describe(0) + " holds something that is not a number");
    // Kept within the range Args::coordinate allows, so no drawing arithmetic overflows.
    auto pixel = [](double v) { return static_cast<int>(std::lround(std::clamp(v, -1e6, 1e6))); };
    pts.push_back({pixel(x.asDouble()), pixel(y.asDouble())});
  }
  return pts;
}

/// Between the edges of a polygon's outline: the run's limits (65,536 edges of a wide line
/// across the screen take minutes).
std::function<void()> edgeCheck(Machine& m) {
  return [&m] { m.checkAlarms(); };
}

const ArrObj& coordinateArray(Args& a) {
  if (!a[0].isArr()) throw RuntimeError(a.describe(0) + " must be an array of coordinates");
  return a[0].arr();
}

/// polygon: a 1-D array x1, y1, x2, y2, ...; outline (default: the current colour) and fill.
Value polygon(Machine& m, Args& a) {
  if (coordinateArray(a).dims.size() != 1)
    throw RuntimeError(a.describe(0) + " must be a one-dimensional array x1, y1, x2, y2, ...");
  auto pts = arrayPairs(a);
  auto [outline, fill] = shapeColours(m, a, 1);
  m.canvas().polygon(pts, m.canvas().lineWidth, outline, fill, edgeCheck(m));
  return {};
}

/// One polygon of mPolygon's flat form: its vertices and the point to fill from, if any.
struct FlatPolygon {
  std::vector<Point> vertices;
  std::optional<Point> fillPoint;
};

/// mPolygon's flat array as real programs write it with `data`: a pair whose x is negative
/// starts a polygon at (-x, y); a pair whose y is negative is the fill point (|x|, -y) of the
/// polygon before it, not a vertex; other pairs are vertices of the current polygon (the first
/// pair starts one whatever its sign).
std::vector<FlatPolygon> flatPolygons(Args& a, const std::vector<Point>& pairs) {
  std::vector<FlatPolygon> polys;
  for (const Point& p : pairs) {
    if (p.y < 0) {
      if (polys.empty() || polys.back().vertices.empty())
        throw RuntimeError(a.describe(0) + " has a fill point (negative y) before any polygon");
      polys.back().fillPoint = Point{std::abs(p.x), -p.y};
    } else if (p.x < 0 || polys.empty()) {
      polys.push_back({{{std::abs(p.x), p.y}}, std::nullopt});
    } else {
      polys.back().vertices.push_back(p);
    }
  }
  return polys;
}

/// mPolygon: an n x 2 array of vertices (outline and fill colours as polygon), or a flat array
/// of one or more polygons (flatPolygons) drawn in the current colour and line width, each
/// flood-filled from its fill point with `colour` (without a fill point: its inside is filled).
Value mPolygon(Machine& m, Args& a) {
  const ArrObj& arr = coordinateArray(a);
  Canvas& c = m.canvas();
  if (arr.dims.size() == 1) {
    if (a.has(2)) throw RuntimeError("mPolygon with a flat array takes one colour, the fill: " + a.describe(2) + " is one too many");
    std::optional<Colour> fill;
    if (a.has(1)) fill = a.colour(1);
    const std::function<void()> check = edgeCheck(m);
    for (const FlatPolygon& poly : flatPolygons(a, arrayPairs(a))) {
      if (fill && poly.fillPoint) {
        c.polygon(poly.vertices, c.lineWidth, c.foreground, std::nullopt, check);
        c.floodFill(poly.fillPoint->x, poly.fillPoint->y, *fill);
      } else {
        c.polygon(poly.vertices, c.lineWidth, c.foreground, fill, check);
      }
      m.checkAlarms();  // each fill may cover the screen
    }
    return {};
  }
  if (arr.dims.size() != 2 || arr.dims[1] != 2)
    throw RuntimeError(a.describe(0) + " must be a flat array of x, y pairs or an array with 2 columns (x, y)");
  auto pts = arrayPairs(a);
  auto [outline, fill] = shapeColours(m, a, 1);
  c.polygon(pts, c.lineWidth, outline, fill, edgeCheck(m));
  return {};
}

Value setPixel(Machine& m, Args& a) {
  m.canvas().setPixel(a.coordinate(0), a.coordinate(1), a.has(2) ? a.colour(2) : m.canvas().foreground);
  return {};
}

Value pixelClr(Machine& m, Args& a) {
  int x = a.coordinate(0), y = a.coordinate(1);
  if (!Canvas::inside(x, y)) return Value::integer(-1);
  return Value::integer(m.canvas().at(x, y));
}

Value floodFill(Machine& m, Args& a) {
  m.canvas().floodFill(a.coordinate(0), a.coordinate(1), a.colour(2));
  return {};
}

Value xyString(Machine& m, Args& a) {
  TextStyle style;
  style.background = m.canvas().textBackground;
  m.canvas().text(a.coordinate(0), a.coordinate(1), a.str(2), style, m.canvas().foreground);
  return {};
}

/// xyText's style: a number, the sum of fs_Bold (1), fs_Italic (2), fs_Underline (4) and
/// fs_StrikeOut (8), or letters ("b", "i", "u", "s").
void parseStyle(Args& a, int i, TextStyle& style) {
  if (a[i].isStr()) {
    for (char c : a.str(i)) {
      char l = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      if (l == 'b') style.font.bold = true;
      else if (l == 'i') style.font.italic = true;
      else if (l == 'u') style.underline = true;
      else if (l == 's') style.strikeout = true;
    }
  } else {
    int64_t bits = a.integer(i);
    style.font.bold = bits & kFsBold;
    style.font.italic = bits & kFsItalic;
    style.underline = bits & kFsUnderline;
    style.strikeout = bits & kFsStrikeOut;
  }
}

Value xyText(Machine& m, Args& a) {
  TextStyle style;
  const Value& text = a[2];
  std::string formatted;  // a number's printed form; a string is drawn where it is
  const std::string& s = text.isStr() ? text.str() : (formatted = formatValue(text));
  // Argument 3 names a font: Courier New, Arial, Times New Roman and their kin map to the
  // Liberation face with the same widths; "" (or a number) is the default face.
  if (a.has(3)) {
    if (a[3].isStr()) style.font.face = typefaceForName(a.str(3));
    else if (!a[3].isNumeric()) (void)a.str(3);
  }
  if (a.has(4)) {
    // Size in points at 96 dpi: pixels = points * 4 / 3.
    double pts = a.num(4);
    if (pts < 1 || pts > 200) throw RuntimeError(a.describe(4) + " must be a font size from 1 to 200");
    style.font.pixelSize = pixelSizeForPoints(pts);
  }
  if (a.has(5)) parseStyle(a, 5, style);
  Colour c = a.has(6) ? a.colour(6) : m.canvas().foreground;
  if (a.has(7)) style.background = a.colour(7);
  m.canvas().text(a.coordinate(0), a.coordinate(1), s, style, c);
  return {};
}

Value saveScr(Machine& m, Args&) {
  m.canvas().save();
  return {};
}

Value restoreScr(Machine& m, Args&) {
  m.canvas().restore();
  return {};
}

Value flip(Machine& m, Args& a) {
  if (a.has(0)) {
    m.flipMode = a.num(0) != 0;
    if (!m.flipMode) m.flipped.clear();
  }
  if (m.flipMode) {
    m.flipped = m.canvas().pixels();
    ++m.flips;
  }
  return {};
}

Value rgb(Machine&, Args& a) {
  for (int i = 0; i < 3; ++i) {
    int64_t v = a.integer(i);
    if (v < 0 || v > 255) throw RuntimeError(a.describe(i) + " must be from 0 to 255");
  }
  return Value::integer(rgbColour(static_cast<int>(a.integer(0)), static_cast<int>(a.integer(1)),
                                  static_cast<int>(a.integer(2))));
}

}  // namespace

void appendGraphicsBuiltins(std::vector<Builtin>& t) {
  t.insert(t.end(), {
      {"clearScr", K::Command, "graphics", "[colour]", clearScr, 0,
       "fills the screen with colour (White) and makes it the background; text cursor home"},
      {"setColor", K::Command, "graphics", "colour [, background]", setColor, 0,
       "drawing and text colour; optional background behind printed text"},
      {"lineWidth", K::Command, "graphics", "width", lineWidth, 0, "width of lines and outlines (1..100)"},
      {"gotoXY", K::Command, "graphics", "x, y", gotoXY, 0, "moves the graphics pen to (x, y) without drawing"},
      {"lineTo", K::Command, "graphics", "x, y [, width [, colour]]", lineTo, 0,
       "draws from the graphics pen to (x, y) and moves the pen there"},
      {"line", K::Command, "graphics", "x1, y1, x2, y2 [, width [, colour]]", line, 0,
       "draws a line; the graphics pen ends at (x2, y2)"},
      {"rectangle", K::Command, "graphics", "x1, y1, x2, y2 [, outline [, fill]]", shape<Box::Corners, false>, 0,
       "rectangle with corners (x1, y1) and (x2, y2); filled when fill is given"},
      {"rectangleWH", K::Command, "graphics", "x, y, width, height [, outline [, fill]]", shape<Box::CornerSize, false>, 0,
       "rectangle from its top-left corner and size"},
      {"eRectangle", K::Command, "graphics", "x1, y1, x2, y2 [, width [, colour]]", edgeShape<false>, 0,
       "the edge of the rectangle with corners (x1, y1), (x2, y2), width pixels wide inward; no fill"},
      {"circle", K::Command, "graphics", "x1, y1, x2, y2 [, outline [, fill]]", shape<Box::Corners, true>, 0,
       "ellipse inside the box (x1, y1)-(x2, y2); filled when fill is given"},
      {"circleWH", K::Command, "graphics", "x, y, width, height [, outline [, fill]]", shape<Box::CornerSize, true>, 0,
       "ellipse inside the box from its top-left corner and size"},
      {"eCircle", K::Command, "graphics", "x1, y1, x2, y2 [, width [, colour]]", edgeShape<true>, 0,
       "the edge of the ellipse in the box (x1, y1)-(x2, y2), width pixels wide inward; no fill"},
      {"polygon", K::Command, "graphics", "points [, outline [, fill]]", polygon, 0,
       "closed polygon through the points of a 1-D array x1, y1, x2, y2, ..."},
      {"mPolygon", K::Command, "graphics", "points [, colour [, fill]]", mPolygon, 0,
       "polygons of a flat array (a negative x starts one, a negative y gives its fill point; "
       "outline in the current colour, filled with colour), or of the rows (x, y) of an n x 2 "
       "array (colour: the outline)"},
      {"setPixel", K::Command, "graphics", "x, y [, colour]", setPixel, 0, "colours one pixel"},
      {"pixelClr", K::Function, "graphics", "x, y", pixelClr, 0,
       "the colour number of a pixel (-1 outside the screen)"},
      {"floodFill", K::Command, "graphics", "x, y, colour", floodFill, 0,
       "fills the area of (x, y)'s colour around it"},
      {"xyString", K::Command, "graphics", "x, y, items...", xyString, 0,
       "prints items (separated as in print) with the top-left corner at (x, y)"},
      {"xyText", K::Command, "graphics",
       "x, y, text [, font [, size [, style [, colour [, background]]]]]", xyText, 0,
       "text at (x, y): font \"Courier New\", \"Arial\", \"Times New Roman\"... (\"\": the print font), "
       "size in points, style fs_Bold + fs_Italic + fs_Underline + fs_StrikeOut (or \"bius\")"},
      {"saveScr", K::Command, "graphics", "", saveScr, 0, "remembers the screen"},
      {"restoreScr", K::Command, "graphics", "", restoreScr, 0, "puts back the screen saveScr remembered"},
      {"flip", K::Command, "graphics", "[mode]", flip, 0,
       "flip On: a live view shows the screen only at each flip (double buffering); flip Off"},
      {"RGB", K::Function, "graphics", "red, green, blue", rgb, 0,
       "the colour number of an RGB colour (each 0..255): red + 256*green + 65536*blue"},
  });
}

}  // namespace rb::builtins
