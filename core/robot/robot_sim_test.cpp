// The collision model (docs/robot.md, "Collisions"): the robot crashes when the quadrant of its
// rim that leads the motion sweeps over an obstacle; a bumper check of that quadrant always
// fires first; turning never crashes; an obstacle already inside the disc is left behind.
// Also rLocate at the screen's edge and the pen trail as an obstacle.

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "base/rng.h"
#include "base/runtime_error.h"
#include "robot/robot_sim.h"
#include "robot/sim_constants.h"

using namespace rb;

namespace {

struct World {
  Canvas canvas;
  Rng rng{1};
  SimRobot robot{canvas, rng};
  World() { canvas.keepDisplayList(true); }
};

/// Drives forward one pixel at a time while the front bumper is free; returns the steps taken.
int driveToBumper(SimRobot& robot, int limit = 2000) {
  int steps = 0;
  while ((robot.bumper() & sim::kBumperFront) == 0 && steps < limit) {
    robot.forward(1, nullptr);
    ++steps;
  }
  return steps;
}

double uniform(Rng& rng, double lo, double hi) { return lo + (hi - lo) * rng.unit(); }

/// Random obstacles of every kind the labs draw: boxes, discs, thick and thin lines at any
/// angle, thin spikes and lone pixels.
void drawRandomArena(Canvas& canvas, Rng& rng) {
  auto pt = [&] { return Point{static_cast<int>(rng.below(800)), static_cast<int>(rng.below(600))}; };
  for (int i = 0; i < 3; ++i) {
    Point a = pt();
    Point b{a.x + 10 + static_cast<int>(rng.below(120)), a.y + 10 + static_cast<int>(rng.below(120))};
    canvas.rectangle(a, b, 1, colours::kBlack, colours::kBlack);
  }
  for (int i = 0; i < 2; ++i) {
    Point a = pt();
    int d = 10 + static_cast<int>(rng.below(90));
    canvas.ellipse(a, {a.x + d, a.y + d}, 1, colours::kRed, colours::kRed);
  }
  for (int i = 0; i < 4; ++i) canvas.line(pt(), pt(), 1 + static_cast<int>(rng.below(6)), colours::kBlue);
  for (int i = 0; i < 3; ++i) {
    Point tip = pt();
    double a = uniform(rng, 0, 2 * std::numbers::pi), len = uniform(rng, 40, 160);
    Point base{tip.x + static_cast<int>(len * std::cos(a)), tip.y + static_cast<int>(len * std::sin(a))};
    int w = 2 + static_cast<int>(rng.below(10));
    int ox = static_cast<int>(-w * std::sin(a)), oy = static_cast<int>(w * std::cos(a));
    canvas.polygon({tip, {base.x + ox, base.y + oy}, {base.x - ox, base.y - oy}}, 1, colours::kBlack,
                   colours::kBlack);
  }
  for (int i = 0; i < 20; ++i) {
    Point p = pt();
    canvas.setPixel(p.x, p.y, colours::kMagenta);
  }
}

}  // namespace

TEST_CASE("sim: driving straight into a wall crashes where the front rim reaches it", "[sim]") {
  World w;
  w.canvas.rectangle({0, 0}, {799, 100}, 1, colours::kBlack, colours::kBlack);
  w.robot.locate(400, 300, 0, 20, colours::kBlue);
  CHECK_THROWS_WITH(w.robot.forward(300, nullptr), Catch::Matchers::StartsWith("robot crashed into an obstacle"));
  // Pixel row 100 would be inside the disc at y = 120: the robot stays at 121.
  CHECK(w.robot.gpsY() == 121);
  CHECK((w.robot.bumper() & sim::kBumperFront) != 0);
  // Backing away is free; backing into a wall crashes on the rear quadrant.
  w.robot.forward(-50, nullptr);
  w.robot.turn(180, nullptr);
  CHECK_THROWS_WITH(w.robot.forward(-300, nullptr), Catch::Matchers::StartsWith("robot crashed into an obstacle"));
  CHECK(w.robot.gpsY() == 121);
  CHECK((w.robot.bumper() & sim::kBumperRear) != 0);
}

