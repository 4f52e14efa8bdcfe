// Graphics built-ins: they draw on the Machine's canvas with its current colour and line width.
#include <cctype>
#include <cmath>

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

/// Points of polygon (a 1-D array x1, y1, x2, y2, ...) or mPolygon (an n x 2 array).
std::vector<Point> polygonPoints(Args& a, bool matrix) {
  if (!a[0].isArr()) throw RuntimeError(a.describe(0) + " must be an array of coordinates");
  const ArrObj& arr = a[0].arr();
  if (matrix && (arr.dims.size() != 2 || arr.dims[1] != 2))
    throw RuntimeError(a.describe(0) + " must be an array with 2 columns (x, y)");
  if (!matrix && arr.dims.size() != 1)
    throw RuntimeError(a.describe(0) + " must be a one-dimensional array x1, y1, x2, y2, ...");
  if (arr.items.size() % 2 != 0 || arr.items.size() < 4)
    throw RuntimeError(a.describe(0) + " must hold at least two x, y pairs");
  std::vector<Point> pts;
  for (size_t i = 0; i + 1 < arr.items.size(); i += 2) {
    const Value& x = arr.items[i];
    const Value& y = arr.items[i + 1];
    if (!x.isNumeric() || !y.isNumeric()) throw RuntimeError(a.describe(0) + " holds something that is not a number");
    pts.push_back({static_cast<int>(std::lround(x.asDouble())), static_cast<int>(std::lround(y.asDouble()))});
  }
  return pts;
}

Value polygon(Machine& m, Args& a) {
  auto pts = polygonPoints(a, false);
  auto [outline, fill] = shapeColours(m, a, 1);
  m.canvas().polygon(pts, m.canvas().lineWidth, outline, fill);
  return {};
}

Value mPolygon(Machine& m, Args& a) {
  auto pts = polygonPoints(a, true);
  auto [outline, fill] = shapeColours(m, a, 1);
  m.canvas().polygon(pts, m.canvas().lineWidth, outline, fill);
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

/// xyText's style: a number (1 bold, 2 italic, 4 underline) or letters ("b", "i", "u").
void parseStyle(Args& a, int i, TextStyle& style) {
  if (a[i].isStr()) {
    for (char c : a.str(i)) {
      char l = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      if (l == 'b') style.bold = true;
      else if (l == 'i') style.italic = true;
      else if (l == 'u') style.underline = true;
    }
  } else {
    int64_t bits = a.integer(i);
    style.bold = bits & 1;
    style.italic = bits & 2;
    style.underline = bits & 4;
  }
}

Value xyText(Machine& m, Args& a) {
  TextStyle style;
  const Value& text = a[2];
  std::string s = formatValue(text);
  // argument 3 names a font; rb has one family of fonts and draws every name with it.
  if (a.has(3) && !a[3].isStr() && !a[3].isNumeric()) (void)a.str(3);
  if (a.has(4)) {
    // Size in points at 96 dpi: pixels = points * 4 / 3.
    double pts = a.num(4);
    if (pts < 1 || pts > 200) throw RuntimeError(a.describe(4) + " must be a font size from 1 to 200");
    style.height = static_cast<int>(std::lround(pts * 4.0 / 3.0));
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
  if (m.flipMode) m.flipped = m.canvas().pixels();
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
      {"mPolygon", K::Command, "graphics", "points [, outline [, fill]]", mPolygon, 0,
       "closed polygon through the rows (x, y) of an n x 2 array"},
      {"setPixel", K::Command, "graphics", "x, y [, colour]", setPixel, 0, "colours one pixel"},
      {"pixelClr", K::Function, "graphics", "x, y", pixelClr, 0,
       "the colour number of a pixel (-1 outside the screen)"},
      {"floodFill", K::Command, "graphics", "x, y, colour", floodFill, 0,
       "fills the area of (x, y)'s colour around it"},
      {"xyString", K::Command, "graphics", "x, y, items...", xyString, 0,
       "prints items (separated as in print) with the top-left corner at (x, y)"},
      {"xyText", K::Command, "graphics",
       "x, y, text [, font [, size [, style [, colour [, background]]]]]", xyText, 0,
       "text at (x, y): size in points, style 1/\"b\" bold, 2/\"i\" italic, 4/\"u\" underline"},
      {"saveScr", K::Command, "graphics", "", saveScr, 0, "remembers the screen"},
      {"restoreScr", K::Command, "graphics", "", restoreScr, 0, "puts back the screen saveScr remembered"},
      {"flip", K::Command, "graphics", "[mode]", flip, 0,
       "flip On: a live view shows the screen only at each flip (double buffering); flip Off"},
      {"RGB", K::Function, "graphics", "red, green, blue", rgb, 0,
       "the colour number of an RGB colour (each 0..255): red + 256*green + 65536*blue"},
  });
}

}  // namespace rb::builtins
