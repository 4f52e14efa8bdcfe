#include "assignment.h"

#include <cmath>
#include <filesystem>
#include <set>
#include <toml++/toml.h>

#include "lang/suggest.h"

namespace rb::grade {

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
  std::vector<std::string_view> keys;  ///< keys besides kind, name and points
};

const std::vector<KindInfo>& kinds() {
  static const std::vector<KindInfo> table = {
      {Check::Output, "output", {"text", "regex"}},
      {Check::NoError, "no-error", {}},
      {Check::NoCrash, "no-crash", {}},
      {Check::Clean, "check", {"warnings", "target"}},
      {Check::EndsIn, "ends-in", {"rect", "circle"}},
      {Check::Visits, "visits", {"waypoints", "tolerance", "in-order"}},
      {Check::Trail, "trail", {"path", "paths", "tolerance"}},
      {Check::Screen, "screen", {"reference", "tolerance"}},
      {Check::SolutionOutput, "solution-output", {}},
      {Check::SolutionTrail, "solution-trail", {"tolerance"}},
      {Check::SolutionScreen, "solution-screen", {"tolerance"}},
  };
  return table;
}

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

Check readCheck(const toml::table& t, const fs::path& dir) {
  Check c;
  c.line = t.source().begin.line;
  const toml::node* kindNode = t.get("kind");
  if (!kindNode) throw Bad{"a [[check]] needs a kind (output, no-error, no-crash, check, ends-in, visits, trail, screen, solution-output, solution-trail or solution-screen)", t.source()};
  std::string kind = text(*kindNode, "kind");
  const KindInfo* info = nullptr;
  for (const KindInfo& k : kinds())
    if (kind == k.name) info = &k;
  if (!info) {
    std::vector<std::string_view> names;
    for (const KindInfo& k : kinds()) names.push_back(k.name);
    std::string message = "unknown check kind " + inQuotes(kind);
    std::string near = closestMatch(kind, names, true);
    if (!near.empty()) message += "; did you mean " + inQuotes(near) + "?";
    throw Bad{message, kindNode->source()};
  }
  c.kind = info->kind;
  c.name = info->name;
  std::vector<std::string_view> allowed = info->keys;
  allowed.insert(allowed.end(), {"kind", "name", "points"});
  std::string where = "in check " + inQuotes(kind);
  onlyKeys(t, allowed, where);
  if (const toml::node* n = t.get("name")) c.name = text(*n, "name");
  if (const toml::node* n = t.get("points")) {
    c.points = number(*n, "points");
    if (c.points < 0) throw Bad{"points must not be negative", n->source()};
  }

  switch (c.kind) {
    case Check::Output: {
      const toml::node* textNode = t.get("text");
      const toml::node* regexNode = t.get("regex");
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
        try {
          c.regexes.emplace_back(p, std::regex::ECMAScript);
        } catch (const std::regex_error& e) {
          throw Bad{"bad regex " + inQuotes(p) + ": " + e.what(), regexNode->source()};
        }
      }
      break;
    }
    case Check::Clean:
      if (const toml::node* n = t.get("warnings")) c.allowWarnings = boolean(*n, "warnings");
      if (const toml::node* n = t.get("target")) {
        c.target = text(*n, "target");
        if (c.target != "rb9") throw Bad{"target must be \"rb9\"", n->source()};
      }
      break;
    case Check::EndsIn: {
      const toml::node* rect = t.get("rect");
      const toml::node* circle = t.get("circle");
      if (!!rect == !!circle)
        throw Bad{"an ends-in check needs either rect = [x1, y1, x2, y2] or circle = [x, y, radius]", t.source()};
      if (rect) {
        std::vector<double> v = numbers(*rect, 4, "rect");
        c.region.kind = Region::Rect;
        c.region.x1 = std::min(v[0], v[2]);
        c.region.x2 = std::max(v[0], v[2]);
        c.region.y1 = std::min(v[1], v[3]);
        c.region.y2 = std::max(v[1], v[3]);
      } else {
        std::vector<double> v = numbers(*circle, 3, "circle");
        if (v[2] < 0) throw Bad{"the circle's radius must not be negative", circle->source()};
        c.region.kind = Region::Circle;
        c.region.cx = v[0];
        c.region.cy = v[1];
        c.region.r = v[2];
      }
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
    case Check::NoError:
    case Check::NoCrash:
    case Check::SolutionOutput:
      break;
  }
  return c;
}

void readRun(const toml::table& run, const fs::path& dir, Assignment& a) {
  onlyKeys(run, {"seeds", "max-steps", "timeout", "memory", "events", "keys", "stdin"}, "in [run]");
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
  }
  if (const toml::node* n = run.get("timeout")) {
    a.timeout = number(*n, "timeout");
    if (!(a.timeout > 0) || a.timeout > 86400) throw Bad{"timeout must be a number of seconds above 0", n->source()};
  }
  if (const toml::node* n = run.get("memory")) {
    std::optional<int64_t> v = n->value<int64_t>();
    if (!v || !n->is_integer() || *v < 16) throw Bad{"memory must be a whole number of megabytes, at least 16", n->source()};
    a.memoryMb = static_cast<uint64_t>(*v);
  }
  if (const toml::node* n = run.get("events")) a.events = requireFile(dir, *n, "events");
  if (const toml::node* n = run.get("keys")) a.keys = text(*n, "keys");
  if (const toml::node* n = run.get("stdin")) {
    const toml::array* arr = n->as_array();
    if (!arr) throw Bad{"stdin must be a list of lines, like [\"3\", \"4\"]", n->source()};
    for (const toml::node& s : *arr) a.stdinLines.push_back(text(s, "each stdin line"));
  }
}

}  // namespace

const char* kindName(Check::Kind kind) {
  for (const KindInfo& k : kinds())
    if (k.kind == kind) return k.name;
  return "check";
}

bool Assignment::needsSolution() const {
  for (const Check& c : checks)
    if (c.kind == Check::SolutionOutput || c.kind == Check::SolutionTrail || c.kind == Check::SolutionScreen)
      return true;
  return false;
}

bool Assignment::needsScreen() const {
  for (const Check& c : checks)
    if (c.kind == Check::Screen || c.kind == Check::SolutionScreen) return true;
  return false;
}

double Assignment::maxPoints() const {
  double total = 0;
  for (const Check& c : checks) total += c.points;
  return total;
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
    toml::table root = toml::parse_file(path);
    onlyKeys(root, {"title", "solution", "run", "check"}, "at the top of the assignment");
    a.title = fs::path(path).stem().string();
    if (const toml::node* n = root.get("title")) a.title = text(*n, "title");
    if (const toml::node* n = root.get("solution")) a.solution = requireFile(dir, *n, "solution");
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
        a.checks.push_back(readCheck(*t, dir));
      }
    }
    if (a.checks.empty()) {
      Check c;
      c.kind = Check::NoError;
      c.name = kindName(c.kind);
      a.checks.push_back(c);
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
