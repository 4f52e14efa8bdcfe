#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <set>
#include <tuple>
#include <vector>
#include <string>

#include "screen/canvas.h"

using namespace rb;

namespace {

/// Whether two screens have the same pixels: a bool, so that a failure does not print 480,000
/// of them.
bool samePixels(const Canvas& a, const Canvas& b) { return a.pixels() == b.pixels(); }

/// The first pixel of rows [y0, y1) where two screens differ, as "x,y", or "" when they agree.
/// The rows are compared as memory first: a test that compares after every step of thousands
/// stays fast under the sanitizers.
std::string firstDifference(const Canvas& a, const Canvas& b, int y0, int y1) {
  const auto& pa = a.pixels();
  const auto& pb = b.pixels();
  const size_t from = static_cast<size_t>(y0) * Canvas::kWidth, to = static_cast<size_t>(y1) * Canvas::kWidth;
  if (std::equal(pa.begin() + static_cast<std::ptrdiff_t>(from), pa.begin() + static_cast<std::ptrdiff_t>(to),
                 pb.begin() + static_cast<std::ptrdiff_t>(from)))
    return "";
  for (size_t i = from;; ++i)
    if (pa[i] != pb[i]) return std::to_string(i % Canvas::kWidth) + "," + std::to_string(i / Canvas::kWidth);
}

}  // namespace

TEST_CASE("a print that scrolls a whole screen draws only what stays visible, identically",
          "[canvas]") {
  // The same text printed line by line (scrolling each time) and in one huge print (which
  // skips the lines that scroll away) must leave the same pixels and cursor.
  std::string lines;
  for (int i = 0; i < 120; ++i) {
    std::string line = "line " + std::to_string(i) + "\tcol\t" + std::string(static_cast<size_t>(i % 130), 'x');
    lines += line + "\n";
  }
  Canvas slow, fast;
  slow.rectangle({100, 100}, {300, 300}, 1, colours::kRed, colours::kRed);
  fast.rectangle({100, 100}, {300, 300}, 1, colours::kRed, colours::kRed);
  slow.print("start ", false);
  fast.print("start ", false);
  size_t pos = 0;
  while (pos < lines.size()) {
    size_t end = lines.find('\n', pos);
    slow.print(lines.substr(pos, end - pos), true);
    pos = end + 1;
  }
  fast.print(lines.substr(0, lines.size() - 1), true);
  CHECK(fast.textCursor() == slow.textCursor());
  CHECK(samePixels(fast, slow));
}

TEST_CASE("print wraps at the right edge and expands tabs to 8 columns", "[canvas]") {
  Canvas c;
  c.print("ab\tc", false);
  CHECK(c.textCursor() == Point{9 * 8, 0});
  // 100 columns of 8 pixels: 150 characters take two lines of 15 pixels.
  c.print(std::string(150, 'x'), true);
  CHECK(c.textCursor() == Point{0, 30});
}

TEST_CASE("the palette: RobotBASIC 4.2's colours, light twins lifted by 128", "[canvas]") {
  using namespace colours;
  // Confirmed by screenshots of RobotBASIC 4.2.
  CHECK(colourToRgb(kRed) == 0xFF0000);
  CHECK(colourToRgb(kBlue) == 0x0000FF);
  CHECK(colourToRgb(kCyan) == 0x008080);
  CHECK(colourToRgb(kGray) == 0xC0C0C0);
  CHECK(colourToRgb(kLightRed) == 0xFF8080);
  // Chosen: every light colour is its dark twin (number - 8) with 128 added to each channel.
  for (Colour dark : {kBlack, kBlue, kGreen, kCyan, kRed, kMagenta, kGray}) {
    uint32_t d = colourToRgb(dark), l = colourToRgb(dark + 8);
    for (int shift : {0, 8, 16}) {
      uint32_t dc = (d >> shift) & 0xFF, lc = (l >> shift) & 0xFF;
      INFO("colour " << dark << " channel " << shift);
      CHECK(lc == std::min<uint32_t>(dc + 128, 255));
    }
  }
  CHECK(colourToRgb(kGreen) == 0x008000);
  CHECK(colourToRgb(kBrown) == 0x804000);
  CHECK(colourToRgb(kYellow) == 0xFFFF00);
  CHECK(colourToRgb(kWhite) == 0xFFFFFF);
  // RGB() numbers above 15 are r + 256 g + 65536 b.
  CHECK(colourToRgb(rgbColour(18, 52, 86)) == 0x123456);
}

