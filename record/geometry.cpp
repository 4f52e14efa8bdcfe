#include "geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

namespace rb::record {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Segment {
  P2 a, b;
};

/// Every segment of `lines`; a polyline of one point is a segment of length zero.
std::vector<Segment> segments(const Polylines& lines) {
  std::vector<Segment> out;
  for (const Polyline& l : lines) {
    if (l.size() == 1) out.push_back({l[0], l[0]});
    for (size_t i = 1; i < l.size(); ++i) out.push_back({l[i - 1], l[i]});
  }
  return out;
}

/// The segments of `lines` in their order, each once: a segment drawn again in either direction
/// (a robot going round the same square lap after lap) is kept only where it first appears.
/// Endpoints count as equal when they agree to a millionth of a pixel, so that laps whose
/// positions drift by rounding errors are still one; the Hausdorff distance changes by less.
std::vector<Segment> distinctSegments(const Polylines& lines) {
  std::vector<Segment> all = segments(lines);
  struct Key {
    std::array<double, 4> ends;
    size_t index;
  };
  auto rounded = [](double v) { return std::nearbyint(v * 1e6); };
  std::vector<Key> keys;
  keys.reserve(all.size());
  for (size_t i = 0; i < all.size(); ++i) {
    std::array<double, 2> a{rounded(all[i].a.x), rounded(all[i].a.y)}, b{rounded(all[i].b.x), rounded(all[i].b.y)};
    if (b < a) std::swap(a, b);
    keys.push_back({{a[0], a[1], b[0], b[1]}, i});
  }
  std::sort(keys.begin(), keys.end(), [](const Key& x, const Key& y) {
    return x.ends != y.ends ? x.ends < y.ends : x.index < y.index;
  });
  std::vector<bool> keep(all.size(), false);
  for (size_t k = 0; k < keys.size(); ++k)
    if (k == 0 || keys[k].ends != keys[k - 1].ends) keep[keys[k].index] = true;
  std::vector<Segment> out;
  for (size_t i = 0; i < all.size(); ++i)
    if (keep[i]) out.push_back(all[i]);
  return out;
}

/// Points along every segment at most `step` apart, ends included.
std::vector<P2> samples(const std::vector<Segment>& segs, double step) {
  std::vector<P2> out;
  for (const Segment& s : segs) {
    P2 a = s.a, b = s.b;
    out.push_back(a);
    double len = distance(a, b);
    int n = static_cast<int>(std::min(std::ceil(len / step), 1e7));
    for (int k = 1; k <= n; ++k) {
      double t = static_cast<double>(k) / n;
      out.push_back({a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t});
    }
  }
  return out;
}

/// The smallest t in [t0, 1] where the point a + t (b - a) lies within `tol` of p, or -1.
double firstWithin(P2 a, P2 b, double t0, P2 p, double tol) {
  double dx = b.x - a.x, dy = b.y - a.y;
  double fx = a.x - p.x, fy = a.y - p.y;
  double qa = dx * dx + dy * dy;
  double qb = 2 * (fx * dx + fy * dy);
  double qc = fx * fx + fy * fy - tol * tol;
  if (qa == 0) return qc <= 0 ? t0 : -1;
  double disc = qb * qb - 4 * qa * qc;
  if (disc < 0) return -1;
  double root = std::sqrt(disc);
  double lo = (-qb - root) / (2 * qa), hi = (-qb + root) / (2 * qa);
  if (hi < t0 || lo > 1) return -1;
  return std::max(lo, t0);
}

P2 lerp(P2 a, P2 b, double t) { return {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t}; }

}  // namespace

double distance(P2 a, P2 b) { return std::hypot(a.x - b.x, a.y - b.y); }

double distanceToSegment(P2 p, P2 a, P2 b) {
  double dx = b.x - a.x, dy = b.y - a.y;
  double len2 = dx * dx + dy * dy;
  if (len2 == 0) return distance(p, a);
  double t = ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2;
  t = std::clamp(t, 0.0, 1.0);
  return distance(p, lerp(a, b, t));
}

