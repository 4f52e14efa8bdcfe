#include "colour_watch.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

using namespace rb;
using namespace rb::record;

namespace {

/// The rule of colour_watch.h done pixel by pixel: every pixel of the disc at every point of
/// the move (what rb test did before the watch).
class Reference {
 public:
  explicit Reference(const std::vector<uint32_t>& colours) {
    for (uint32_t rgb : colours) touches.push_back({rgb, false, {}, 0});
  }

  void startAt(P2 p) {
    last_ = p;
    placed_ = true;
  }

  void robotEvent(const Canvas& canvas, const RobotEvent& e, double r) {
    if (e.kind != RobotEvent::Locate && e.kind != RobotEvent::Move && e.kind != RobotEvent::Crash) return;
    P2 to{e.pose.pos.x(), e.pose.pos.y()};
    P2 from = e.kind == RobotEvent::Locate || !placed_ ? to : last_;
    last_ = to;
    placed_ = true;
    // (Once every colour is touched nothing can change: passed over, for speed.)
    if (std::all_of(touches.begin(), touches.end(), [](const RunRecord::Touch& t) { return t.touched; })) return;
    std::optional<uint32_t> own;
    if (e.pen) own = colourToRgb(canvas.trailColour());
    uint32_t line = e.loc.file == 0 ? e.loc.line : 0;
    int n = std::max(1, static_cast<int>(std::ceil(distance(from, to))));
    for (int k = 0; k <= n; ++k) {
      double t = static_cast<double>(k) / n;
      P2 c{from.x + (to.x - from.x) * t, from.y + (to.y - from.y) * t};
      int x0 = static_cast<int>(std::floor(c.x - r)), x1 = static_cast<int>(std::ceil(c.x + r));
      int y0 = static_cast<int>(std::floor(c.y - r)), y1 = static_cast<int>(std::ceil(c.y + r));
      for (int y = std::max(0, y0); y <= std::min(Canvas::kHeight - 1, y1); ++y)
        for (int x = std::max(0, x0); x <= std::min(Canvas::kWidth - 1, x1); ++x) {
          if (coverDistance2(x, y, c) > r * r) continue;
          uint32_t rgb = colourToRgb(canvas.at(x, y));
          if (own && rgb == *own) continue;
          for (RunRecord::Touch& t2 : touches)
            if (!t2.touched && t2.rgb == rgb) {
              t2.touched = true;
              t2.at = c;
              t2.line = line;
            }
        }
    }
  }

  std::vector<RunRecord::Touch> touches;

 private:
  P2 last_;
  bool placed_ = false;
};

RobotEvent event(RobotEvent::Kind kind, P2 at, bool pen, uint32_t line) {
  RobotEvent e{kind, "rForward", {}, "", Pose{}, pen, std::nullopt};
  e.pose.pos = {at.x, at.y};
  e.loc.line = line;
  return e;
}

std::string describe(const std::vector<RunRecord::Touch>& touches) {
  std::ostringstream out;
  out.precision(17);
  for (const RunRecord::Touch& t : touches)
    out << std::hex << t.rgb << std::dec << ": " << (t.touched ? "touched at " : "not touched")
        << (t.touched ? "(" + std::to_string(t.at.x) + ", " + std::to_string(t.at.y) + ") line " + std::to_string(t.line) : "")
        << "; ";
  return out.str();
}

bool same(const std::vector<RunRecord::Touch>& a, const std::vector<RunRecord::Touch>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i].rgb != b[i].rgb || a[i].touched != b[i].touched ||
        (a[i].touched && (a[i].at != b[i].at || a[i].line != b[i].line)))
      return false;
  return true;
}