TEST_CASE("sim: a front-bumper check stops the robot one step before any crash", "[sim]") {
  World w;
  w.canvas.rectangle({300, 100}, {500, 120}, 1, colours::kBlack, colours::kBlack);
  w.robot.locate(400, 300, 0, 20, colours::kBlue);
  CHECK_NOTHROW(driveToBumper(w.robot));
  CHECK(w.robot.gpsY() == 142);
  CHECK_NOTHROW(w.robot.forward(1, nullptr));    // the bumper reaches 2 px past the rim
  CHECK_THROWS(w.robot.forward(1, nullptr));     // the rim itself
}

TEST_CASE("sim: grazing a wall at a shallow angle presses a side bumper but does not crash", "[sim]") {
  World w;
  w.canvas.rectangle({0, 400}, {799, 599}, 1, colours::kBlack, colours::kBlack);
  // Heading 92: moving right, drifting down into the wall by 2 degrees.
  w.robot.locate(60, 375, 92, 20, colours::kBlue);
  bool sidePressed = false;
  int steps = 0;
  REQUIRE_NOTHROW([&] {
    while ((w.robot.bumper() & sim::kBumperFront) == 0 && steps < 1000) {
      if (w.robot.bumper() & sim::kBumperRight) sidePressed = true;
      w.robot.forward(1, nullptr);
      ++steps;
    }
  }());
  CHECK(sidePressed);
  CHECK(steps < 1000);
  // The wall entered the disc through its side: the robot overlaps it a little.
  CHECK(w.robot.collides(w.robot.pose().pos));
  CHECK(w.robot.gpsY() > 380);
  // Turning away and driving off is free.
  w.robot.turn(-150, nullptr);
  CHECK_NOTHROW(w.robot.forward(100, nullptr));
  CHECK_FALSE(w.robot.collides(w.robot.pose().pos));
}

TEST_CASE("sim: turning in place never crashes, even with an obstacle inside the disc", "[sim]") {
  World w;
  w.robot.locate(400, 300, 0, 20, colours::kBlue);
  // Something drawn over the robot's right half after it was placed.
  w.canvas.rectangle({405, 270}, {430, 330}, 1, colours::kBlack, colours::kBlack);
  CHECK(w.robot.collides(w.robot.pose().pos));
  for (int i = 0; i < 36; ++i) CHECK_NOTHROW(w.robot.turn(10, nullptr));
  // Facing away from it, the robot drives away; facing it, it cannot drive on.
  w.robot.turn(-90, nullptr);
  CHECK((w.robot.bumper() & sim::kBumperRear) != 0);
  CHECK_NOTHROW(w.robot.forward(40, nullptr));
  CHECK(w.robot.gpsX() == 360);
  w.robot.forward(-18, nullptr);  // back up until the box is at the rear rim again
  CHECK_THROWS(w.robot.forward(-10, nullptr));
}

TEST_CASE("sim: a thin line drawn across the robot is left behind", "[sim]") {
  World w;
  w.robot.locate(400, 300, 0, 20, colours::kBlue);
  w.canvas.line({350, 300}, {450, 300}, 1, colours::kBlack);
  CHECK_NOTHROW(w.robot.forward(60, nullptr));
  CHECK(w.robot.gpsY() == 240);
}

TEST_CASE("sim: the robot's own trail is harmless until it drives back over it", "[sim]") {
  World w;
  w.canvas.lineWidth = 4;
  w.robot.locate(400, 300, 0, 20, colours::kBlue);
  w.robot.setPen(true);  // no invisible colour: the trail is black, an obstacle
  for (int side = 0; side < 3; ++side) {
    CHECK_NOTHROW(w.robot.forward(120, nullptr));
    w.robot.turn(90, nullptr);
  }
  CHECK_THROWS_WITH(w.robot.forward(120, nullptr), Catch::Matchers::StartsWith("robot crashed into an obstacle"));
  // The front rim met the first side's trail (x 398..401).
  CHECK(w.robot.gpsX() == 422);
  CHECK(w.robot.gpsY() == 300);
}

