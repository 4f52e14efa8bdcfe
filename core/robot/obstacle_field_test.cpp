#include <catch2/catch.hpp>

#include <cmath>

#include "robot/obstacle_field.h"
#include "base/rng.h"

using namespace rb;

namespace {
/// The distance from (x, y) to the nearest obstacle pixel or wall pixel, the slow way.
double bruteDistance(const Canvas& c, int x, int y) {
  double best = std::min({x + 1, y + 1, Canvas::kWidth - x, Canvas::kHeight - y});
  for (int yy = 0; yy < Canvas::kHeight; ++yy)
    for (int xx = 0; xx < Canvas::kWidth; ++xx)
      if (c.isObstacleColour(c.at(xx, yy))) best = std::min(best, std::hypot(xx - x, yy - y));
  return best;
}
}  // namespace

TEST_CASE("the obstacle field equals the brute-force distance", "[sim]") {
  Canvas canvas;
  Rng rng(3);
  for (int i = 0; i < 40; ++i) {
    int x = static_cast<int>(rng.below(800)), y = static_cast<int>(rng.below(600));
    canvas.setPixel(x, y, colours::kBlack);
  }
  canvas.rectangle({300, 200}, {340, 260}, 1, colours::kRed, colours::kRed);
  ObstacleField field(canvas);
  for (int i = 0; i < 60; ++i) {
    int x = static_cast<int>(rng.below(800)), y = static_cast<int>(rng.below(600));
    INFO("pixel " << x << "," << y);
    CHECK(field.distance(x, y) == Approx(bruteDistance(canvas, x, y)).margin(1e-3));
    CHECK(field.obstacle(x, y) == canvas.isObstacle(x, y));
  }
}

TEST_CASE("the obstacle field follows the invisible colours and redraws", "[sim]") {
  Canvas canvas;
  ObstacleField field(canvas);
  CHECK(field.distance(400, 300) == Approx(300));  // the wall above and below: 301 to the nearer
  canvas.line({400, 250}, {500, 250}, 1, colours::kGreen);
  CHECK(field.distance(400, 300) == Approx(50));
  canvas.setInvisible({colours::kGreen});
  CHECK(field.distance(400, 300) == Approx(300));
  CHECK_FALSE(field.obstacle(450, 250));
  CHECK(field.obstacle(-1, 0));
}

TEST_CASE("the obstacle field catches up locally with a few new obstacle pixels", "[sim]") {
  Canvas canvas;
  canvas.rectangle({300, 200}, {340, 260}, 1, colours::kRed, colours::kRed);
  ObstacleField field(canvas);
  CHECK(field.distance(400, 300) == Approx(std::hypot(60, 40)));
  Rng rng(5);
  // A trail drawn a little at a time, the way the robot's pen draws in an obstacle colour.
  Point at{500, 400};
  for (int i = 0; i < 30; ++i) {
    uint64_t before = canvas.obstacleVersion();
    Point to{at.x + static_cast<int>(rng.below(5)) - 2, at.y - 3};
    canvas.line(at, to, 3, colours::kBlack);
    field.changedWithin(std::min(at.x, to.x) - 3, std::min(at.y, to.y) - 3, std::max(at.x, to.x) + 3,
                        std::max(at.y, to.y) + 3, before);
    at = to;
  }
  for (int i = 0; i < 200; ++i) {
    int x = 400 + static_cast<int>(rng.below(200)), y = 250 + static_cast<int>(rng.below(200));
    INFO("pixel " << x << "," << y);
    double truth = bruteDistance(canvas, x, y);
    CHECK(field.obstacle(x, y) == canvas.isObstacle(x, y));
    // Exact within the local reach, and never more than the truth.
    if (truth < ObstacleField::kLocalReach) CHECK(field.distance(x, y) == Approx(truth).margin(1e-3));
    CHECK(field.distance(x, y) <= truth + 1e-3);
  }
  // Anything else (here: erasing) makes the next query rebuild, exact again everywhere.
  canvas.rectangle({300, 200}, {340, 260}, 1, colours::kWhite, colours::kWhite);
  CHECK(field.distance(320, 230) == Approx(bruteDistance(canvas, 320, 230)).margin(1e-3));
  CHECK(field.distance(100, 300) == Approx(101));
}