/// A watch and the reference fed the same events on the same screen.
struct Both {
  Canvas& canvas;
  ColourWatch watch;
  Reference reference;
  Both(Canvas& c, const std::vector<uint32_t>& colours) : canvas(c), watch(c, colours), reference(colours) {}
  void on(const RobotEvent& e, double radius) {
    watch.robotEvent(e, radius);
    reference.robotEvent(canvas, e, radius);
  }
  bool agree() const { return same(watch.touches(), reference.touches); }
};

}  // namespace

TEST_CASE("colour watch: a colour under the disc at any point of a move is touched there, with the line",
          "[grade][colour]") {
  Canvas canvas;
  canvas.rectangle({300, 95}, {302, 97}, 1, colours::kBlack, colours::kBlack);
  ColourWatch watch(canvas, {0x000000, 0xFF0000});
  watch.robotEvent(event(RobotEvent::Locate, {100, 100}, false, 3), 20);
  CHECK_FALSE(watch.touches()[0].touched);
  watch.robotEvent(event(RobotEvent::Move, {500, 100}, false, 4), 20);
  REQUIRE(watch.touches()[0].touched);
  // The first of the points 1 px apart (x = 100, 101, ...) whose disc reaches (300, 97):
  // 281, since 19^2 + 3^2 > 20^2 >= 19^2 + 3^2 - 19 * 2 + 1.
  CHECK(watch.touches()[0].at == P2{281, 100});
  CHECK(watch.touches()[0].line == 4);
  CHECK_FALSE(watch.touches()[1].touched);
}

TEST_CASE("colour watch: what is drawn under a robot standing still is touched at its next move",
          "[grade][colour]") {
  Canvas canvas;
  Both both(canvas, {0x000000});
  both.on(event(RobotEvent::Locate, {400, 300}, false, 1), 20);
  canvas.setPixel(410, 300, colours::kBlack);  // under the disc, after the robot stopped there
  both.on(event(RobotEvent::Turn, {400, 300}, false, 3), 20);
  CHECK_FALSE(both.watch.touches()[0].touched);  // a turn is not looked at
  both.on(event(RobotEvent::Move, {400, 250}, false, 4), 20);
  REQUIRE(both.watch.touches()[0].touched);
  CHECK(both.watch.touches()[0].at == P2{400, 300});  // where it stood
  CHECK(both.agree());
}

TEST_CASE("colour watch: a colour erased before the robot gets there is not touched, one drawn ahead is",
          "[grade][colour]") {
  Canvas canvas;
  canvas.rectangle({600, 290}, {610, 310}, 1, colours::kRed, colours::kRed);
  Both both(canvas, {0xFF0000, 0x0000FF});
  both.on(event(RobotEvent::Locate, {100, 300}, false, 1), 20);
  for (int x = 101; x <= 400; ++x) both.on(event(RobotEvent::Move, {double(x), 300}, false, 2), 20);
  canvas.rectangle({600, 290}, {610, 310}, 1, colours::kWhite, colours::kWhite);  // erased
  canvas.rectangle({450, 200}, {452, 400}, 1, std::nullopt, rgbColour(0, 0, 255));  // a blue wall ahead
  for (int x = 401; x <= 700; ++x) both.on(event(RobotEvent::Move, {double(x), 300}, false, 3), 20);
  CHECK_FALSE(both.watch.touches()[0].touched);
  REQUIRE(both.watch.touches()[1].touched);
  CHECK(both.watch.touches()[1].at == P2{430, 300});
  CHECK(both.agree());
}

TEST_CASE("colour watch: the robot's own trail counts only while the pen is up", "[grade][colour]") {
  Canvas canvas;
  Both both(canvas, {colourToRgb(colours::kGreen)});
  both.on(event(RobotEvent::Locate, {200, 300}, true, 1), 20);
  canvas.trailStart(200, 300, 3, colours::kGreen);
  for (int x = 201; x <= 300; ++x) {
    canvas.trailTo(x, 300);
    both.on(event(RobotEvent::Move, {double(x), 300}, true, 2), 20);
  }
  CHECK_FALSE(both.watch.touches()[0].touched);
  canvas.trailEnd();
  both.on(event(RobotEvent::Pen, {300, 300}, false, 3), 20);
  both.on(event(RobotEvent::Move, {300, 310}, false, 4), 20);
  REQUIRE(both.watch.touches()[0].touched);
  CHECK(both.watch.touches()[0].at == P2{300, 300});
  CHECK(both.agree());
}

