#include "assignment.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <filesystem>
#include <set>
#include <re2/re2.h>
#include <toml++/toml.h>

#include "lang/builtins.h"
#include "lang/suggest.h"
#include "machine/builtins.h"
#include "screen/canvas.h"

namespace rb::grade {

using record::P2;
using record::Region;
using record::regionInside;

namespace fs = std::filesystem;

namespace {

/// Thrown with a message for the assignment file's reader.
struct Bad {
  std::string message;
  toml::source_region where;
};

struct KindInfo {
  Check::Kind kind;
  const char* name;
  std::vector<std::string_view> keys;  ///< keys besides the ones every check takes
};

const std::vector<KindInfo>& kinds() {
  static const std::vector<KindInfo> table = {
      {Check::Output, "output", {"text", "regex", "prompts"}},
      {Check::NoError, "no-error", {}},
      {Check::NoCrash, "no-crash", {}},
      {Check::Clean, "check", {"warnings", "target"}},
      {Check::EndsIn, "ends-in", {"rect", "circle", "polygon"}},
      {Check::Visits, "visits", {"waypoints", "tolerance", "in-order"}},
      {Check::Trail, "trail", {"path", "paths", "tolerance"}},
      {Check::Screen, "screen", {"reference", "tolerance"}},
      {Check::SolutionOutput, "solution-output", {"prompts"}},
      {Check::SolutionTrail, "solution-trail", {"tolerance"}},
      {Check::SolutionScreen, "solution-screen", {"tolerance"}},
      {Check::Avoid, "avoid", {"rect", "circle", "polygon", "colour", "color"}},
      {Check::Touch, "touch", {"rect", "circle", "polygon", "colour", "color"}},
      {Check::Post, "post", {"post", "program"}},
      {Check::Efficiency, "efficiency", {"measure", "tiers"}},
      {Check::AnyOf, "any-of", {"of"}},
      {Check::AllOf, "all-of", {"of"}},
  };
  return table;
}

/// Keys every check takes.
const std::vector<std::string_view> kCommonKeys = {"kind", "name", "points", "required", "after", "hint",
                                                   "hidden", "max-statements", "max-moves", "max-distance"};
/// Keys a check inside a group may not have: the group scores, depends and hides as one.
const std::vector<std::string_view> kGroupOnlyKeys = {"points", "required", "after", "hidden"};

std::string inQuotes(std::string_view s) { return "'" + std::string(s) + "'"; }

/// Refuses keys of `table` that are not in `allowed`, suggesting the nearest one.
void onlyKeys(const toml::table& table, const std::vector<std::string_view>& allowed,
              const std::string& where) {
  for (auto&& [key, node] : table) {
    bool known = false;
    for (std::string_view k : allowed) known = known || k == key.str();
    if (known) continue;
    std::string message = "unknown key " + inQuotes(key.str()) + " " + where;
    std::string near = closestMatch(key.str(), allowed, true);
    if (!near.empty()) message += "; did you mean " + inQuotes(near) + "?";
    throw Bad{message, key.source()};
  }
}

/// A number, finite: TOML's nan and inf mean nothing as a coordinate, tolerance or time.
double number(const toml::node& node, const std::string& what) {
  if (std::optional<double> v = node.value<double>(); v && node.is_number()) {
    if (std::isfinite(*v)) return *v;
    throw Bad{what + " must be a finite number, not " + std::string(std::isnan(*v) ? "nan" : "inf"), node.source()};
  }
  throw Bad{what + " must be a number", node.source()};
}

std::string text(const toml::node& node, const std::string& what) {
  if (std::optional<std::string> v = node.value<std::string>()) return *v;
  throw Bad{what + " must be a string", node.source()};
}

bool boolean(const toml::node& node, const std::string& what) {
  if (std::optional<bool> v = node.value<bool>()) return *v;
  throw Bad{what + " must be true or false", node.source()};
}

/// A list of numbers of exactly `count` entries (any count when 0).
std::vector<double> numbers(const toml::node& node, size_t count, const std::string& what) {
  const toml::array* arr = node.as_array();
  if (!arr || (count && arr->size() != count))
    throw Bad{what + " must be a list of " + (count ? std::to_string(count) + " " : "") + "numbers",
              node.source()};
  std::vector<double> out;
  for (const toml::node& n : *arr) out.push_back(number(n, what + "'s entries"));
  return out;
}

std::vector<P2> points(const toml::node& node, const std::string& what) {
  const toml::array* arr = node.as_array();
  if (!arr || arr->empty())
    throw Bad{what + " must be a list of points like [[400, 300], [400, 180]]", node.source()};
  std::vector<P2> out;
  for (const toml::node& n : *arr) {
    std::vector<double> xy = numbers(n, 2, "each point of " + what);
    out.push_back({xy[0], xy[1]});
  }
  return out;
}

std::string fileBeside(const fs::path& dir, const std::string& name) {
  fs::path p(name);
  if (p.is_relative()) p = dir / p;
  return p.lexically_normal().string();
}

std::string requireFile(const fs::path& dir, const toml::node& node, const std::string& what) {
  std::string path = fileBeside(dir, text(node, what));
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) throw Bad{what + ": no such file '" + path + "'", node.source()};
  return path;
}

double tolerance(const toml::table& t, double fallback, bool share, const std::string& what) {
  const toml::node* node = t.get("tolerance");
  if (!node) return fallback;
  double v = number(*node, what + ": tolerance");
  if (v < 0 || (share && v > 1))
    throw Bad{what + ": tolerance must be " + (share ? "a share of pixels from 0 to 1 (0.01 is 1%)" : "0 or more pixels"),
              node->source()};
  return v;
}

/// A colour: a name RobotBASIC knows ("red", any case), a colour number (4, or what rgb()
/// gives), [r, g, b], or "#RRGGBB". 0xRRGGBB.
uint32_t colour(const toml::node& node, std::string& name) {
  if (std::optional<std::string> s = node.value<std::string>()) {
    name = *s;
    if (s->size() == 7 && (*s)[0] == '#') {
      try {
        size_t used = 0;
        unsigned long v = std::stoul(s->substr(1), &used, 16);
        if (used == 6) return static_cast<uint32_t>(v);
      } catch (const std::exception&) {
      }
    }
    const BuiltinTable& table = standardBuiltins();
    if (const Builtin* b = table.find(*s, BuiltinKind::Constant); b && b->group == "colour")
      return colourToRgb(static_cast<Colour>(b->constant));
    std::vector<std::string_view> names;
    for (const Builtin& b : table.rows())
      if (b.kind == BuiltinKind::Constant && b.group == "colour") names.push_back(b.name);
    std::string message = "unknown colour " + inQuotes(*s);
    std::string near = closestMatch(*s, names, true);
    if (!near.empty()) message += "; did you mean " + inQuotes(near) + "?";
    throw Bad{message + " (a colour is a name like \"red\", a number, [r, g, b] or \"#RRGGBB\")", node.source()};
  }
  if (node.is_integer()) {
    int64_t v = *node.value<int64_t>();
    if (v < 0 || v > 0xFFFFFFFF) throw Bad{"a colour number must be 0 or more", node.source()};
    name = "colour " + std::to_string(v);
    return colourToRgb(static_cast<Colour>(v));
  }
  if (const toml::array* arr = node.as_array(); arr && arr->size() == 3) {
    std::vector<double> v = numbers(node, 3, "a colour [r, g, b]");
    for (double c : v)
      if (c < 0 || c > 255 || c != std::floor(c))
        throw Bad{"a colour's [r, g, b] are whole numbers from 0 to 255", node.source()};
    char buf[48];
    std::snprintf(buf, sizeof buf, "[%d, %d, %d]", static_cast<int>(v[0]), static_cast<int>(v[1]), static_cast<int>(v[2]));
    name = buf;
    return static_cast<uint32_t>(v[0]) << 16 | static_cast<uint32_t>(v[1]) << 8 | static_cast<uint32_t>(v[2]);
  }
  throw Bad{"a colour is a name like \"red\", a number, [r, g, b] or \"#RRGGBB\"", node.source()};
}

/// True when the node is a list whose first entry is a list: several of a thing.
bool listOfLists(const toml::node& node, int depth) {
  const toml::node* n = &node;
  for (int i = 0; i < depth; ++i) {
    const toml::array* arr = n->as_array();
    if (!arr || arr->empty()) return false;
    n = arr->get(0);
  }
  return n->is_array();
}

Region rectRegion(const toml::node& n) {
  std::vector<double> v = numbers(n, 4, "rect");
  Region g;
  g.kind = Region::Rect;
  g.x1 = std::min(v[0], v[2]);
  g.x2 = std::max(v[0], v[2]);
  g.y1 = std::min(v[1], v[3]);
  g.y2 = std::max(v[1], v[3]);
  return g;
}

Region circleRegion(const toml::node& n) {
  std::vector<double> v = numbers(n, 3, "circle");
  if (v[2] < 0) throw Bad{"the circle's radius must not be negative", n.source()};
  Region g;
  g.kind = Region::Circle;
  g.cx = v[0];
  g.cy = v[1];
  g.r = v[2];
  return g;
}

Region polygonRegion(const toml::node& n) {
  Region g;
  g.kind = Region::Polygon;
  g.points = points(n, "polygon");
  if (g.points.size() < 3) throw Bad{"a polygon needs at least 3 corners", n.source()};
  return g;
}

/// rect, circle and polygon: one each, or a list of them.
std::vector<Region> regions(const toml::table& t) {
  std::vector<Region> out;
  if (const toml::node* n = t.get("rect")) {
    if (listOfLists(*n, 1))
      for (const toml::node& r : *n->as_array()) out.push_back(rectRegion(r));
    else
      out.push_back(rectRegion(*n));
  }
  if (const toml::node* n = t.get("circle")) {
    if (listOfLists(*n, 1))
      for (const toml::node& r : *n->as_array()) out.push_back(circleRegion(r));
    else
      out.push_back(circleRegion(*n));
  }
  if (const toml::node* n = t.get("polygon")) {
    if (listOfLists(*n, 2))
      for (const toml::node& r : *n->as_array()) out.push_back(polygonRegion(r));
    else
      out.push_back(polygonRegion(*n));
  }
  return out;
}

double positiveLimit(const toml::node& n, const std::string& what) {
  double v = number(n, what);
  if (!(v > 0)) throw Bad{what + " must be above 0", n.source()};
  return v;
}

Check readCheck(const toml::table& t, const fs::path& dir, bool inGroup) {
  Check c;
  c.line = t.source().begin.line;
  c.column = t.source().begin.column;
  const toml::node* kindNode = t.get("kind");
  if (!kindNode && (t.get("post") || t.get("program"))) {
    c.kind = Check::Post;
  } else {
    if (!kindNode) {
      std::string list;
      for (const KindInfo& k : kinds()) list += std::string(list.empty() ? "" : ", ") + k.name;
      throw Bad{"a check needs a kind (" + list + ")", t.source()};
    }
    std::string kind = text(*kindNode, "kind");
    const KindInfo* found = nullptr;
    for (const KindInfo& k : kinds())
      if (kind == k.name) found = &k;
    if (!found) {
      std::vector<std::string_view> names;
      for (const KindInfo& k : kinds()) names.push_back(k.name);
      std::string message = "unknown check kind " + inQuotes(kind);
      std::string near = closestMatch(kind, names, true);
      if (!near.empty()) message += "; did you mean " + inQuotes(near) + "?";
      throw Bad{message, kindNode->source()};
    }
    c.kind = found->kind;
  }
  const KindInfo* info = nullptr;
  for (const KindInfo& k : kinds())
    if (k.kind == c.kind) info = &k;
  c.name = info->name;
  std::vector<std::string_view> allowed = info->keys;
  allowed.insert(allowed.end(), kCommonKeys.begin(), kCommonKeys.end());
  std::string where = "in check " + inQuotes(info->name);
  onlyKeys(t, allowed, where);
  if (inGroup)
    for (std::string_view k : kGroupOnlyKeys)
      if (const toml::node* n = t.get(k))
        throw Bad{"a check inside any-of or all-of has no " + std::string(k) + " of its own: the group has it", n->source()};
  if (const toml::node* n = t.get("name")) {
    c.name = text(*n, "name");
    c.named = true;
    if (c.name.empty()) throw Bad{"a check's name must not be empty", n->source()};
  }
  if (const toml::node* n = t.get("points")) {
    c.points = number(*n, "points");
    if (c.points < 0) throw Bad{"points must not be negative", n->source()};
  }
  if (const toml::node* n = t.get("required")) c.required = boolean(*n, "required");
  if (const toml::node* n = t.get("hidden")) c.hidden = boolean(*n, "hidden");
  if (const toml::node* n = t.get("hint")) c.hint = text(*n, "hint");
  if (const toml::node* n = t.get("after")) {
    c.after = text(*n, "after");
    if (c.after.empty()) throw Bad{"after names the check that must pass first", n->source()};
  }
  if (const toml::node* n = t.get("max-statements")) c.maxStatements = positiveLimit(*n, "max-statements");
  if (const toml::node* n = t.get("max-moves")) c.maxMoves = positiveLimit(*n, "max-moves");
  if (const toml::node* n = t.get("max-distance")) c.maxDistance = positiveLimit(*n, "max-distance");

  switch (c.kind) {
    case Check::Output: {
      const toml::node* textNode = t.get("text");
      const toml::node* regexNode = t.get("regex");
      if (const toml::node* n = t.get("prompts")) c.prompts = boolean(*n, "prompts");
      if (!!textNode == !!regexNode)
        throw Bad{"an output check needs either text (the exact output) or regex (patterns, one per line)", t.source()};
      if (textNode) {
        c.text = text(*textNode, "text");
        break;
      }
      if (regexNode->is_string()) {
        c.patterns.push_back(text(*regexNode, "regex"));
      } else if (const toml::array* arr = regexNode->as_array()) {
        for (const toml::node& n : *arr) c.patterns.push_back(text(n, "each regex"));
      } else {
        throw Bad{"regex must be a pattern or a list of patterns", regexNode->source()};
      }
      for (const std::string& p : c.patterns) {
        RE2::Options options;
        options.set_log_errors(false);
        auto re = std::make_shared<const RE2>(p, options);
        if (!re->ok()) throw Bad{"bad regex " + inQuotes(p) + ": " + re->error(), regexNode->source()};
        c.regexes.push_back(std::move(re));
      }
      break;
    }
    case Check::SolutionOutput:
      if (const toml::node* n = t.get("prompts")) c.prompts = boolean(*n, "prompts");
      break;
    case Check::Clean:
      if (const toml::node* n = t.get("warnings")) c.allowWarnings = boolean(*n, "warnings");
      if (const toml::node* n = t.get("target")) {
        c.target = text(*n, "target");
        if (c.target != "rb9") throw Bad{"target must be \"rb9\"", n->source()};
      }
      break;
    case Check::EndsIn: {
      c.regions = regions(t);
      if (c.regions.size() != 1)
        throw Bad{"an ends-in check needs one region: rect = [x1, y1, x2, y2], circle = [x, y, radius] or polygon = [[x, y], ...]", t.source()};
      break;
    }
    case Check::Avoid:
    case Check::Touch: {
      c.regions = regions(t);
      const toml::node* colourNode = t.get("colour");
      if (const toml::node* alt = t.get("color")) {
        if (colourNode) throw Bad{"colour and color are the same key: give one", alt->source()};
        colourNode = alt;
      }
      if (colourNode) {
        std::string name;
        if (const toml::array* arr = colourNode->as_array(); arr && !(arr->size() == 3 && (*arr)[0].is_number())) {
          for (const toml::node& n : *arr) {
            c.colours.push_back(colour(n, name));
            c.colourNames.push_back(name);
          }
        } else {
          c.colours.push_back(colour(*colourNode, name));
          c.colourNames.push_back(name);
        }
      }
      if (c.regions.empty() && c.colours.empty())
        throw Bad{std::string("an ") + (c.kind == Check::Avoid ? "avoid" : "touch") +
                      " check needs a region (rect, circle, polygon) or a colour",
                  t.source()};
      break;
    }
    case Check::Visits: {
      const toml::node* n = t.get("waypoints");
      if (!n) throw Bad{"a visits check needs waypoints = [[x, y], ...]", t.source()};
      c.targets = points(*n, "waypoints");
      c.tolerance = tolerance(t, 5, false, where);
      if (const toml::node* o = t.get("in-order")) c.inOrder = boolean(*o, "in-order");
      break;
    }
    case Check::Trail: {
      const toml::node* path = t.get("path");
      const toml::node* paths = t.get("paths");
      if (!!path == !!paths)
        throw Bad{"a trail check needs either path = [[x, y], ...] (one line) or paths = [[[x, y], ...], ...]", t.source()};
      if (path) {
        c.reference.push_back(points(*path, "path"));
      } else {
        const toml::array* arr = paths->as_array();
        if (!arr || arr->empty()) throw Bad{"paths must be a list of lists of points", paths->source()};
        for (const toml::node& l : *arr) c.reference.push_back(points(l, "each path"));
      }
      c.tolerance = tolerance(t, 5, false, where);
      break;
    }
    case Check::Screen: {
      const toml::node* n = t.get("reference");
      if (!n) throw Bad{"a screen check needs reference = \"picture.png\"", t.source()};
      c.picture = requireFile(dir, *n, "reference");
      c.tolerance = tolerance(t, 0.01, true, where);
      break;
    }
    case Check::SolutionTrail:
      c.tolerance = tolerance(t, 5, false, where);
      break;
    case Check::SolutionScreen:
      c.tolerance = tolerance(t, 0.01, true, where);
      break;
    case Check::Post: {
      const toml::node* a = t.get("post");
      const toml::node* b = t.get("program");
      if (!!a == !!b) throw Bad{"a post check needs post = \"goal.bas\": the teacher's program run after the student's", t.source()};
      c.program = requireFile(dir, a ? *a : *b, "post");
      if (!t.get("name")) c.name = fs::path(c.program).stem().string();
      break;
    }
    case Check::Efficiency: {
      const toml::node* m = t.get("measure");
      if (!m) throw Bad{"an efficiency check needs measure = \"statements\", \"moves\" or \"distance\"", t.source()};
      std::string measure = text(*m, "measure");
      if (measure == "statements") c.measure = Check::Statements;
      else if (measure == "moves") c.measure = Check::Moves;
      else if (measure == "distance") c.measure = Check::Distance;
      else throw Bad{"measure must be \"statements\", \"moves\" or \"distance\", not " + inQuotes(measure), m->source()};
      const toml::node* tiers = t.get("tiers");
      const toml::array* arr = tiers ? tiers->as_array() : nullptr;
      if (!arr || arr->empty())
        throw Bad{"an efficiency check needs tiers = [[at most, points], ...], like [[40, 10], [60, 5]]", tiers ? tiers->source() : t.source()};
      for (const toml::node& n : *arr) {
        std::vector<double> v = numbers(n, 2, "each tier [at most, points]");
        if (v[0] < 0 || v[1] < 0) throw Bad{"a tier's limit and points must not be negative", n.source()};
        c.tiers.push_back({v[0], v[1]});
      }
      std::sort(c.tiers.begin(), c.tiers.end());
      for (size_t i = 1; i < c.tiers.size(); ++i) {
        if (c.tiers[i].first == c.tiers[i - 1].first)
          throw Bad{"two tiers have the same limit " + std::to_string(c.tiers[i].first), tiers->source()};
        if (c.tiers[i].second >= c.tiers[i - 1].second)
          throw Bad{"tiers contradict each other: a looser limit must earn fewer points than a stricter one", tiers->source()};
      }
      if (t.get("points")) throw Bad{"an efficiency check's points are its tiers' (the best tier's points)", t.get("points")->source()};
      c.points = c.tiers.front().second;
      break;
    }
    case Check::AnyOf:
    case Check::AllOf: {
      const toml::node* n = t.get("of");
      const toml::array* arr = n ? n->as_array() : nullptr;
      if (!arr || arr->empty())
        throw Bad{std::string("an ") + info->name + " group needs its checks: [[check.of]] tables after it", t.source()};
      for (const toml::node& m : *arr) {
        const toml::table* mt = m.as_table();
        if (!mt) throw Bad{"the checks of a group are written [[check.of]], one table each", m.source()};
        c.of.push_back(readCheck(*mt, dir, true));
      }
      break;
    }
    case Check::NoError:
    case Check::NoCrash:
      break;
  }
  return c;
}

std::string regionWords(const Region& g) {
  char buf[160];
  switch (g.kind) {
    case Region::Rect:
      std::snprintf(buf, sizeof buf, "the rectangle (%g, %g)-(%g, %g)", g.x1, g.y1, g.x2, g.y2);
      break;
    case Region::Circle: std::snprintf(buf, sizeof buf, "the circle of radius %g around (%g, %g)", g.r, g.cx, g.cy); break;
    case Region::Polygon: std::snprintf(buf, sizeof buf, "the polygon of %zu corners", g.points.size()); break;
  }
  return buf;
}

/// Checks that cannot all pass, and names that do not resolve.
void contradictions(const std::vector<Check>& checks) {
  auto at = [](const Check& c) {
    toml::source_region r;
    r.begin.line = c.line;
    r.begin.column = c.column;
    return r;
  };
  std::vector<const Check*> flat;
  for (const Check& c : checks) {
    flat.push_back(&c);
    for (const Check& m : c.of) flat.push_back(&m);
  }
  for (size_t i = 0; i < checks.size(); ++i) {
    const Check& c = checks[i];
    for (size_t j = 0; j < i; ++j)
      if (checks[j].name == c.name && c.named)
        throw Bad{"two checks are named " + inQuotes(c.name) + " (line " + std::to_string(checks[j].line) +
                      " and here): give one a name = \"...\" of its own",
                  at(c)};
    if (!c.after.empty()) {
      bool before = false;
      for (size_t j = 0; j < i; ++j) before = before || checks[j].name == c.after;
      if (!before) {
        bool later = false;
        for (size_t j = i; j < checks.size(); ++j) later = later || checks[j].name == c.after;
        throw Bad{"after = " + inQuotes(c.after) + " names " +
                      (c.after == c.name ? std::string("this check itself")
                       : later           ? std::string("a check that comes later: put it before this one")
                                         : std::string("no check")),
                  at(c)};
      }
    }
  }
  for (const Check* a : flat) {
    if (a->kind != Check::Avoid) continue;
    for (const Check* b : flat) {
      if (b == a) continue;
      if (b->kind == Check::Touch)
        for (uint32_t col : b->colours)
          for (size_t k = 0; k < a->colours.size(); ++k)
            if (a->colours[k] == col)
              throw Bad{"checks contradict each other: " + inQuotes(b->name) + " must touch " + a->colourNames[k] +
                            ", which " + inQuotes(a->name) + " must avoid",
                        at(*b)};
      for (const Region& avoid : a->regions) {
        if ((b->kind == Check::EndsIn || b->kind == Check::Touch) && !b->regions.empty()) {
          bool all = true;
          for (const Region& g : b->regions) all = all && regionInside(g, avoid);
          if (all)
            throw Bad{"checks contradict each other: " + inQuotes(b->name) + "'s " + regionWords(b->regions[0]) +
                          " lies inside " + regionWords(avoid) + ", which " + inQuotes(a->name) + " must avoid",
                      at(*b)};
        }
        if (b->kind == Check::Visits)
          for (size_t k = 0; k < b->targets.size(); ++k) {
            Region dot;
            dot.kind = Region::Circle;
            dot.cx = b->targets[k].x;
            dot.cy = b->targets[k].y;
            dot.r = b->tolerance;
            if (regionInside(dot, avoid))
              throw Bad{"checks contradict each other: " + inQuotes(b->name) + "'s waypoint " + std::to_string(k + 1) +
                            " lies inside " + regionWords(avoid) + ", which " + inQuotes(a->name) + " must avoid",
                        at(*b)};
          }
      }
    }
  }
}

void readRun(const toml::table& run, const fs::path& dir, Assignment& a) {
  onlyKeys(run, {"seeds", "max-steps", "timeout", "memory", "events", "keys", "stdin", "files", "spawn"}, "in [run]");
  if (const toml::node* n = run.get("seeds")) {
    const toml::array* arr = n->as_array();
    if (!arr || arr->empty()) throw Bad{"seeds must be a list of whole numbers, like [1, 2, 3]", n->source()};
    a.seeds.clear();
    for (const toml::node& s : *arr) {
      std::optional<int64_t> v = s.value<int64_t>();
      if (!v || !s.is_integer() || *v < 0) throw Bad{"each seed must be a whole number of 0 or more", s.source()};
      a.seeds.push_back(static_cast<uint64_t>(*v));
    }
  }
  if (const toml::node* n = run.get("max-steps")) {
    std::optional<int64_t> v = n->value<int64_t>();
    if (!v || !n->is_integer() || *v < 0) throw Bad{"max-steps must be a whole number (0: no limit)", n->source()};
    a.maxSteps = static_cast<uint64_t>(*v);
    a.maxStepsSet = true;
  }
  if (const toml::node* n = run.get("timeout")) {
    a.timeout = number(*n, "timeout");
    if (!(a.timeout > 0) || a.timeout > 86400) throw Bad{"timeout must be a number of seconds above 0", n->source()};
    a.timeoutSet = true;
  }
  if (const toml::node* n = run.get("memory")) {
    std::optional<int64_t> v = n->value<int64_t>();
    if (!v || !n->is_integer() || *v < 16) throw Bad{"memory must be a whole number of megabytes, at least 16", n->source()};
    a.memoryMb = static_cast<uint64_t>(*v);
  }
  if (const toml::node* n = run.get("events")) a.events = requireFile(dir, *n, "events");
  if (const toml::node* n = run.get("keys")) a.keys = text(*n, "keys");
  if (const toml::node* n = run.get("files")) {
    const toml::array* arr = n->as_array();
    if (!arr) throw Bad{"files must be a list of files or folders, like [\"maze.txt\", \"data\"]", n->source()};
    for (const toml::node& f : *arr) {
      std::string path = fileBeside(dir, text(f, "each of files"));
      std::error_code ec;
      fs::file_status st = fs::status(path, ec);
      if (!fs::is_regular_file(st) && !fs::is_directory(st))
        throw Bad{"files: no such file or folder '" + path + "'", f.source()};
      a.files.push_back(path);
    }
  }
  if (const toml::node* n = run.get("spawn")) a.spawn = boolean(*n, "spawn");
  if (const toml::node* n = run.get("stdin")) {
    const toml::array* arr = n->as_array();
    if (!arr) throw Bad{"stdin must be a list of lines, like [\"3\", \"4\"]", n->source()};
    for (const toml::node& s : *arr) a.stdinLines.push_back(text(s, "each stdin line"));
  }
}

/// Where TOML's text may not have a byte of a non-ASCII character, by the TOML 1.0 grammar: outside
/// strings and comments, and right after a multi-line basic string's line-ending backslash
/// (where the reader skips white space). toml++ 3.3 classifies such characters with code that
/// is undefined for many of them (upstream issues #190 and #295), so rb refuses them before
/// toml++ reads the file, naming the line and column; it also refuses text that is not UTF-8.
/// "" when the text is fine.
std::string unreadableText(const std::string& text, toml::source_region& where) {
  uint32_t line = 1, col = 1;
  auto fail = [&](const std::string& why) {
    where.begin.line = line;
    where.begin.column = col;
    return why;
  };
  enum { Plain, Comment, Basic, Literal, MultiBasic, MultiLiteral } state = Plain;
  bool afterBackslashLine = false;  // in a multi-line basic string, skipping after "\" + newline
  for (size_t i = 0; i < text.size();) {
    unsigned char c = static_cast<unsigned char>(text[i]);
    size_t len = 1;
    if (c >= 0x80) {
      // A whole UTF-8 sequence, shortest form, no surrogates, at most U+10FFFF.
      len = c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : c >= 0xC0 ? 2 : 0;
      uint32_t cp = len == 4 ? c & 0x07u : len == 3 ? c & 0x0Fu : c & 0x1Fu;
      bool ok = len >= 2 && c <= 0xF4 && i + len <= text.size();
      for (size_t k = 1; ok && k < len; ++k) {
        unsigned char d = static_cast<unsigned char>(text[i + k]);
        ok = (d & 0xC0) == 0x80;
        cp = cp << 6 | (d & 0x3Fu);
      }
      ok = ok && !(len == 2 && cp < 0x80) && !(len == 3 && cp < 0x800) && !(len == 4 && cp < 0x10000) &&
           !(cp >= 0xD800 && cp <= 0xDFFF) && cp <= 0x10FFFF;
      if (!ok) return fail("the file is not UTF-8 text: save it as UTF-8");
      if (state == Plain) return fail("a character that is not ASCII outside a string or comment");
      if (afterBackslashLine)
        return fail("a character that is not ASCII first after a line-ending backslash in a string: "
                    "end the line before without the backslash, or begin this text with an ASCII character");
      i += len;
      ++col;
      continue;
    }
    auto starts = [&](const char* s) { return text.compare(i, std::strlen(s), s) == 0; };
    if (c == '\n') {
      ++line;
      col = 1;
      if (state == Comment) state = Plain;
      ++i;
      continue;
    }
    // A quote opens a string only where TOML lets one begin: first on a line, or after a blank,
    // '=', '[', '{', ',' or '.'. Right after a bare word (0%1\"\"\") it is part of that word,
    // which toml++ reads character by character.
    const unsigned char before = i > 0 ? static_cast<unsigned char>(text[i - 1]) : '\n';
    const bool stringMayBegin = std::strchr(" \t\r\n=[{,.", before) != nullptr;
    switch (state) {
      case Plain:
        if (c == '#') state = Comment;
        else if (!stringMayBegin) break;
        else if (starts("\"\"\"")) state = MultiBasic, len = 3;
        else if (starts("'''")) state = MultiLiteral, len = 3;
        else if (c == '"') state = Basic;
        else if (c == '\'') state = Literal;
        break;
      case Comment: break;
      case Basic:
        if (c == '\\') len = i + 1 < text.size() && text[i + 1] != '\n' ? 2 : 1;
        else if (c == '"') state = Plain;
        break;
      case Literal:
        if (c == '\'') state = Plain;
        break;
      case MultiBasic:
        if (c == '\\') {
          size_t j = i + 1;
          while (j < text.size() && (text[j] == ' ' || text[j] == '\t' || text[j] == '\r')) ++j;
          if (j < text.size() && text[j] == '\n') afterBackslashLine = true;
          else len = j < text.size() ? 2 : 1;
        } else if (starts("\"\"\"")) {
          state = Plain;
          len = 3;
        }
        break;
      case MultiLiteral:
        if (starts("'''")) state = Plain, len = 3;
        break;
    }
    if (afterBackslashLine && c != '\\' && c != ' ' && c != '\t' && c != '\r') afterBackslashLine = false;
    i += len;
    col += static_cast<uint32_t>(len);
  }
  return "";
}

}  // namespace