namespace {
/// The distance from p to the segment a-b.
double segmentDistance(double px, double py, Point a, Point b) {
  double dx = b.x - a.x, dy = b.y - a.y;
  double len2 = dx * dx + dy * dy;
  double t = len2 == 0 ? 0 : std::clamp(((px - a.x) * dx + (py - a.y) * dy) / len2, 0.0, 1.0);
  return std::hypot(px - (a.x + t * dx), py - (a.y + t * dy));
}
}  // namespace

TEST_CASE("canvas: a run keeps no display list unless asked", "[canvas]") {
  Canvas c;
  for (int i = 0; i < 1000; ++i) c.setPixel(i % 800, i % 600, colours::kRed);
  c.text(10, 10, "status", TextStyle{}, colours::kBlack);
  CHECK(c.displayList().empty());
  CHECK(c.at(5, 5) == colours::kRed);  // the pixels are drawn all the same
}

TEST_CASE("canvas: the pen trail's straight stretches are single segments", "[canvas]") {
  Canvas c;
  c.keepDisplayList(true);
  // A square of side 120, one pixel at a time, as the robot's pen draws it.
  c.trailStart(400, 300, 1, colours::kGreen);
  double x = 400, y = 300;
  const double step[4][2] = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
  for (const auto& s : step)
    for (int i = 0; i < 120; ++i) c.trailTo(x += s[0], y += s[1]);
  REQUIRE(c.displayList().size() == 1);
  CHECK(c.displayList()[0].points ==
        std::vector<Point>{{400, 300}, {400, 180}, {520, 180}, {520, 300}, {400, 300}});

  // A circle of small steps: few points, and every point the pen passed stays within a pixel
  // of the polyline that replaces them.
  Canvas arc;
  arc.keepDisplayList(true);
  std::vector<std::pair<double, double>> passed;
  double h = 0;
  x = 400, y = 200;
  arc.trailStart(x, y, 1, colours::kGreen);
  for (int i = 0; i < 3600; ++i) {
    h += 0.1 * std::numbers::pi / 180;
    x += 0.3 * std::sin(h) * 3, y -= 0.3 * std::cos(h) * 3;
    arc.trailTo(x, y);
    passed.emplace_back(x, y);
  }
  const std::vector<Point>& pts = arc.displayList().back().points;
  CHECK(pts.size() < 400);
  for (auto [px, py] : passed) {
    double best = 1e9;
    for (size_t i = 0; i + 1 < pts.size(); ++i) best = std::min(best, segmentDistance(px, py, pts[i], pts[i + 1]));
    INFO("point " << px << "," << py);
    CHECK(best <= 1.5);
  }
}

namespace {
/// The straight segments the trail entries of a display list stroke, each one way round, with
/// the colour and width: what the SVG's polylines cover (round caps and joins make a polyline
/// exactly the union of its segments' strokes).
std::set<std::tuple<int, int, int, int, Colour, int>> trailSegments(const std::vector<DrawOp>& ops) {
  std::set<std::tuple<int, int, int, int, Colour, int>> out;
  for (const DrawOp& op : ops) {
    if (op.kind != DrawOp::Trail) continue;
    for (size_t i = 0; i + 1 < op.points.size(); ++i) {
      Point a = op.points[i], b = op.points[i + 1];
      if (b.x < a.x || (b.x == a.x && b.y < a.y)) std::swap(a, b);
      out.emplace(a.x, a.y, b.x, b.y, op.colour, op.width);
    }
  }
  return out;
}

size_t pointCount(const std::vector<DrawOp>& ops) {
  size_t n = 0;
  for (const DrawOp& op : ops) n += op.points.size();
  return n;
}

/// Drives `laps` laps of a square of side 120 one pixel at a time, as the robot's pen does.
void squareLaps(Canvas& c, int laps, double& x, double& y) {
  const double step[4][2] = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
  for (int lap = 0; lap < laps; ++lap)
    for (const auto& s : step)
      for (int i = 0; i < 120; ++i) c.trailTo(x += s[0], y += s[1]);
}
}  // namespace