TEST_CASE("sim: the trail drawn step by step matches a trail drawn per move", "[sim]") {
  // A live view draws the trail at every step; headless runs draw it per move unless it is an
  // obstacle. Either way the robot ends where the obstacle field says.
  for (bool live : {false, true}) {
    World w;
    w.canvas.lineWidth = 3;
    w.robot.locate(200, 200, 90, 20, colours::kBlue);
    w.robot.setPen(true);
    std::function<void()> step = [] {};
    w.robot.forward(200, live ? step : nullptr);
    w.robot.turn(90, nullptr);
    w.robot.forward(100, live ? step : nullptr);
    w.robot.turn(90, nullptr);
    w.robot.forward(100, live ? step : nullptr);
    w.robot.turn(90, nullptr);
    CHECK_THROWS(w.robot.forward(200, live ? step : nullptr));
    // The first side's trail covers rows 199..201: the rim stops short of row 201.
    CHECK(w.robot.gpsY() == 222);
    CHECK(w.canvas.at(300, 200) == colours::kBlack);
  }
}

TEST_CASE("sim: the front bumper fires first into corners and walls from every heading", "[sim]") {
  // From one place, every heading in half-degree steps: into the screen's corners and walls, a
  // box's convex corners and an L-shaped concave corner, with whole steps and with 0.7 px ones.
  for (double step : {1.0, 0.7}) {
    World w;
    w.canvas.rectangle({150, 120}, {260, 200}, 1, colours::kBlack, colours::kBlack);
    w.canvas.rectangle({520, 380}, {700, 400}, 1, colours::kBlack, colours::kBlack);
    w.canvas.rectangle({680, 250}, {700, 400}, 1, colours::kBlack, colours::kBlack);
    w.canvas.line({300, 500}, {560, 520}, 4, colours::kBlack);
    for (double h = 0; h < 360; h += 0.5) {
      w.robot.locate(400, 300, h, 20, colours::kBlue);
      int steps = 0;
      INFO("heading " << h << " step " << step);
      REQUIRE_NOTHROW([&] {
        while ((w.robot.bumper() & sim::kBumperFront) == 0 && steps < 2000) {
          w.robot.forward(step, nullptr);
          ++steps;
        }
      }());
      CHECK(steps < 2000);
    }
  }
}

TEST_CASE("sim: the front bumper fires before any forward crash, in random arenas", "[sim]") {
  // Random walks that check the bumper of the leading quadrant before every step: forward and
  // backward, whole and partial steps, random turns (large and tiny, so the robot grazes walls
  // at shallow angles and slides into corners), radii from 5 to 50. None may crash.
  int steps = 0, bumps = 0;
  for (uint64_t trial = 0; trial < 60; ++trial) {
    World w;
    w.rng.reseed(trial);
    drawRandomArena(w.canvas, w.rng);
    double radius = trial % 3 == 0 ? 20 : uniform(w.rng, sim::kMinRadius, sim::kMaxRadius);
    bool placed = false;
    for (int attempt = 0; attempt < 500 && !placed; ++attempt) {
      try {
        w.robot.locate(uniform(w.rng, 0, 800), uniform(w.rng, 0, 600), uniform(w.rng, 0, 360), radius,
                       colours::kBlue);
        placed = true;
      } catch (const RuntimeError&) {
      }
    }
    if (!placed) continue;
    for (int move = 0; move < 4000; ++move) {
      double r = w.rng.unit();
      if (r < 0.03) {
        w.robot.turn(uniform(w.rng, -180, 180), nullptr);
        continue;
      }
      if (r < 0.10) {
        w.robot.turn(uniform(w.rng, -3, 3), nullptr);
        continue;
      }
      bool back = w.rng.unit() < 0.2;
      double d = w.rng.unit() < 0.7 ? 1.0 : uniform(w.rng, 0.01, 1.0);
      int leading = back ? sim::kBumperRear : sim::kBumperFront;
      if (w.robot.bumper() & leading) {
        ++bumps;
        w.robot.turn(uniform(w.rng, 120, 180), nullptr);
        continue;
      }
      Pose before = w.robot.pose();
      INFO("trial " << trial << " radius " << radius << " at " << before.pos.x() << "," << before.pos.y()
                    << " heading " << before.heading << " step " << (back ? -d : d));
      REQUIRE_NOTHROW(w.robot.forward(back ? -d : d, nullptr));
      ++steps;
    }
  }
  CHECK(steps > 100000);
  CHECK(bumps > 1000);
}

