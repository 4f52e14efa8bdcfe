#pragma once
// Plane geometry for grading robot runs: distances between a point and a path, the Hausdorff
// distance between two pen trails, regions the robot must end in. Coordinates are screen pixels
// (x right, y down), as the simulator uses them.

#include <cstddef>
#include <optional>
#include <vector>

namespace rb::grade {

struct P2 {
  double x = 0, y = 0;
  friend bool operator==(const P2&, const P2&) = default;
};

/// A path: one or more polylines (a new one starts where the robot was placed again, or where
/// the pen went down again). A polyline of one point is a dot.
using Polyline = std::vector<P2>;
using Polylines = std::vector<Polyline>;

double distance(P2 a, P2 b);
/// The shortest distance from `p` to the segment a-b.
double distanceToSegment(P2 p, P2 a, P2 b);
/// The shortest distance from `p` to any point of `lines` (infinity when `lines` has no point).
double distanceToLines(P2 p, const Polylines& lines);
/// The sum of the segment lengths.
double length(const Polylines& lines);
/// True when `lines` has no point at all.
bool empty(const Polylines& lines);

/// The directed Hausdorff distance from `a` to `b`: how far the point of `a` farthest from `b`
/// is from `b`, along with that point. The segments of `a` are sampled at most `step` pixels
/// apart (plus every vertex), so the result is exact to within step / 2; distances to `b` are
/// exact (point to segment). Infinity when `b` is empty and `a` is not; 0 when `a` is empty.
struct DirectedDistance {
  double distance = 0;
  P2 worst;  ///< the point of `a` that is farthest from `b`
};
DirectedDistance directedHausdorff(const Polylines& a, const Polylines& b, double step = 0.5);

/// The Hausdorff distance between two paths: the larger of the two directed distances.
/// `fromA` tells which side the worst point lies on.
struct HausdorffDistance {
  double distance = 0;
  P2 worst;
  bool fromA = true;  ///< `worst` is a point of a (far from b), else a point of b (far from a)
};
HausdorffDistance hausdorff(const Polylines& a, const Polylines& b, double step = 0.5);

/// An axis-aligned rectangle (corners inclusive) or a circle.
struct Region {
  enum Kind { Rect, Circle } kind = Rect;
  double x1 = 0, y1 = 0, x2 = 0, y2 = 0;  ///< Rect: corners, x1 <= x2 and y1 <= y2
  double cx = 0, cy = 0, r = 0;           ///< Circle: centre and radius
};
/// How far `p` is outside the region (0 when inside or on its edge).
double outside(const Region& region, P2 p);

/// Visiting points in order: for each target, the first moment the path comes within
/// `tolerance` of it, searched from where the previous target was reached. Returns the index of
/// the first target never reached (nullopt when all are), with the closest the path came to it
/// after the previous target (`closest`).
struct VisitResult {
  std::optional<size_t> missed;
  double closest = 0;
};
VisitResult visitInOrder(const Polylines& path, const std::vector<P2>& targets, double tolerance);
/// The same without order: each target on its own.
VisitResult visitAny(const Polylines& path, const std::vector<P2>& targets, double tolerance);

}  // namespace rb::grade