TEST_CASE("canvas: a retraced trail keeps one lap in the display list", "[canvas]") {
  Canvas one, many;
  one.keepDisplayList(true);
  many.keepDisplayList(true);
  double x = 400, y = 300;
  one.trailStart(x, y, 3, colours::kGreen);
  squareLaps(one, 1, x, y);
  x = 400, y = 300;
  many.trailStart(x, y, 3, colours::kGreen);
  squareLaps(many, 1000, x, y);
  // The same segments in the same colour and width: the same picture, and about one lap's size.
  CHECK(trailSegments(many.displayList()) == trailSegments(one.displayList()));
  CHECK(pointCount(many.displayList()) <= pointCount(one.displayList()) + 4);
  CHECK(samePixels(many, one));

  // Lifting the pen and putting it down again with nothing drawn in between: still one lap.
  many.trailEnd();
  many.trailStart(x, y, 3, colours::kGreen);
  squareLaps(many, 10, x, y);
  CHECK(trailSegments(many.displayList()) == trailSegments(one.displayList()));
  CHECK(pointCount(many.displayList()) <= pointCount(one.displayList()) + 8);
}

TEST_CASE("canvas: a retraced trail is kept again after something drawn over it", "[canvas]") {
  // A red line across the square, then another lap: the lap paints over the line, so it must
  // stay in the display list after the line.
  Canvas c;
  c.keepDisplayList(true);
  double x = 400, y = 300;
  c.trailStart(x, y, 1, colours::kGreen);
  squareLaps(c, 2, x, y);
  const size_t lapPoints = pointCount(c.displayList());
  c.line({380, 240}, {540, 240}, 5, colours::kRed);
  squareLaps(c, 1, x, y);
  auto line = std::find_if(c.displayList().begin(), c.displayList().end(),
                           [](const DrawOp& op) { return op.kind == DrawOp::Line; });
  REQUIRE(line != c.displayList().end());
  std::vector<DrawOp> after(line + 1, c.displayList().end());
  CHECK(trailSegments(after).size() == 4);  // the square's four sides, after the line
  CHECK(pointCount(c.displayList()) <= 2 * lapPoints + 4);
  // A lap in another colour is kept, and so is the next lap in the first colour over it.
  Canvas d;
  d.keepDisplayList(true);
  x = 400, y = 300;
  d.trailStart(x, y, 1, colours::kGreen);
  squareLaps(d, 1, x, y);
  d.trailStart(x, y, 1, colours::kBlue);
  squareLaps(d, 1, x, y);
  d.trailStart(x, y, 1, colours::kGreen);
  squareLaps(d, 1, x, y);
  CHECK(trailSegments(d.displayList()).size() == 8);
  size_t lastBlue = 0;
  for (size_t i = 0; i < d.displayList().size(); ++i)
    if (d.displayList()[i].colour == colours::kBlue) lastBlue = i;
  std::vector<DrawOp> overBlue(d.displayList().begin() + static_cast<long>(lastBlue) + 1, d.displayList().end());
  CHECK(trailSegments(overBlue).size() == 4);
  CHECK(d.at(400, 250) == colours::kGreen);
}

TEST_CASE("canvas: a fill of the whole screen drops what it hides from the display list", "[canvas]") {
  Canvas c;
  c.keepDisplayList(true);
  for (int i = 0; i < 100; ++i) c.line({0, i}, {799, i}, 1, colours::kRed);
  c.rectangle({0, 0}, {799, 599}, 1, std::nullopt, colours::kYellow);
  CHECK(c.displayList().size() == 1);
  c.rectangle({10, 10}, {799, 599}, 1, std::nullopt, colours::kBlue);  // not the whole screen
  CHECK(c.displayList().size() == 2);
}

TEST_CASE("canvas: a line from far outside draws only what crosses the screen", "[canvas]") {
  Canvas c;
  c.line({-100000, -100000}, {100000, 100000}, 100, colours::kRed);
  CHECK(c.at(300, 300) == colours::kRed);
  CHECK(c.at(330, 300) == colours::kRed);  // within the brush's 50-pixel radius
  CHECK(c.at(400, 300) == colours::kWhite);
  Canvas far;
  far.line({-100000, 5000}, {100000, 5000}, 100, colours::kRed);
  CHECK(std::count(far.pixels().begin(), far.pixels().end(), colours::kRed) == 0);
  // The part on the screen is the same as that of a line from the edge of the screen.
  Canvas a, b;
  a.line({-1000, -500}, {1600, 800}, 3, colours::kBlue);
  b.line({0, 0}, {800, 400}, 3, colours::kBlue);
  int differ = 0;
  for (size_t i = 0; i < a.pixels().size(); ++i) differ += a.pixels()[i] != b.pixels()[i];
  CHECK(differ == 0);  // the same pixels however far the ends lie
}