TEST_CASE("colour watch: colours compare as the screen shows them, a colour given twice has two touches",
          "[grade][colour]") {
  Canvas canvas;
  canvas.setPixel(420, 300, rgbColour(255, 0, 0));  // RGB(255, 0, 0) is Red on the screen
  ColourWatch watch(canvas, {0xFF0000, 0x0000FF, 0xFF0000});
  watch.robotEvent(event(RobotEvent::Locate, {400, 300}, false, 7), 20);
  CHECK(watch.touches()[0].touched);
  CHECK_FALSE(watch.touches()[1].touched);
  CHECK(watch.touches()[2].touched);
  CHECK(watch.touches()[2].at == P2{400, 300});
}

TEST_CASE("colour watch: a world's placement starts the path without being a move", "[grade][colour]") {
  Canvas canvas;
  canvas.setPixel(400, 300, colours::kBlack);
  Both both(canvas, {0x000000});
  both.watch.startAt({400, 310});
  both.reference.startAt({400, 310});
  CHECK_FALSE(both.watch.touches()[0].touched);  // nothing looked at yet
  both.on(event(RobotEvent::Move, {500, 310}, false, 2), 20);
  REQUIRE(both.watch.touches()[0].touched);
  CHECK(both.watch.touches()[0].at == P2{400, 310});
  CHECK(both.agree());
}

TEST_CASE("colour watch: far from the colour, a long walk of short moves searches seldom", "[grade][colour]") {
  // A black wall at the top; the robot drives 2,000 moves of 0.37 px along the bottom, far
  // from it, then 740 moves of 1 px back along the wall, 16 px from its rim. Work is counted,
  // not timed.
  Canvas canvas;
  canvas.rectangle({0, 0}, {799, 9}, 1, colours::kBlack, colours::kBlack);
  ColourWatch watch(canvas, {0x000000});
  watch.robotEvent(event(RobotEvent::Locate, {30, 500}, false, 1), 20);
  for (int i = 0; i < 2000; ++i)
    watch.robotEvent(event(RobotEvent::Move, {30 + 0.37 * i, 500}, false, 2), 20);
  CHECK(watch.searches() <= 24);  // the room doubles: 16, 32, ... 256 px
  const uint64_t before = watch.searches();
  watch.robotEvent(event(RobotEvent::Locate, {770, 45}, false, 3), 20);
  for (int i = 0; i < 740; ++i) watch.robotEvent(event(RobotEvent::Move, {770.0 - i, 45}, false, 4), 20);
  CHECK_FALSE(watch.touches()[0].touched);
  CHECK(watch.searches() - before <= 55);  // one in 16 px (the room the wall leaves), about
  // Every cell was read once (the screen was new): none again.
  CHECK(watch.cellsRead() <= 100 * 75);
}

TEST_CASE("colour watch: a colour once touched is not looked at again", "[grade][colour]") {
  Canvas canvas;
  canvas.rectangle({0, 0}, {799, 599}, 1, std::nullopt, colours::kBlack);  // black everywhere
  ColourWatch watch(canvas, {0x000000});
  watch.robotEvent(event(RobotEvent::Locate, {400, 300}, false, 1), 20);
  REQUIRE(watch.touches()[0].touched);
  const uint64_t searches = watch.searches(), cells = watch.cellsRead();
  for (int i = 0; i < 100; ++i) {
    canvas.clear(colours::kBlack);
    watch.robotEvent(event(RobotEvent::Move, {400, 300.0 - i}, false, 2), 20);
  }
  CHECK(watch.searches() == searches);
  CHECK(watch.cellsRead() == cells);
}