TEST_CASE("sim: without a bumper check the robot does crash in random arenas", "[sim]") {
  // The model is not toothless: driving blind ends in a crash, into the wall if nothing else.
  int crashes = 0;
  for (uint64_t trial = 0; trial < 20; ++trial) {
    World w;
    w.rng.reseed(trial + 100);
    drawRandomArena(w.canvas, w.rng);
    try {
      w.robot.locate(uniform(w.rng, 0, 800), uniform(w.rng, 0, 600), uniform(w.rng, 0, 360), 20, colours::kBlue);
    } catch (const RuntimeError&) {
      continue;
    }
    try {
      w.robot.forward(1000, nullptr);
    } catch (const RuntimeError&) {
      ++crashes;
      CHECK((w.robot.bumper() & sim::kBumperFront) != 0);
    }
  }
  CHECK(crashes > 5);
}

TEST_CASE("sim: a robot edging around a spike's tip can still hit it", "[sim]") {
  // A thin spike pointing left, its tip at (400, 300). The robot has followed its lower edge
  // leftward past the tip and turns right to go around it: the tip is near its front-right.
  World w;
  w.canvas.polygon({{400, 300}, {600, 292}, {600, 308}}, 1, colours::kBlack, colours::kBlack);
  w.robot.locate(390, 318, 270, 20, colours::kBlue);
  CHECK_NOTHROW(w.robot.turn(90, nullptr));  // turning never crashes, even this close
  CHECK((w.robot.bumper() & sim::kBumperFront) != 0);
  CHECK_THROWS_WITH(w.robot.forward(10, nullptr), Catch::Matchers::StartsWith("robot crashed into an obstacle"));
}

TEST_CASE("sim: rLocate off the screen puts the robot just inside, touching the edge", "[sim]") {
  World w;
  w.robot.locate(110, 600, 0, 20, colours::kBlue);
  CHECK(w.robot.gpsX() == 110);
  CHECK(w.robot.gpsY() == 579);
  CHECK((w.robot.bumper() & sim::kBumperRear) != 0);
  w.robot.locate(-50, -50, 0, 30, colours::kBlue);
  CHECK(w.robot.pose().pos == Eigen::Vector2d(30, 30));
  w.robot.locate(2000, 300, 0, 5, colours::kBlue);
  CHECK(w.robot.pose().pos == Eigen::Vector2d(794, 300));
  // Touching the edge is not overlapping it: the robot drives away from it.
  CHECK_NOTHROW(w.robot.forward(-10, nullptr));
  CHECK_THROWS_WITH(w.robot.locate(NAN, 300, 0, 20, colours::kBlue), Catch::Contains("not a number"));
  // Over a drawn obstacle it stays an error, after moving inside.
  w.canvas.rectangle({0, 560}, {200, 599}, 1, colours::kBlack, colours::kBlack);
  CHECK_THROWS_WITH(w.robot.locate(110, 600, 0, 20, colours::kBlue),
                    "rLocate: the robot at (110, 600) would overlap an obstacle");
  CHECK(w.robot.gpsX() == 794);  // unchanged
}

TEST_CASE("sim: the trail continues across other drawing", "[sim]") {
  World w;
  w.canvas.setInvisible({colours::kGreen});
  w.robot.locate(400, 300, 0, 20, colours::kBlue);
  w.robot.setPen(true);
  for (int i = 0; i < 50; ++i) {
    w.canvas.text(10, 10, std::to_string(i), TextStyle{}, colours::kBlack);
    w.robot.forward(1, nullptr);
  }
  for (int y = 251; y <= 300; ++y) CHECK(w.canvas.at(400, y) == colours::kGreen);
  // In the display list the trail is pieces that join end to end.
  std::vector<const DrawOp*> pieces;
  for (const DrawOp& op : w.canvas.displayList())
    if (op.kind == DrawOp::Trail) pieces.push_back(&op);
  REQUIRE(pieces.size() >= 2);
  CHECK(pieces.front()->points.front() == Point{400, 300});
  CHECK(pieces.back()->points.back() == Point{400, 250});
  for (size_t i = 1; i < pieces.size(); ++i) CHECK(pieces[i]->points.front() == pieces[i - 1]->points.back());
  // A new width starts a new piece where the last one ended.
  w.canvas.lineWidth = 5;
  w.robot.forward(20, nullptr);
  CHECK(w.canvas.displayList().back().points == std::vector<Point>{{400, 250}, {400, 230}});
  CHECK(w.canvas.displayList().back().width == 5);
}