namespace {

/// The colour the ellipse as it was drawn before spans gives pixel (x, y) of a white screen:
/// every pixel of the bounding box tested on its own. The span drawing must agree everywhere.
Colour ellipsePerPixel(int x, int y, Point a, Point b, int width, std::optional<Colour> outline,
                       std::optional<Colour> fill) {
  int x1 = std::min(a.x, b.x), x2 = std::max(a.x, b.x);
  int y1 = std::min(a.y, b.y), y2 = std::max(a.y, b.y);
  if (x < x1 || x > x2 || y < y1 || y > y2) return colours::kWhite;
  double cx = (x1 + x2) / 2.0, cy = (y1 + y2) / 2.0;
  double rx = (x2 - x1) / 2.0, ry = (y2 - y1) / 2.0;
  int w = std::max(width, 1);
  auto inside = [](double dx, double dy, double ax, double ay) {
    double u = dx / (ax + 0.5), v = dy / (ay + 0.5);
    return u * u + v * v <= 1.0;
  };
  double irx = rx - w, iry = ry - w;
  bool hasInner = irx + 0.5 > 0 && iry + 0.5 > 0;
  double dx = x - cx, dy = y - cy;
  if (!inside(dx, dy, rx, ry)) return colours::kWhite;
  bool inner = hasInner && inside(dx, dy, irx, iry);
  if (outline && !inner) return *outline;
  if (fill) return *fill;
  return colours::kWhite;
}

}  // namespace

TEST_CASE("canvas: ellipses drawn by rows are the pixels of the per-pixel rule", "[canvas]") {
  // Every small size (even and odd, zero width or height), larger and off-screen boxes, each
  // filled, outlined and both, with several outline widths. Each is drawn on a white screen
  // and compared over its box and a margin of 2 pixels (on the screen).
  std::vector<std::pair<Point, Point>> boxes;
  for (int w = 0; w <= 12; ++w)
    for (int h = 0; h <= 12; ++h) boxes.push_back({{300, 200}, {300 + w, 200 + h}});
  for (int k = 0; k < 40; ++k) {
    int w = 25 + (k * 37) % 400, h = 25 + (k * 53) % 300;
    boxes.push_back({{400 - w / 2 + k, 300 - h / 2 - k}, {400 + (w + 1) / 2 + k, 300 + h / 2 - k}});
  }
  boxes.push_back({{-50, -40}, {90, 70}});       // crosses the top-left corner
  boxes.push_back({{700, 520}, {900, 650}});     // crosses the bottom-right corner
  boxes.push_back({{-300, -200}, {1100, 800}});  // larger than the screen
  boxes.push_back({{-5000, 100}, {5000, 500}});  // far wider than the screen
  boxes.push_back({{390, -4000}, {410, 4000}});  // far taller
  boxes.push_back({{900, 100}, {1000, 200}});    // wholly off the screen
  boxes.push_back({{500, 300}, {100, 100}});     // corners given the other way round
  const std::vector<std::pair<std::optional<Colour>, std::optional<Colour>>> paints = {
      {colours::kRed, std::nullopt}, {std::nullopt, colours::kBlue}, {colours::kRed, colours::kGreen}};
  int checked = 0;
  Canvas c;
  for (const auto& [a, b] : boxes)
    for (const auto& [outline, fill] : paints)
      for (int width : {1, 2, 3, 7}) {
        if (!outline && width > 1) continue;  // the width only shapes the outline
        int x0 = std::max(std::min(a.x, b.x) - 2, 0), x1 = std::min(std::max(a.x, b.x) + 2, Canvas::kWidth - 1);
        int y0 = std::max(std::min(a.y, b.y) - 2, 0), y1 = std::min(std::max(a.y, b.y) + 2, Canvas::kHeight - 1);
        c.clear(colours::kWhite);
        c.ellipse(a, b, width, outline, fill);
        bool same = true;
        for (int y = y0; y <= y1 && same; ++y)
          for (int x = x0; x <= x1 && same; ++x)
            same = c.at(x, y) == ellipsePerPixel(x, y, a, b, width, outline, fill);
        if (!same)
          FAIL_CHECK("ellipse (" << a.x << "," << a.y << ")-(" << b.x << "," << b.y << ") width " << width
                                 << (outline ? " outlined" : "") << (fill ? " filled" : ""));
        ++checked;
      }
  CHECK(checked > 1500);
}