namespace {

/// A small random generator (the tests' own, the same everywhere).
struct Random {
  uint64_t s;
  uint32_t next() {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<uint32_t>(s >> 33);
  }
  int in(int lo, int hi) { return lo + static_cast<int>(next() % static_cast<uint32_t>(hi - lo + 1)); }
  double real(double lo, double hi) { return lo + (hi - lo) * (next() / 4294967296.0); }
  bool chance(int percent) { return in(1, 100) <= percent; }
};

}  // namespace

TEST_CASE("colour watch: the same touches as the pixel-by-pixel rule on random screens and paths",
          "[grade][colour]") {
  // Random drawing between moves (small shapes near the robot and far from it, erasing, big
  // fills, clearScr in a watched colour, scrolling text, flood fills), walks that leave the
  // screen's edge, rLocate jumps, radii from 5 to 50, the pen down in a watched colour, moves
  // of length 0 and turns. After every event the watch must say what the rule says: touched
  // or not, the point and the line.
  const Colour palette[] = {colours::kBlack, colours::kRed, colours::kBlue, rgbColour(0, 0, 255),
                            colours::kGreen, colours::kYellow, colours::kWhite, rgbColour(10, 20, 30)};
  const std::vector<uint32_t> watched = {0x000000, 0xFF0000, 0x0000FF, 0x0A141E};
  int touchedLate = 0;
  for (uint64_t seed = 1; seed <= 60; ++seed) {
    Random rnd{seed};
    Canvas canvas;
    // A few sparse watched things to start with.
    for (int i = rnd.in(0, 6); i > 0; --i) {
      Colour c = palette[rnd.in(0, 7)];
      int x = rnd.in(-20, 810), y = rnd.in(-20, 610);
      canvas.rectangle({x, y}, {x + rnd.in(0, 6), y + rnd.in(0, 6)}, 1, c, c);
    }
    Both both(canvas, watched);
    P2 at{rnd.real(0, 800), rnd.real(0, 600)};
    double radius = rnd.real(5, 50);
    bool pen = false;
    if (rnd.chance(30)) {
      both.watch.startAt(at);
      both.reference.startAt(at);
    } else {
      both.on(event(RobotEvent::Locate, at, pen, 1), radius);
    }
    for (int step = 0; step < 80; ++step) {
      INFO("seed " << seed << ", step " << step);
      const int what = rnd.in(1, 100);
      if (what <= 12) {  // a small shape, often under or near the robot
        Colour c = palette[rnd.in(0, 7)];
        int x = rnd.chance(60) ? static_cast<int>(at.x) + rnd.in(-60, 60) : rnd.in(0, 799);
        int y = rnd.chance(60) ? static_cast<int>(at.y) + rnd.in(-60, 60) : rnd.in(0, 599);
        if (rnd.chance(50)) canvas.setPixel(x, y, c);
        else canvas.line({x, y}, {x + rnd.in(-30, 30), y + rnd.in(-30, 30)}, rnd.in(1, 3), c);
      } else if (what <= 16) {  // a large fill, a watched colour or the background
        Colour c = rnd.chance(50) ? colours::kWhite : palette[rnd.in(0, 7)];
        int x = rnd.in(-50, 700), y = rnd.in(-50, 500);
        canvas.rectangle({x, y}, {x + rnd.in(70, 300), y + rnd.in(70, 300)}, 1, std::nullopt, c);
      } else if (what <= 17) {
        canvas.clear(rnd.chance(70) ? colours::kWhite : palette[rnd.in(0, 7)]);
      } else if (what <= 18) {
        canvas.print("scrolling text", true);
        for (int i = 0; i < 40; ++i) canvas.print("", true);
      } else if (what <= 19) {
        canvas.floodFill(rnd.in(0, 799), rnd.in(0, 599), palette[rnd.in(0, 7)]);
      } else if (what <= 24) {  // rLocate somewhere else, maybe with another radius
        at = {rnd.real(-10, 810), rnd.real(-10, 610)};
        if (rnd.chance(50)) radius = rnd.real(5, 50);
        canvas.trailEnd();
        both.on(event(RobotEvent::Locate, at, pen, 10), radius);
      } else if (what <= 28) {  // the pen, in a colour that may be watched
        pen = !pen;
        if (pen) canvas.trailStart(at.x, at.y, rnd.in(1, 4), palette[rnd.in(0, 7)]);
        else canvas.trailEnd();
        both.on(event(RobotEvent::Pen, at, pen, 11), radius);
      } else if (what <= 31) {
        both.on(event(RobotEvent::Turn, at, pen, 12), radius);
      } else {  // a move (a crash now and then), short or long, maybe off the screen
        double len = rnd.chance(70) ? rnd.real(0, 12) : rnd.chance(10) ? 0 : rnd.real(0, 250);
        double dir = rnd.real(0, 6.283185307179586);
        P2 to{at.x + len * std::cos(dir), at.y + len * std::sin(dir)};
        if (pen) canvas.trailTo(to.x, to.y);
        at = to;
        both.on(event(rnd.chance(5) ? RobotEvent::Crash : RobotEvent::Move, at, pen, static_cast<uint32_t>(20 + step)),
                radius);
      }
      INFO("watch:     " << describe(both.watch.touches()));
      INFO("reference: " << describe(both.reference.touches));
      REQUIRE(both.agree());
    }
    for (const RunRecord::Touch& t : both.reference.touches) touchedLate += t.touched && t.line >= 40;
  }
  // The screens and paths are sparse enough that colours are touched late as well as early.
  CHECK(touchedLate >= 20);
}

