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

TEST_CASE("local updates of the obstacle field agree with a full rebuild on random drawings", "[sim]") {
  // The same drawings on two canvases: the field under test follows its canvas by region and
  // lazily; the reference rebuilds from scratch before every query.
  Canvas a, b;
  ObstacleField field(a), reference(b);
  Rng rng(11);
  auto both = [&](auto draw) { draw(a), draw(b); };
  both([](Canvas& c) { c.rectangle({300, 200}, {340, 260}, 1, colours::kRed, colours::kRed); });
  const float reach = float(ObstacleField::kLocalReach);
  for (int round = 0; round < 40; ++round) {
    // A few small drawings: lines, boxes, text, and erasing with the background.
    for (int k = 0; k < 3; ++k) {
      int x = static_cast<int>(rng.below(760)), y = static_cast<int>(rng.below(570));
      switch (rng.below(4)) {
        case 0: both([&](Canvas& c) { c.line({x, y}, {x + 20, y + 7}, 3, colours::kBlack); }); break;
        case 1: both([&](Canvas& c) { c.rectangle({x, y}, {x + 15, y + 10}, 1, colours::kBlue, colours::kBlue); }); break;
        case 2: both([&](Canvas& c) { c.text(x, y, "step " + std::to_string(round), TextStyle{}, colours::kBlack); }); break;
        default: both([&](Canvas& c) { c.rectangle({x, y}, {x + 40, y + 30}, 1, colours::kWhite, colours::kWhite); }); break;
      }
    }
    b.setInvisible(b.invisible());  // the reference: changed everywhere, so rebuilt
    for (int i = 0; i < 25; ++i) {
      int x = static_cast<int>(rng.below(800)), y = static_cast<int>(rng.below(600));
      INFO("round " << round << ", pixel " << x << "," << y);
      float got = field.distance(x, y), truth = reference.distance(x, y);
      CHECK(field.obstacle(x, y) == reference.obstacle(x, y));
      CHECK(got <= truth + 1e-3f);                                    // never more than the truth
      CHECK(std::min(got, reach) == Approx(std::min(truth, reach)).margin(1e-3));  // exact below the cap
    }
  }
  CHECK(field.localUpdates() > 0);
  CHECK(field.rebuilds() < 5);  // small drawings never rebuild the whole field
}

TEST_CASE("a change far from every query is never computed", "[sim]") {
  Canvas canvas;
  ObstacleField field(canvas);
  CHECK(field.distance(400, 300) == Approx(300));
  uint64_t rebuilt = field.rebuilds();
  for (int i = 0; i < 100; ++i) {  // a status line redrawn in a loop, far from the robot
    canvas.text(10, 10, "step " + std::to_string(i), TextStyle{}, colours::kBlack);
    CHECK(field.distance(400, 300) == Approx(ObstacleField::kLocalReach));  // capped, a lower bound
  }
  CHECK(field.rebuilds() == rebuilt);
  CHECK(field.localUpdates() == 0);
  // Near the text the distances are exact. Text drawn without a background over itself only
  // adds ink, so its pixels are a list of added pixels and no local update is needed.
  CHECK(field.distance(30, 60) == Approx(bruteDistance(canvas, 30, 60)).margin(1e-3));
  CHECK(field.distance(30, 60) == Approx(30).margin(16));
  CHECK(field.localUpdates() == 0);
  // Text over an opaque background also clears pixels: then the box waits for a local update,
  // computed once a query comes near.
  TextStyle opaque;
  opaque.background = colours::kWhite;
  for (int i = 0; i < 10; ++i) canvas.text(10, 10, "step " + std::to_string(i), opaque, colours::kBlack);
  CHECK(field.distance(400, 300) == Approx(ObstacleField::kLocalReach));
  CHECK(field.localUpdates() == 0);
  CHECK(field.distance(30, 60) == Approx(bruteDistance(canvas, 30, 60)).margin(1e-3));
  CHECK(field.localUpdates() == 1);
}

TEST_CASE("a trail that only adds obstacle pixels is followed without local updates", "[sim]") {
  // The robot's pen trail in an obstacle colour, drawn a pixel at a time: each step's few new
  // pixels join a list, and the distances near them are the rebuilt field's, exactly.
  Canvas a, b;
  ObstacleField field(a), reference(b);
  auto both = [&](auto draw) { draw(a), draw(b); };
  CHECK(field.distance(400, 300) == Approx(300));
  const float reach = float(ObstacleField::kLocalReach);
  auto agree = [&](int x, int y) {
    b.setInvisible(b.invisible());  // the reference rebuilds
    INFO("pixel " << x << "," << y);
    float got = field.distance(x, y), truth = reference.distance(x, y);
    CHECK(got <= truth + 1e-3f);
    CHECK(std::min(got, reach) == std::min(truth, reach));  // the same float below the cap
    CHECK(field.obstacle(x, y) == reference.obstacle(x, y));
  };
  int x = 400, y = 300;
  both([&](Canvas& c) { c.trailStart(x, y, 4, colours::kBlack); });
  for (int i = 0; i < 120; ++i) {
    --y;
    both([&](Canvas& c) { c.trailTo(x, y); });
    agree(x, y - 20);
    agree(x + 7, y + 3);
    agree(x - 30, y - 40);
  }
  CHECK(field.localUpdates() == 0);
  CHECK(field.freshPixels() > 0);
  // The list is bounded: a long trail becomes a local update of its box.
  for (int i = 0; i < 400; ++i) {
    ++x;
    both([&](Canvas& c) { c.trailTo(x, y); });
    agree(x + 20, y);
  }
  CHECK(field.localUpdates() > 0);
  CHECK(field.freshPixels() <= ObstacleField::kMaxFresh);
  // Erasing part of the trail makes distances grow again.
  both([&](Canvas& c) { c.rectangle({x - 60, y - 10}, {x + 2, y + 10}, 1, colours::kWhite, colours::kWhite); });
  agree(x - 30, y);
  agree(x - 30, y - 12);
  agree(x + 10, y);
}