TEST_CASE("canvas: the screen made on first use looks the same as one made at once", "[canvas]") {
  const size_t n = static_cast<size_t>(Canvas::kWidth) * Canvas::kHeight;
  Canvas fresh;
  CHECK(fresh.at(0, 0) == colours::kWhite);
  CHECK(fresh.at(799, 599) == colours::kWhite);
  CHECK(fresh.pixels() == Pixels(n, colours::kWhite));

  // clearScr before anything is drawn: every pixel takes the new colour, read either way.
  Canvas cleared;
  cleared.clear(colours::kRed);
  CHECK(cleared.at(400, 300) == colours::kRed);
  CHECK(cleared.pixels() == Pixels(n, colours::kRed));
  cleared.setPixel(1, 1, colours::kBlue);
  CHECK(cleared.at(1, 1) == colours::kBlue);
  CHECK(cleared.at(2, 1) == colours::kRed);

  // saveScr of an untouched screen, then drawing, then restoreScr: the blank screen again.
  Canvas saved;
  saved.save();
  saved.rectangle({10, 10}, {50, 50}, 1, colours::kBlack, colours::kBlack);
  CHECK(saved.at(20, 20) == colours::kBlack);
  saved.restore();
  CHECK(saved.pixels() == Pixels(n, colours::kWhite));
}

TEST_CASE("canvas: text redrawn over itself paints only what changed, with the same pixels",
          "[canvas]") {
  // Two screens get the same random drawing: one remembers its text (the default), one draws
  // every character every time. Status lines are redrawn at a few places, in a few styles
  // (italic glyphs reach into their neighbours' cells), with and without a background, between
  // other drawing that covers them, clearScr, scrolling prints and restoreScr.
  Canvas fast, slow;
  slow.setTextMemory(false);
  uint64_t state = 0x2545F4914F6CDD1Dull;
  auto next = [&](uint64_t n) {
    state ^= state << 13, state ^= state >> 7, state ^= state << 17;
    return state % n;
  };
  const std::vector<Point> places = {{20, 560}, {420, 560}, {24, 562}, {790, 300}, {-4, 10},
                                     {300, 20}, {500, 300}, {100, 300}};
  const std::string alphabet = "0123456789 ._-Wjgfy|";
  auto both = [&](auto draw) {
    draw(fast);
    draw(slow);
  };
  size_t textDraws = 0;
  for (int step = 0; step < 6000; ++step) {
    const uint64_t what = next(100);
    if (what < 80) {
      const size_t place = next(places.size());
      const Point at = places[place];
      // Each place keeps its style most of the time (a status line), so redraws match.
      TextStyle style;
      const bool usual = next(5) != 0;
      auto pick = [&](uint64_t n) { return usual ? (place * 7 + 3) % n : next(n); };
      style.font.face = pick(3) == 0 ? Typeface::Sans : Typeface::Mono;
      style.font.italic = pick(4) == 0;
      style.font.bold = pick(5) == 0;
      style.font.pixelSize = pick(4) == 0 ? 20 : 13;
      style.underline = pick(6) == 0;
      style.strikeout = pick(8) == 0;
      if (pick(2) == 0) style.background = pick(3) == 0 ? colours::kYellow : colours::kWhite;
      const Colour c = next(8) == 0 ? colours::kRed : colours::kBlack;
      std::string s = "step ";
      // Now and then a text too long to be remembered (Canvas::kMaxTraceChars).
      for (uint64_t k = next(50) == 0 ? 600 : next(12); k > 0; --k) s += alphabet[next(alphabet.size())];
      both([&](Canvas& cv) { cv.text(at.x, at.y, s, style, c); });
      ++textDraws;
    } else if (what < 90) {
      Point a{static_cast<int>(next(800)), static_cast<int>(next(40)) + 540};
      Point b{a.x + static_cast<int>(next(60)), a.y + static_cast<int>(next(20))};
      const Colour c = static_cast<Colour>(next(16));
      const int w = 1 + static_cast<int>(next(3));
      if (next(2) == 0) both([&](Canvas& cv) { cv.rectangle(a, b, 1, c, c); });
      else both([&](Canvas& cv) { cv.line(a, b, w, c); });
    } else if (what < 94) {
      const int x = static_cast<int>(next(800)), y = static_cast<int>(next(600));
      const Colour c = static_cast<Colour>(next(16));
      both([&](Canvas& cv) { cv.setPixel(x, y, c); });
    } else if (what < 96) {
      both([&](Canvas& cv) { cv.print("a line\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n", false); });
    } else if (what < 97) {
      const Colour c = next(2) == 0 ? colours::kWhite : colours::kGray;
      both([&](Canvas& cv) { cv.clear(c); });
    } else if (what < 98) {
      both([](Canvas& cv) { cv.save(); });
    } else if (what < 99) {
      both([](Canvas& cv) { cv.restore(); });
    } else {
      const int x = static_cast<int>(next(800)), y = static_cast<int>(next(40)) + 540;
      both([&](Canvas& cv) { cv.floodFill(x, y, colours::kCyan); });
    }
    INFO("step " << step << " (operation " << what << ")");
    if (step % 64 == 0) {
      REQUIRE(samePixels(fast, slow));
    } else {
      // Where the text is drawn, after every step.
      for (int band : {0, 290, 530}) {
        const std::string differs = firstDifference(fast, slow, band, std::min(band + 70, Canvas::kHeight));
        if (!differs.empty()) FAIL("pixel " << differs << " differs");
      }
    }
  }
  REQUIRE(samePixels(fast, slow));
  CHECK(textDraws > 4000);
}

