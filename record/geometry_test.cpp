#include "geometry.h"

#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

using namespace rb::record;

namespace {

/// The Hausdorff distance by brute force over densely sampled points of both sides.
double bruteForce(const Polylines& a, const Polylines& b) {
  auto sample = [](const Polylines& lines) {
    std::vector<P2> pts;
    for (const Polyline& l : lines) {
      if (l.size() == 1) pts.push_back(l[0]);
      for (size_t i = 1; i < l.size(); ++i)
        for (int k = 0; k <= 400; ++k) {
          double t = k / 400.0;
          pts.push_back({l[i - 1].x + (l[i].x - l[i - 1].x) * t, l[i - 1].y + (l[i].y - l[i - 1].y) * t});
        }
    }
    return pts;
  };
  double worst = 0;
  for (const P2& p : sample(a)) worst = std::max(worst, distanceToLines(p, b));
  for (const P2& p : sample(b)) worst = std::max(worst, distanceToLines(p, a));
  return worst;
}

const Polylines kSquare{{{400, 300}, {400, 180}, {520, 180}, {520, 300}, {400, 300}}};

}  // namespace

TEST_CASE("distance from a point to a segment", "[grade][geometry]") {
  CHECK(distanceToSegment({0, 5}, {-10, 0}, {10, 0}) == Approx(5));
  CHECK(distanceToSegment({13, 4}, {-10, 0}, {10, 0}) == Approx(5));  // past the end: to the end point
  CHECK(distanceToSegment({3, 4}, {0, 0}, {0, 0}) == Approx(5));      // a segment of length zero
}

TEST_CASE("Hausdorff distance of known shapes", "[grade][geometry]") {
  SECTION("the same trail is at distance 0, whichever way it was drawn") {
    Polylines reversed{{{400, 300}, {520, 300}, {520, 180}, {400, 180}, {400, 300}}};
    CHECK(hausdorff(kSquare, reversed).distance == Approx(0).margin(1e-9));
  }
  SECTION("a square missing its last side: the middle of that side is 60 px away") {
    Polylines three{{{400, 300}, {400, 180}, {520, 180}, {520, 300}}};
    HausdorffDistance h = hausdorff(three, kSquare);
    CHECK(h.distance == Approx(60).margin(0.25));
    CHECK_FALSE(h.fromA);  // the worst point is on the full square
    CHECK(h.worst.y == Approx(300));
    CHECK(h.worst.x == Approx(460).margin(0.5));
  }
  SECTION("a shifted square: the shift") {
    Polylines shifted{{{410, 300}, {410, 180}, {530, 180}, {530, 300}, {410, 300}}};
    CHECK(hausdorff(shifted, kSquare).distance == Approx(10).margin(0.25));
  }
  SECTION("an empty trail is infinitely far from a drawn one; two empty ones coincide") {
    CHECK(std::isinf(hausdorff({}, kSquare).distance));
    CHECK(std::isinf(hausdorff(kSquare, {}).distance));
    CHECK(hausdorff({}, {}).distance == 0);
  }
}

TEST_CASE("Hausdorff distance agrees with brute force on random trails", "[grade][geometry]") {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> coord(0, 300);
  for (int round = 0; round < 40; ++round) {
    auto randomLines = [&] {
      Polylines lines(1 + rng() % 2);
      for (Polyline& l : lines)
        for (int k = 0, n = 1 + static_cast<int>(rng() % 5); k < n; ++k) l.push_back({coord(rng), coord(rng)});
      return lines;
    };
    Polylines a = randomLines(), b = randomLines();
    double fast = hausdorff(a, b).distance, slow = bruteForce(a, b);
    INFO("round " << round);
    // Both sample the segments; 0.5 px steps on one side, 400 per segment on the other.
    CHECK(fast == Approx(slow).margin(0.8));
  }
}

TEST_CASE("Hausdorff distance of a trail retraced lap after lap is that of one lap",
          "[grade][geometry]") {
  // 2,000 laps of the square, each point off by a rounding error as a turning robot's would be,
  // some laps driven the other way round: the same distances as the single square.
  Polylines laps{{}};
  for (int lap = 0; lap < 2000; ++lap) {
    const double drift = (lap % 7) * 1e-9;
    Polyline one = kSquare[0];
    if (lap % 3 == 0) std::reverse(one.begin(), one.end());
    for (const P2& p : one) laps[0].push_back({p.x + drift, p.y - drift});
  }
  CHECK(hausdorff(laps, kSquare).distance == Approx(0).margin(1e-6));
  Polylines three{{{400, 300}, {400, 180}, {520, 180}, {520, 300}}};
  CHECK(hausdorff(laps, three).distance == Approx(hausdorff(kSquare, three).distance).margin(1e-6));
  Polylines shifted{{{410, 300}, {410, 180}, {530, 180}, {530, 300}, {410, 300}}};
  CHECK(hausdorff(shifted, laps).distance == Approx(hausdorff(shifted, kSquare).distance).margin(1e-6));
}