double distanceToLines(P2 p, const Polylines& lines) {
  double best = kInf;
  for (const Segment& s : segments(lines)) best = std::min(best, distanceToSegment(p, s.a, s.b));
  return best;
}

double length(const Polylines& lines) {
  double total = 0;
  for (const Polyline& l : lines)
    for (size_t i = 1; i < l.size(); ++i) total += distance(l[i - 1], l[i]);
  return total;
}

bool empty(const Polylines& lines) {
  return std::all_of(lines.begin(), lines.end(), [](const Polyline& l) { return l.empty(); });
}

namespace {
/// directedHausdorff on the distinct segments of both sides (distinctSegments).
DirectedDistance directed(const std::vector<Segment>& a, const std::vector<Segment>& segs, double step) {
  DirectedDistance result;
  std::vector<P2> points = samples(a, step > 0 ? step : 0.5);
  if (points.empty()) return result;
  if (segs.empty()) return {kInf, points[0]};
  // Visit the samples in a scattered order: once a far point sets the running maximum, most
  // other samples find a segment nearer than it at once and stop early (Taha and Hanbury's
  // early break). The order is a fixed permutation, so ties resolve the same on every run.
  size_t n = points.size();
  size_t stride = static_cast<size_t>(static_cast<double>(n) * 0.618033988749895) | 1;
  while (std::gcd(stride, n) != 1) stride += 2;
  double worst = -1;
  size_t index = 0;
  for (size_t k = 0; k < n; ++k, index = (index + stride) % n) {
    P2 p = points[index];
    double nearest = kInf;
    for (const Segment& s : segs) {
      nearest = std::min(nearest, distanceToSegment(p, s.a, s.b));
      if (nearest <= worst) break;
    }
    if (nearest > worst) {
      worst = nearest;
      result.worst = p;
    }
  }
  result.distance = worst;
  return result;
}
}  // namespace

// A trail retraced many times (a program that loops until its step limit) is compared once:
// repeated segments add no point to either side. Each side's distinct segments are found once.
DirectedDistance directedHausdorff(const Polylines& a, const Polylines& b, double step) {
  return directed(distinctSegments(a), distinctSegments(b), step);
}

HausdorffDistance hausdorff(const Polylines& a, const Polylines& b, double step) {
  if (empty(a) && empty(b)) return {};
  const std::vector<Segment> sa = distinctSegments(a), sb = distinctSegments(b);
  DirectedDistance ab = directed(sa, sb, step), ba = directed(sb, sa, step);
  if (empty(a)) return {kInf, ba.worst, false};
  if (ab.distance >= ba.distance) return {ab.distance, ab.worst, true};
  return {ba.distance, ba.worst, false};
}

namespace {
/// Even-odd rule: a ray to the right crosses the outline an odd number of times.
bool insidePolygon(const std::vector<P2>& pts, P2 p) {
  bool in = false;
  for (size_t i = 0, j = pts.size() - 1; i < pts.size(); j = i++) {
    const P2 &a = pts[i], &b = pts[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) in = !in;
  }
  return in;
}

std::vector<P2> outline(const Region& g) {
  switch (g.kind) {
    case Region::Rect: return {{g.x1, g.y1}, {g.x2, g.y1}, {g.x2, g.y2}, {g.x1, g.y2}};
    case Region::Circle: {
      std::vector<P2> out;
      for (int d = 0; d < 360; ++d) {
        double a = d * 3.14159265358979323846 / 180;
        out.push_back({g.cx + g.r * std::cos(a), g.cy + g.r * std::sin(a)});
      }
      return out;
    }
    case Region::Polygon: return g.points;
  }
  return {};
}
}  // namespace