TEST_CASE("canvas: a long text starting far to the left shows its end", "[canvas]") {
  // 600 characters of 8 pixels from x = -4000: the last 100 are on the screen, where the same
  // 100 drawn alone from x = 0 are.
  const TextStyle mono;
  std::string s;
  for (int i = 0; i < 600; ++i) s += static_cast<char>('a' + i % 26);
  Canvas whole, tail;
  REQUIRE(whole.text(-4000, 100, s, mono, colours::kBlack) == 4800);
  tail.text(0, 100, s.substr(500), mono, colours::kBlack);
  CHECK(samePixels(whole, tail));
  CHECK(std::count(whole.pixels().begin(), whole.pixels().end(), colours::kBlack) > 1000);
}

TEST_CASE("canvas: a screen of pixels (large memory) copies, compares and grows like a vector", "[screen]") {
  const size_t n = static_cast<size_t>(Canvas::kWidth) * Canvas::kHeight;
  Pixels screen(n, colours::kWhite);
  screen[n - 1] = colours::kRed;
  Pixels copy = screen;
  CHECK(copy == screen);
  copy[0] = colours::kBlue;
  CHECK(copy != screen);
  copy.resize(2 * n, colours::kGreen);  // moves to a larger block
  CHECK(copy[n - 1] == colours::kRed);
  CHECK(copy[2 * n - 1] == colours::kGreen);
  copy = screen;  // back to the screen's size, in the block it has
  CHECK(copy == screen);
}

TEST_CASE("canvas: a filled row reports every pixel that became or stopped being an obstacle",
          "[canvas]") {
  // Rows of random colours, some of them the background or an invisible colour, filled over
  // and over: every pixel whose obstacle state a fill changed lies in a reported box, and the
  // fill leaves exactly its pixels in its colour.
  const Colour palette[] = {colours::kWhite, colours::kBlack, colours::kRed, colours::kGreen, colours::kBlue};
  for (bool withInvisible : {false, true}) {
    INFO("invisible colours: " << withInvisible);
    Canvas canvas;
    if (withInvisible) canvas.setInvisible({colours::kGreen});
    uint32_t seed = 7;
    auto next = [&](uint32_t n) {
      seed = seed * 1103515245u + 12345u;
      return (seed >> 8) % n;
    };
    for (int round = 0; round < 3000; ++round) {
      const int y = static_cast<int>(next(4)) * 3 + 100;
      int x1 = static_cast<int>(next(820)) - 10, x2 = x1 + static_cast<int>(next(200));
      const Colour c = palette[next(5)];
      std::vector<bool> before(Canvas::kWidth);
      for (int x = 0; x < Canvas::kWidth; ++x) before[static_cast<size_t>(x)] = canvas.isObstacle(x, y);
      (void)canvas.takeObstacleChanges();
      canvas.rectangle({x1, y}, {x2, y}, 1, c, c);
      ChangeBoxes changes = canvas.takeObstacleChanges();
      for (int x = 0; x < Canvas::kWidth; ++x) {
        INFO("round " << round << ", pixel " << x << "," << y);
        if (x >= x1 && x <= x2) REQUIRE(canvas.at(x, y) == c);
        if (canvas.isObstacle(x, y) == before[static_cast<size_t>(x)] || changes.all) continue;
        bool reported = std::any_of(changes.boxes.begin(), changes.boxes.end(), [&](const PixelBox& b) {
          return x >= b.x0 && x <= b.x1 && y >= b.y0 && y <= b.y1;
        });
        REQUIRE(reported);
      }
    }
  }
}