const char* kindName(Check::Kind kind) {
  for (const KindInfo& k : kinds())
    if (k.kind == kind) return k.name;
  return "check";
}

const char* measureName(Check::Measure measure) {
  switch (measure) {
    case Check::Statements: return "statements";
    case Check::Moves: return "moves";
    case Check::Distance: return "distance";
  }
  return "statements";
}

std::vector<const Check*> allChecks(const Assignment& a) {
  std::vector<const Check*> out;
  for (const Check& c : a.checks) {
    out.push_back(&c);
    for (const Check& m : c.of) out.push_back(&m);
  }
  return out;
}

bool Assignment::needsSolution() const {
  for (const Check* c : allChecks(*this))
    if (c->kind == Check::SolutionOutput || c->kind == Check::SolutionTrail || c->kind == Check::SolutionScreen)
      return true;
  return false;
}

bool Assignment::needsScreen() const {
  for (const Check* c : allChecks(*this))
    if (c->kind == Check::Screen || c->kind == Check::SolutionScreen) return true;
  return false;
}

double Assignment::maxPoints() const {
  double total = 0;
  for (const Check& c : checks) total += c.points;
  return total;
}

std::vector<std::string> Assignment::posts() const {
  std::vector<std::string> out;
  for (const Check* c : allChecks(*this))
    if (c->kind == Check::Post) out.push_back(c->program);
  return out;
}