double outside(const Region& region, P2 p) {
  if (region.kind == Region::Circle)
    return std::max(0.0, distance(p, {region.cx, region.cy}) - region.r);
  if (region.kind == Region::Polygon) {
    const std::vector<P2>& pts = region.points;
    if (pts.empty()) return kInf;
    if (pts.size() >= 3 && insidePolygon(pts, p)) return 0;
    double best = kInf;
    for (size_t i = 0, j = pts.size() - 1; i < pts.size(); j = i++)
      best = std::min(best, distanceToSegment(p, pts[j], pts[i]));
    return best;
  }
  double dx = std::max({region.x1 - p.x, 0.0, p.x - region.x2});
  double dy = std::max({region.y1 - p.y, 0.0, p.y - region.y2});
  return std::hypot(dx, dy);
}

P2 labelPoint(const Region& g) {
  switch (g.kind) {
    case Region::Rect: return {(g.x1 + g.x2) / 2, (g.y1 + g.y2) / 2};
    case Region::Circle: return {g.cx, g.cy};
    case Region::Polygon: {
      P2 mean;
      for (const P2& p : g.points) {
        mean.x += p.x / static_cast<double>(g.points.size());
        mean.y += p.y / static_cast<double>(g.points.size());
      }
      if (g.points.empty() || outside(g, mean) == 0) return mean;
      // A concave polygon's mean can lie outside: the first corner, nudged toward the mean.
      P2 c = g.points[0];
      for (double t = 0.05; t <= 1; t += 0.05) {
        P2 q = lerp(c, mean, t);
        if (outside(g, q) == 0) return q;
      }
      return c;
    }
  }
  return {};
}

bool regionInside(const Region& inner, const Region& outer) {
  for (const P2& p : outline(inner))
    if (outside(outer, p) > 1e-9) return false;
  return true;
}

Reach firstReach(const Polylines& path, const Region& region, double radius, double step) {
  Reach r;
  r.closest = kInf;
  if (step <= 0) step = 0.5;
  auto test = [&](P2 p, size_t line, size_t point) {
    double d = outside(region, p);
    r.closest = std::min(r.closest, d - radius);
    if (d <= radius) {
      r.reached = true;
      r.at = p;
      r.line = line;
      r.point = point;
    }
    return r.reached;
  };
  for (size_t l = 0; l < path.size(); ++l) {
    const Polyline& pl = path[l];
    if (pl.empty()) continue;
    if (test(pl[0], l, 0)) return r;
    for (size_t i = 1; i < pl.size(); ++i) {
      double len = distance(pl[i - 1], pl[i]);
      int n = static_cast<int>(std::min(std::ceil(len / step), 1e7));
      for (int k = 1; k <= n; ++k)
        if (test(lerp(pl[i - 1], pl[i], static_cast<double>(k) / n), l, i)) return r;
    }
  }
  r.closest = std::max(0.0, r.closest);
  return r;
}

VisitResult visitInOrder(const Polylines& path, const std::vector<P2>& targets, double tolerance) {
  std::vector<Segment> segs = segments(path);
  size_t seg = 0;
  double t = 0;
  for (size_t k = 0; k < targets.size(); ++k) {
    bool found = false;
    double closest = kInf;
    for (size_t s = seg; s < segs.size() && !found; ++s) {
      double from = s == seg ? t : 0;
      double hit = firstWithin(segs[s].a, segs[s].b, from, targets[k], tolerance);
      if (hit >= 0) {
        seg = s;
        t = hit;
        found = true;
      } else {
        closest = std::min(closest, distanceToSegment(targets[k], lerp(segs[s].a, segs[s].b, from), segs[s].b));
      }
    }
    if (!found) return {k, closest};
  }
  return {};
}

VisitResult visitAny(const Polylines& path, const std::vector<P2>& targets, double tolerance) {
  for (size_t k = 0; k < targets.size(); ++k) {
    double d = distanceToLines(targets[k], path);
    if (!(d <= tolerance)) return {k, d};
  }
  return {};
}

}  // namespace rb::record