TEST_CASE("canvas: the change boxes hold every pixel that changed, whatever drew it", "[canvas]") {
  // Random drawing of every kind, the screen compared before and after each command: every pixel
  // that differs lies in a box takeChanges() reports (or it reports a change everywhere).
  const Colour palette[] = {colours::kWhite, colours::kBlack, colours::kRed, colours::kGreen, rgbColour(1, 2, 3)};
  Canvas canvas;
  ChangeBoxes changes;
  canvas.takeChanges(changes);
  CHECK((changes.boxes.empty() && !changes.all));  // not kept unless asked for
  canvas.trackChanges(true);
  canvas.takeChanges(changes);
  CHECK(changes.all);  // at first, everything is new
  uint32_t seed = 11;
  auto next = [&](int n) {
    seed = seed * 1103515245u + 12345u;
    return static_cast<int>((seed >> 8) % static_cast<uint32_t>(n));
  };
  int reported = 0, everywhere = 0;
  for (int round = 0; round < 300; ++round) {
    const Pixels before = canvas.pixels();
    const Colour c = palette[next(5)];
    const Point a{next(900) - 50, next(700) - 50}, b{a.x + next(200) - 100, a.y + next(200) - 100};
    const int what = next(12);
    switch (what) {
      case 0: canvas.setPixel(a.x, a.y, c); break;
      case 1: canvas.line(a, b, 1 + next(5), c); break;
      case 2: canvas.rectangle(a, b, 1 + next(3), c, next(2) ? std::optional<Colour>(c) : std::nullopt); break;
      case 3: canvas.ellipse(a, b, 1 + next(3), c, next(2) ? std::optional<Colour>(palette[next(5)]) : std::nullopt); break;
      case 4: canvas.polygon({a, b, {a.x, b.y}}, 1 + next(3), c, std::nullopt); break;
      case 5: canvas.text(a.x, a.y, "Ag " + std::to_string(round), TextStyle{}, c); break;
      case 6: canvas.floodFill(a.x, a.y, c); break;
      case 7: canvas.print("line " + std::to_string(round), next(2) != 0); break;
      case 8:
        if (!canvas.trailOpen()) canvas.trailStart(a.x, a.y, 1 + next(3), c);
        canvas.trailTo(b.x, b.y);
        break;
      case 9:
        if (next(8) == 0) canvas.clear(c);
        else canvas.save();
        break;
      case 10:
        if (next(4) == 0) canvas.restore();
        break;
      default: canvas.trailEnd(); break;
    }
    canvas.takeChanges(changes);
    everywhere += changes.all;
    if (changes.all) continue;
    const Pixels& after = canvas.pixels();
    std::string missed;  // the first changed pixel no box holds
    for (int y = 0; y < Canvas::kHeight && missed.empty(); ++y)
      for (int x = 0; x < Canvas::kWidth; ++x) {
        const size_t i = static_cast<size_t>(y) * Canvas::kWidth + static_cast<size_t>(x);
        if (before[i] == after[i]) continue;
        ++reported;
        if (std::none_of(changes.boxes.begin(), changes.boxes.end(), [&](const PixelBox& box) {
              return x >= box.x0 && x <= box.x1 && y >= box.y0 && y <= box.y1;
            })) {
          missed = std::to_string(x) + "," + std::to_string(y);
          break;
        }
      }
    INFO("round " << round << ", command " << what);
    REQUIRE(missed == "");
  }
  CHECK(reported > 10000);
  CHECK(everywhere < 45);  // boxes, mostly: only clearScr and scrolling change everything
  canvas.trackChanges(false);
  canvas.setPixel(1, 1, canvas.at(1, 1) == colours::kRed ? colours::kBlue : colours::kRed);
  canvas.takeChanges(changes);
  CHECK((changes.boxes.empty() && !changes.all));
}