TEST_CASE("colour watch: a long walk in a maze drawn as it goes agrees with the rule", "[grade][colour]") {
  // A maze of black walls drawn a wall at a time between moves, the robot walking its
  // corridors 1 px at a time and now and then grazing a wall's corner (a colour touched by a
  // hair), with its pen down in black (its own trail never counts) or up.
  for (uint64_t seed = 1; seed <= 6; ++seed) {
    Random rnd{seed * 7919};
    Canvas canvas;
    Both both(canvas, {0x000000, 0xFF0000});
    P2 at{60, 60};
    both.on(event(RobotEvent::Locate, at, false, 1), 20);
    bool pen = false;
    int walls = 0;
    for (int step = 0; step < 1500; ++step) {
      INFO("seed " << seed << ", step " << step);
      if (step % 25 == 0 && walls < 40) {
        ++walls;
        int gx = rnd.in(1, 7) * 100, gy = rnd.in(1, 5) * 100;
        bool across = rnd.chance(50);
        canvas.line({gx, gy}, {across ? gx + 100 : gx, across ? gy : gy + 100}, 4,
                    rnd.chance(90) ? colours::kBlack : colours::kRed);
      }
      if (step % 300 == 150) {
        pen = !pen;
        if (pen) canvas.trailStart(at.x, at.y, 2, colours::kBlack);
        else canvas.trailEnd();
      }
      // Along the corridors at x, y = 50, 150, ... (30 px from the walls' middle lines).
      P2 to = at;
      const int leg = (step / 200) % 4;
      to.x += leg == 0 ? 1 : leg == 2 ? -1 : 0;
      to.y += leg == 1 ? 1 : leg == 3 ? -1 : 0;
      to.x += rnd.real(-0.2, 0.2);
      to.y += rnd.real(-0.2, 0.2);
      if (pen) canvas.trailTo(to.x, to.y);
      at = to;
      both.on(event(RobotEvent::Move, at, pen, 5), 20);
      INFO("watch:     " << describe(both.watch.touches()));
      INFO("reference: " << describe(both.reference.touches));
      REQUIRE(both.agree());
    }
  }
}