std::vector<uint32_t> Assignment::watchedColours() const {
  std::vector<uint32_t> out;
  for (const Check* c : allChecks(*this))
    for (uint32_t col : c->colours)
      if (std::find(out.begin(), out.end(), col) == out.end()) out.push_back(col);
  return out;
}

bool Assignment::robotChecks() const {
  for (const Check* c : allChecks(*this)) {
    switch (c->kind) {
      case Check::NoCrash:
      case Check::EndsIn:
      case Check::Visits:
      case Check::Trail:
      case Check::SolutionTrail:
      case Check::Avoid:
      case Check::Touch: return true;
      case Check::Efficiency:
        if (c->measure != Check::Statements) return true;
        break;
      default: break;
    }
    if (c->maxMoves || c->maxDistance) return true;
  }
  return false;
}

std::optional<Assignment> loadAssignment(const std::string& path, std::string& error) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    error = path + ": no such file";
    return std::nullopt;
  }
  fs::path dir = fs::absolute(path, ec).parent_path();
  Assignment a;
  a.path = path;
  try {
    std::string content;
    {
      std::ifstream in(path, std::ios::binary);
      std::ostringstream all;
      all << in.rdbuf();
      content = all.str();
    }
    toml::source_region where;
    if (std::string why = unreadableText(content, where); !why.empty()) throw Bad{why, where};
    toml::table root = toml::parse(content, path);
    onlyKeys(root, {"title", "solution", "world", "roster", "robot", "ports", "run", "check"},
             "at the top of the assignment");
    a.title = fs::path(path).stem().string();
    if (const toml::node* n = root.get("title")) a.title = text(*n, "title");
    if (const toml::node* n = root.get("solution")) a.solution = requireFile(dir, *n, "solution");
    if (const toml::node* n = root.get("world")) a.world = requireFile(dir, *n, "world");
    if (const toml::node* n = root.get("roster")) a.roster = requireFile(dir, *n, "roster");
    if (const toml::node* n = root.get("robot")) a.aboutRobot = boolean(*n, "robot");
    if (const toml::node* n = root.get("ports")) a.ports = boolean(*n, "ports");
    if (const toml::node* n = root.get("run")) {
      const toml::table* run = n->as_table();
      if (!run) throw Bad{"run must be a table: [run]", n->source()};
      readRun(*run, dir, a);
    }
    if (const toml::node* n = root.get("check")) {
      const toml::array* arr = n->as_array();
      if (!arr) throw Bad{"checks are written [[check]], one table per check", n->source()};
      for (const toml::node& c : *arr) {
        const toml::table* t = c.as_table();
        if (!t) throw Bad{"checks are written [[check]], one table per check", c.source()};
        a.checks.push_back(readCheck(*t, dir, false));
      }
    }
    if (a.checks.empty()) {
      Check c;
      c.kind = Check::NoError;
      c.name = kindName(c.kind);
      a.checks.push_back(c);
    }
    // Unnamed checks of one kind are told apart by a number: "ends-in", "ends-in 2".
    auto number = [](std::vector<Check>& list) {
      for (size_t i = 0; i < list.size(); ++i) {
        Check& c = list[i];
        if (c.named) continue;
        std::string base = c.name;
        for (int k = 2;; ++k) {
          bool taken = false;
          for (size_t j = 0; j < list.size(); ++j)
            taken = taken || (j != i && list[j].name == c.name && (j < i || list[j].named));
          if (!taken) break;
          c.name = base + " " + std::to_string(k);
        }
      }
    };
    number(a.checks);
    for (Check& c : a.checks) number(c.of);
    contradictions(a.checks);
    size_t posts = 0;
    for (Check& c : a.checks) {
      if (c.kind == Check::Post) c.postIndex = posts++;
      for (Check& m : c.of)
        if (m.kind == Check::Post) m.postIndex = posts++;
    }
    if (a.needsSolution() && !a.solution)
      throw Bad{"the solution-* checks need the reference solution: solution = \"solution.bas\"", root.source()};
  } catch (const toml::parse_error& e) {
    error = path + ":" + std::to_string(e.source().begin.line) + ":" + std::to_string(e.source().begin.column) +
            ": " + std::string(e.description());
    return std::nullopt;
  } catch (const Bad& b) {
    error = path + ":" + std::to_string(b.where.begin.line) + ":" + std::to_string(b.where.begin.column) +
            ": " + b.message;
    return std::nullopt;
  }
  return a;
}

}  // namespace rb::grade