TEST_CASE("regions", "[grade][geometry]") {
  Region rect;
  rect.x1 = 380, rect.y1 = 280, rect.x2 = 420, rect.y2 = 320;
  CHECK(outside(rect, {400, 300}) == 0);
  CHECK(outside(rect, {420, 320}) == 0);  // the edge counts as inside
  CHECK(outside(rect, {430, 300}) == Approx(10));
  CHECK(outside(rect, {423, 324}) == Approx(5));  // past a corner: to the corner
  Region circle;
  circle.kind = Region::Circle;
  circle.cx = 400;
  circle.cy = 300;
  circle.r = 5;
  CHECK(outside(circle, {403, 304}) == 0);
  CHECK(outside(circle, {520, 300}) == Approx(115));
}

TEST_CASE("visiting points in order", "[grade][geometry]") {
  std::vector<P2> corners{{400, 300}, {400, 180}, {520, 180}, {520, 300}, {400, 300}};
  SECTION("the square visits every corner in order") {
    VisitResult v = visitInOrder(kSquare, corners, 3);
    CHECK_FALSE(v.missed);
  }
  SECTION("three sides miss the return to the start") {
    Polylines three{{{400, 300}, {400, 180}, {520, 180}, {520, 300}}};
    VisitResult v = visitInOrder(three, corners, 3);
    REQUIRE(v.missed);
    CHECK(*v.missed == 4);
    CHECK(v.closest == Approx(120));
    // Without order the start counts: it was visited first.
    CHECK_FALSE(visitAny(three, corners, 3).missed);
  }
  SECTION("the wrong order fails where the order breaks") {
    Polylines backwards{{{400, 300}, {520, 300}, {520, 180}, {400, 180}, {400, 300}}};
    VisitResult v = visitInOrder(backwards, corners, 3);
    REQUIRE(v.missed);
    CHECK(*v.missed == 2);  // (520, 180) after (400, 180): the path ends at the start instead
  }
  SECTION("passing within the tolerance mid-segment counts") {
    Polylines line{{{0, 0}, {100, 0}}};
    CHECK_FALSE(visitInOrder(line, {{50, 2}}, 3).missed);
    CHECK(visitInOrder(line, {{50, 4}}, 3).missed);
  }
  SECTION("a robot that never moved reaches only where it stands") {
    Polylines still{{{400, 300}}};
    VisitResult v = visitInOrder(still, corners, 3);
    REQUIRE(v.missed);
    CHECK(*v.missed == 1);
  }
}

TEST_CASE("polygon regions and reaching a region along a path", "[grade][geometry]") {
  Region tri;
  tri.kind = Region::Polygon;
  tri.points = {{100, 100}, {200, 100}, {100, 200}};
  CHECK(outside(tri, {120, 120}) == 0);
  CHECK(outside(tri, {100, 150}) == 0);  // on an edge
  CHECK(outside(tri, {200, 200}) == Approx(std::sqrt(2.0) * 50));  // to the long edge's middle
  CHECK(outside(tri, {50, 150}) == Approx(50));
  CHECK(outside(tri, labelPoint(tri)) == 0);
  Region concave;  // an L: its corners' mean lies outside
  concave.kind = Region::Polygon;
  concave.points = {{0, 0}, {100, 0}, {100, 10}, {10, 10}, {10, 100}, {0, 100}};
  CHECK(outside(concave, labelPoint(concave)) == 0);

  Region box;
  box.x1 = 300, box.y1 = 100, box.x2 = 400, box.y2 = 200;
  Polylines path{{{100, 150}, {250, 150}, {250, 400}}};
  Reach centre = firstReach(path, box, 0);
  CHECK_FALSE(centre.reached);
  CHECK(centre.closest == Approx(50));
  Reach disc = firstReach(path, box, 60);  // a disc of radius 60 reaches it at x = 240
  REQUIRE(disc.reached);
  CHECK(disc.at.x == Approx(240).margin(0.5));
  CHECK(disc.line == 0);
  CHECK(disc.point == 1);  // on the segment that ends at the path's point 1
  Polylines through{{{350, 400}, {350, 0}}};
  Reach in = firstReach(through, box, 0);
  REQUIRE(in.reached);
  CHECK(in.at.y == Approx(200).margin(0.5));

  Region small, big;
  small.kind = big.kind = Region::Circle;
  small.cx = big.cx = 400, small.cy = big.cy = 300, small.r = 10, big.r = 30;
  CHECK(regionInside(small, big));
  CHECK_FALSE(regionInside(big, small));
  CHECK(regionInside(small, box) == false);
}
