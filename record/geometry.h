#pragma once
// Plane geometry for grading robot runs: distances between a point and a path, the Hausdorff
// distance between two pen trails, regions the robot must end in. Coordinates are screen pixels
// (x right, y down), as the simulator uses them.

#include <cstddef>
#include <optional>
#include <vector>

namespace rb::record {

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

/// An axis-aligned rectangle (corners inclusive), a circle or a polygon (its inside by the
/// even-odd rule, edges included).
struct Region {
  enum Kind { Rect, Circle, Polygon } kind = Rect;
  double x1 = 0, y1 = 0, x2 = 0, y2 = 0;  ///< Rect: corners, x1 <= x2 and y1 <= y2
  double cx = 0, cy = 0, r = 0;           ///< Circle: centre and radius
  std::vector<P2> points;                 ///< Polygon: corners in order (3 or more)
};
/// How far `p` is outside the region (0 when inside or on its edge).
double outside(const Region& region, P2 p);
/// A point inside the region (its centre, or a polygon's corners' mean pulled inside): where a
/// picture writes its label.
P2 labelPoint(const Region& region);
/// True when every point of `inner` lies inside `outer` (tested on inner's outline; a circle
/// outline is sampled every degree).
bool regionInside(const Region& inner, const Region& outer);

/// The first moment a disc of `radius` moving along `path` overlaps the region (its centre
/// within `radius` of it), found on points at most `step` apart. `line`/`point` index the
/// polyline and the point that ends the segment where it happens (0 for a path's first point).
/// When never: `closest` is how near the disc's rim came (the centre's distance minus radius).
struct Reach {
  bool reached = false;
  P2 at;
  size_t line = 0, point = 0;
  double closest = 0;
};
Reach firstReach(const Polylines& path, const Region& region, double radius, double step = 0.5);

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

}  // namespace rb::record
