#include "checks.h"

#include <optional>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>

#include <re2/re2.h>

#include "base/text.h"
#include "text.h"

namespace rb::grade {

using record::DiagRecord;
using record::HausdorffDistance;
using record::P2;
using record::Polylines;
using record::Reach;
using record::Region;
using record::RunRecord;
using record::Screen;
using record::VisitResult;
using record::distance;
using record::empty;
using record::firstReach;
using record::hausdorff;
using record::length;
using record::outside;
using record::printedOutput;
using record::toUtf8;
using record::visitAny;
using record::visitInOrder;

namespace {

std::string baseName(const std::string& path) { return std::filesystem::path(path).filename().string(); }

/// A string for a message: quoted, escaped, shortened.
std::string quote(std::string_view s) { return cQuoted(s, 160); }

std::vector<std::string> splitLines(const std::string& s, bool dropFinalEmpty) {
  std::vector<std::string> lines;
  size_t start = 0;
  while (true) {
    size_t nl = s.find('\n', start);
    if (nl == std::string::npos) {
      lines.push_back(s.substr(start));
      break;
    }
    lines.push_back(s.substr(start, nl - start));
    start = nl + 1;
  }
  if (dropFinalEmpty && !lines.empty() && lines.back().empty()) lines.pop_back();
  return lines;
}

std::string where(const DiagRecord& d) {
  return d.file + ":" + std::to_string(d.line) + ":" + std::to_string(d.col);
}

std::string diagText(const DiagRecord& d) { return where(d) + ": " + d.message; }

std::string firstLine(const std::string& s) {
  std::string line = s.substr(0, s.find('\n'));
  return line.size() > 300 ? line.substr(0, 300) + "..." : line;
}

std::string percent(double share) {
  char buf[32];
  double p = share * 100;
  std::snprintf(buf, sizeof buf, p != 0 && p < 0.01 ? "%.4f%%" : "%.2f%%", p);
  std::string s = buf;
  // 1.00% -> 1%, 3.20% -> 3.2%
  size_t pct = s.size() - 1;
  std::string num = s.substr(0, pct);
  if (num.find('.') != std::string::npos) {
    while (num.back() == '0') num.pop_back();
    if (num.back() == '.') num.pop_back();
  }
  return num + "%";
}

std::string point(P2 p) { return "(" + pixels(p.x) + ", " + pixels(p.y) + ")"; }

// ---------------------------------------------------------------- comment expectations

std::set<Expected> expectedSet(const std::vector<DiagRecord>& diags, const char* severity) {
  std::set<Expected> out;
  for (const DiagRecord& d : diags)
    if (d.severity == severity) out.insert({baseName(d.file), d.line, d.message});
  return out;
}

/// An expectation as the record carries it: its text in UTF-8 (see text.h).
Expected utf8(const Expected& e) { return {toUtf8(e.file), e.line, toUtf8(e.message)}; }

std::set<Expected> utf8(const std::set<Expected>& set) {
  std::set<Expected> out;
  for (const Expected& e : set) out.insert(utf8(e));
  return out;
}

std::string expectedText(const Expected& e) { return e.file + ":" + std::to_string(e.line) + ": " + e.message; }

/// The comments ask for rb check's extra warnings (--target rb9, --portable): the record's
/// target warnings count.
bool checkArgsTarget(const CommentSpec& spec) {
  for (size_t i = 0; i < spec.checkArgs.size(); ++i) {
    if (spec.checkArgs[i] == "--target=rb9" || spec.checkArgs[i] == "--portable") return true;
    if (spec.checkArgs[i] == "--target" && i + 1 < spec.checkArgs.size() && spec.checkArgs[i + 1] == "rb9")
      return true;
  }
  return false;
}

}  // namespace

std::string pixels(double v) {
  if (!std::isfinite(v)) return "infinitely";
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.1f", v);
  std::string s = buf;
  if (s.size() > 2 && s.compare(s.size() - 2, 2, ".0") == 0) s.resize(s.size() - 2);
  return s == "-0" ? "0" : s;
}

std::string outputDifference(const std::string& expected, const std::string& got, bool byLine) {
  if (expected == got) return "";
  // Lines as printed: a final newline ends the last line rather than starting an empty one.
  std::vector<std::string> want = splitLines(expected, true), have = splitLines(got, true);
  size_t n = std::min(want.size(), have.size());
  for (size_t i = 0; i < n; ++i)
    if (want[i] != have[i])
      return "output differs at line " + std::to_string(i + 1) + ": expected " + quote(want[i]) + ", got " +
             quote(have[i]);
  auto lines = [](size_t k) { return std::to_string(k) + " line" + (k == 1 ? "" : "s"); };
  if (want.size() > have.size())
    return "output ends after " + lines(have.size()) + "; expected " + std::to_string(want.size()) +
           ", the next being " + quote(want[have.size()]);
  if (have.size() > want.size())
    return "output has " + lines(have.size()) + ", expected " + std::to_string(want.size()) + "; line " +
           std::to_string(want.size() + 1) + " is " + quote(have[want.size()]);
  if (byLine) return "";
  bool wantNewline = !expected.empty() && expected.back() == '\n';
  return wantNewline ? "output lacks the newline at its end" : "output ends with a newline that was not expected";
}

std::optional<PixelDifference> compareImages(const render::RgbImage& a, const render::RgbImage& b) {
  if (a.width != b.width || a.height != b.height || a.rgb.size() != b.rgb.size()) return std::nullopt;
  PixelDifference d;
  d.total = static_cast<size_t>(a.width) * static_cast<size_t>(a.height);
  for (size_t i = 0; i < d.total; ++i) {
    const uint8_t* p = a.rgb.data() + i * 3;
    const uint8_t* q = b.rgb.data() + i * 3;
    if (p[0] != q[0] || p[1] != q[1] || p[2] != q[2]) ++d.differing;
  }
  return d;
}

std::optional<PixelDifference> compareScreens(const Screen& a, const Screen& b) {
  if (a.width != b.width || a.height != b.height) return std::nullopt;
  PixelDifference d;
  d.total = static_cast<size_t>(a.width) * static_cast<size_t>(a.height);
  size_t i = 0, j = 0;
  uint64_t leftA = a.runs.empty() ? 0 : a.runs[0].count, leftB = b.runs.empty() ? 0 : b.runs[0].count;
  uint64_t covered = 0;
  while (i < a.runs.size() && j < b.runs.size()) {
    uint64_t n = std::min(leftA, leftB);
    if (a.runs[i].rgb != b.runs[j].rgb) d.differing += n;
    covered += n;
    leftA -= n;
    leftB -= n;
    if (leftA == 0 && ++i < a.runs.size()) leftA = a.runs[i].count;
    if (leftB == 0 && ++j < b.runs.size()) leftB = b.runs[j].count;
  }
  if (covered < d.total) d.differing += d.total - covered;  // what one of them does not cover
  return d;
}

std::string unrunnable(const RunOutcome& run) {
  if (run.process.kind != JobOutcome::Exited) return run.processText;
  if (!run.record) {
    std::string why = "rb ended (exit " + std::to_string(run.process.code) + ") without reporting the run";
    if (!run.errors.empty()) why += ": " + firstLine(run.errors);
    return why;
  }
  const RunRecord& r = *run.record;
  if (r.status == "rejected") {
    std::string why = "does not compile";
    if (!r.loadErrors.empty()) {
      why += ": " + diagText(r.loadErrors[0]);
      if (r.loadErrors.size() > 1) why += " (and " + std::to_string(r.loadErrors.size() - 1) + " more)";
    }
    return why;
  }
  if (r.status == "not-run") {
    std::string why = "did not run (exit " + std::to_string(r.exitCode) + ")";
    if (!run.errors.empty()) why += ": " + firstLine(run.errors);
    return why;
  }
  return "";
}

std::string stopDescription(const RunRecord& r, const LimitNames& limits) {
  std::string steps = " after " + std::to_string(r.steps) + " step" + (r.steps == 1 ? "" : "s");
  std::string at = r.error ? " at " + where(*r.error) : "";
  std::string message = r.error ? r.error->message : "";
  if (r.status == "error") {
    if (r.crashed) return "the robot crashed" + at + steps + ": " + message;
    return "runtime error" + at + steps + ": " + message;
  }
  if (r.status == "limit") {
    std::string loop = r.loopFirst ? ", in the loop of lines " + std::to_string(r.loopFirst) + "-" +
                                         std::to_string(r.loopLast) + " (does it ever end?)"
                                   : "";
    if (r.limit == "max-steps")
      return "did not finish: stopped" + at + steps + ", the step limit (" + limits.steps + ")" + loop;
    return "did not finish: stopped" + at + steps + ", the time limit (" + limits.time + ")" + loop;
  }
  if (r.status == "stopped") return "stopped" + at + steps;
  return "";
}

std::string comparedOutput(const RunOutcome& run, bool prompts) {
  if (prompts || !run.record || run.record->inputs.empty()) return run.output;
  return printedOutput(run.output, run.record->inputs);
}

std::vector<CheckResult> checkComments(const CommentSpec& spec, const RunOutcome& run, const LimitNames& limits) {
  std::vector<CheckResult> results;
  auto fail = [&](const std::string& name, const std::string& message) {
    CheckResult c;
    c.name = name;
    c.message = message;
    results.push_back(c);
  };
  auto pass = [&](const std::string& name, const std::string& message) {
    CheckResult c;
    c.name = name;
    c.passed = true;
    c.message = message;
    c.earned = 1;
    results.push_back(c);
  };
  // A child killed at its time limit still wrote rb check's part of the record.
  bool checkKnown = run.record.has_value();
  std::string process = run.process.kind != JobOutcome::Exited ? run.processText
                        : !run.record ? unrunnable(run)
                                      : "";
  for (const std::string& p : spec.problems) fail("comments", p);

  // 1. rb check: exactly the expected errors and warnings, and its exit status.
  size_t before = results.size();
  if (!checkKnown) {
    fail("check", "rb check: " + process);
  } else {
    const RunRecord& r = *run.record;
    std::vector<DiagRecord> diags = r.checkDiags;
    if (checkArgsTarget(spec)) diags.insert(diags.end(), r.targetDiags.begin(), r.targetDiags.end());
    std::set<Expected> errors = expectedSet(diags, "error"), warnings = expectedSet(diags, "warning");
    std::set<Expected> wantErrors = utf8(spec.errors), wantWarnings = utf8(spec.warnings);
    for (const Expected& e : wantErrors)
      if (!errors.count(e)) fail("check", "rb check: missing error " + expectedText(e));
    for (const Expected& e : errors)
      if (!wantErrors.count(e)) fail("check", "rb check: unexpected error " + expectedText(e));
    for (const Expected& w : wantWarnings)
      if (!warnings.count(w)) fail("check", "rb check: missing warning " + expectedText(w));
    for (const Expected& w : warnings)
      if (!wantWarnings.count(w)) fail("check", "rb check: unexpected warning " + expectedText(w));
    int want = spec.errors.empty() ? 0 : 65;
    if (r.checkExit != want)
      fail("check", "rb check: exit status " + std::to_string(r.checkExit) + ", expected " + std::to_string(want));
  }
  if (results.size() == before) pass("check", "rb check reports what the comments expect");

  // 2. The run: standard output, the runtime error, standard error and the exit status.
  before = results.size();
  if (!process.empty()) {
    fail("run", process);
  } else if (!run.record->complete) {
    fail("run", "the run did not end: " + run.processText);
  } else {
    const RunRecord& r = *run.record;
    int want = 0;
    if (!spec.errors.empty()) {
      want = 65;
      std::set<Expected> got = expectedSet(r.loadErrors, "error");
      if (got != utf8(spec.errors)) {
        std::string list;
        for (const Expected& e : got) list += (list.empty() ? "" : "; ") + expectedText(e);
        fail("run", "rb run: errors differ from rb check's: " + (list.empty() ? "none" : list));
      }
      if (!run.output.empty())
        fail("output", "rb run printed output although the program was rejected: " + quote(run.output));
    } else {
      want = spec.runtime ? 70 : 0;
      std::string expected;
      for (const std::string& line : spec.output) expected += line + "\n";
      if (std::string diff = outputDifference(expected, run.output, false); !diff.empty())
        fail("output", "standard " + diff);
      if (spec.runtime) {
        std::optional<Expected> got;
        if (r.error) got = Expected{baseName(r.error->file), r.error->line, r.error->message};
        if (got != utf8(*spec.runtime))
          fail("runtime error", "runtime error " + (got ? expectedText(*got) : std::string("none")) +
                                    ", expected " + expectedText(utf8(*spec.runtime)));
      } else if (!run.errors.empty() && spec.stderrHas.empty()) {
        std::string stop = r.status == "limit" ? stopDescription(r, limits) : "";
        fail("stderr", stop.empty() ? "unexpected standard error (below)" : stop);
      }
    }
    for (const std::string& s : spec.stderrHas)
      if (run.errors.find(s) == std::string::npos)
        fail("stderr", "standard error lacks " + quote(s) + (run.errors.empty() ? " (it is empty)" : " (below)"));
    if (spec.exit) want = *spec.exit;
    if (run.process.code != want)
      fail("exit status", "exit status " + std::to_string(run.process.code) + ", expected " + std::to_string(want));
  }
  if (results.size() == before) pass("run", "the run does what the comments expect");
  return results;
}

// ---------------------------------------------------------------- assignment checks

namespace {

/// The verdict of one check on one run.
struct Verdict {
  Verdict(bool p, std::string m) : passed(p), message(std::move(m)) {}
  bool passed;
  std::string message;
  double earned = -1;  ///< points earned when not the check's own (a tier's); -1: the check's
  std::vector<std::string> feedback;
  std::optional<P2> at;  ///< where on the screen it failed, when it failed at a place
};

Verdict failedAt(std::string message, P2 at) {
  Verdict v{false, std::move(message)};
  v.at = at;
  return v;
}

Verdict checkOutput(const Check& c, const RunOutcome& run) {
  if (run.outputCut) return {false, "the output is longer than " + std::to_string(kOutputCap >> 20) + " MB"};
  std::string output = comparedOutput(run, c.prompts);
  if (c.text) {
    std::string diff = outputDifference(*c.text, output, true);
    if (diff.empty()) return {true, "the output is as expected"};
    return {false, diff};
  }
  std::vector<std::string> lines = splitLines(output, true);
  for (size_t i = 0; i < lines.size() && i < c.regexes.size(); ++i) {
    if (!RE2::FullMatch(lines[i], *c.regexes[i]))
      return {false, "output line " + std::to_string(i + 1) + " " + quote(lines[i]) + " does not match " +
                         quote(c.patterns[i])};
  }
  if (lines.size() != c.regexes.size())
    return {false, "output has " + std::to_string(lines.size()) + " line" + (lines.size() == 1 ? "" : "s") +
                       ", expected " + std::to_string(c.regexes.size())};
  return {true, "every output line matches its pattern"};
}

Verdict checkClean(const Check& c, const RunRecord& r) {
  std::vector<DiagRecord> diags = r.checkDiags;
  if (!c.target.empty()) diags.insert(diags.end(), r.targetDiags.begin(), r.targetDiags.end());
  std::vector<const DiagRecord*> errors, warnings;
  for (const DiagRecord& d : diags) {
    if (d.severity == "error") errors.push_back(&d);
    if (d.severity == "warning") warnings.push_back(&d);
  }
  auto count = [](size_t n, const char* what) {
    return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
  };
  // Every diagnostic the check counts, with its text: the first in the message, the others
  // below it (at most 20, then how many more).
  auto listed = [](Verdict v, const std::vector<const DiagRecord*>& all) {
    constexpr size_t kShown = 20;
    for (size_t i = 1; i < all.size() && i <= kShown; ++i) v.feedback.push_back(diagText(*all[i]));
    if (all.size() > kShown + 1) v.feedback.push_back("(and " + std::to_string(all.size() - kShown - 1) + " more)");
    return v;
  };
  if (!errors.empty())
    return listed({false, "rb check finds " + count(errors.size(), "error") + ": " + diagText(*errors[0])}, errors);
  if (!warnings.empty() && !c.allowWarnings)
    return listed({false, "rb check finds " + count(warnings.size(), "warning") + " (none allowed): " + diagText(*warnings[0])},
                  warnings);
  if (warnings.empty()) return {true, "rb check finds nothing"};
  return listed({true, "rb check finds " + count(warnings.size(), "warning") + " (allowed): " + diagText(*warnings[0])},
                warnings);
}

std::string regionText(const Region& g) {
  switch (g.kind) {
    case Region::Circle: return "the circle of radius " + pixels(g.r) + " around " + point({g.cx, g.cy});
    case Region::Rect: return "the rectangle " + point({g.x1, g.y1}) + "-" + point({g.x2, g.y2});
    case Region::Polygon: {
      std::string s = "the polygon " + point(g.points[0]);
      for (size_t i = 1; i < g.points.size() && i < 4; ++i) s += "-" + point(g.points[i]);
      if (g.points.size() > 4) s += "-...";
      return s;
    }
  }
  return "the region";
}

/// ", on line 12" for a line of the program, or "".
std::string onLine(uint32_t line) { return line ? " (line " + std::to_string(line) + ")" : ""; }

uint32_t pathLine(const RunRecord& r, size_t line, size_t point) {
  if (line < r.pathLines.size() && point < r.pathLines[line].size()) return r.pathLines[line][point];
  return 0;
}

Verdict checkEndsIn(const Check& c, const RunRecord& r) {
  if (!r.located) return {false, "the robot was never placed (no rLocate)"};
  const Region& g = c.regions[0];
  double off = outside(g, r.pos);
  if (off > 0)
    return failedAt("the robot ends at " + point(r.pos) + ", " + pixels(off) + " px outside " + regionText(g), r.pos);
  return {true, "the robot ends at " + point(r.pos) + ", inside " + regionText(g)};
}

Verdict checkVisits(const Check& c, const RunRecord& r) {
  if (!r.located) return {false, "the robot was never placed (no rLocate)"};
  VisitResult v = c.inOrder ? visitInOrder(r.path, c.targets, c.tolerance) : visitAny(r.path, c.targets, c.tolerance);
  if (!v.missed) return {true, "the robot passes every point" + std::string(c.inOrder ? " in order" : "")};
  size_t k = *v.missed;
  std::string which = "point " + std::to_string(k + 1) + " " + point(c.targets[k]);
  if (c.inOrder) {
    std::vector<P2> reversed(c.targets.rbegin(), c.targets.rend());
    if (!visitInOrder(r.path, reversed, c.tolerance).missed)
      return {false, "the robot passes every point, but in the opposite order: it does not reach " + which +
                         " after point " + std::to_string(k) + " (drawn the other way round?)"};
    // Every point is passed, only not in this order (a closed figure's last point is its first:
    // passing it at the start does not count).
    bool repeats = false;
    for (size_t j = 0; j < k; ++j) repeats = repeats || distance(c.targets[j], c.targets[k]) <= c.tolerance;
    if (!repeats && !visitAny(r.path, c.targets, c.tolerance).missed)
      return {false, "the robot passes every point, but not in the order asked: it does not reach " + which +
                         " after point " + std::to_string(k)};
  }
  std::string after = c.inOrder && k > 0 ? " after point " + std::to_string(k) : "";
  if (!std::isfinite(v.closest))
    return failedAt("the robot never reaches " + which + after + ": it does not move on", c.targets[k]);
  return failedAt("the robot misses " + which + after + " by " + pixels(v.closest - c.tolerance) + " px: it comes within " +
                      pixels(v.closest) + " px, " + pixels(c.tolerance) + " px allowed",
                  c.targets[k]);
}

Verdict compareTrails(const Polylines& got, const Polylines& want, double tolerance, const std::string& whose) {
  if (empty(got) && empty(want)) return {true, "neither draws a trail"};
  if (empty(got)) return {false, "the pen drew nothing; " + whose + " trail is " + pixels(length(want)) + " px long"};
  if (empty(want)) return {false, "the pen drew a trail of " + pixels(length(got)) + " px; " + whose + " has none"};
  HausdorffDistance h = hausdorff(got, want);
  std::string amount = pixels(h.distance) + " px";
  if (h.distance > tolerance) {
    std::string detail = h.fromA ? "the trail passes " + point(h.worst) + ", " + amount + " from " + whose
                                 : whose + " passes " + point(h.worst) + ", " + amount + " from the trail";
    return {false, "the trail is " + amount + " off " + whose + " at its worst, " + pixels(tolerance) +
                       " px allowed: " + detail};
  }
  return {true, "the trail is within " + amount + " of " + whose + ", " + pixels(tolerance) + " px allowed"};
}

Verdict screenVerdict(const std::optional<Screen>& got, const Screen& want, double tolerance,
                      const std::string& whose) {
  if (!got) return {false, "the final screen was not captured"};
  std::optional<PixelDifference> d = compareScreens(*got, want);
  if (!d)
    return {false, whose + " is " + std::to_string(want.width) + "x" + std::to_string(want.height) +
                       ", the screen " + std::to_string(got->width) + "x" + std::to_string(got->height)};
  std::string amount = percent(d->share()) + " of pixels (" + std::to_string(d->differing) + " of " +
                       std::to_string(d->total) + ")";
  if (d->share() > tolerance)
    return {false, "the screen differs from " + whose + " in " + amount + ", " + percent(tolerance) + " allowed"};
  return {true, "the screen differs from " + whose + " in " + amount + ", " + percent(tolerance) + " allowed"};
}

std::string colourText(const Check& c, size_t k) { return c.colourNames[k]; }

const RunRecord::Touch* touchOf(const RunRecord& r, uint32_t rgb) {
  for (const RunRecord::Touch& t : r.touches)
    if (t.rgb == rgb) return &t;
  return nullptr;
}

Verdict checkAvoid(const Check& c, const RunRecord& r) {
  for (const Region& g : c.regions) {
    Reach reach = firstReach(r.path, g, r.radius);
    if (reach.reached)
      return failedAt("the robot enters " + regionText(g) + " at " + point(reach.at) +
                          onLine(pathLine(r, reach.line, reach.point)),
                      reach.at);
  }
  for (size_t k = 0; k < c.colours.size(); ++k) {
    const RunRecord::Touch* t = touchOf(r, c.colours[k]);
    if (!t) return {false, "the colour " + colourText(c, k) + " was not watched"};
    if (t->touched) return failedAt("the robot touches " + colourText(c, k) + " at " + point(t->at) + onLine(t->line), t->at);
  }
  return {true, "the robot keeps out"};
}

Verdict checkTouch(const Check& c, const RunRecord& r) {
  if (!r.located) return {false, "the robot was never placed (no rLocate)"};
  for (const Region& g : c.regions) {
    Reach reach = firstReach(r.path, g, r.radius);
    if (!reach.reached)
      return {false, "the robot never reaches " + regionText(g) + ": it comes within " + pixels(reach.closest) + " px of it"};
  }
  for (size_t k = 0; k < c.colours.size(); ++k) {
    const RunRecord::Touch* t = touchOf(r, c.colours[k]);
    if (!t || !t->touched) return {false, "the robot never touches " + colourText(c, k)};
  }
  return {true, "the robot gets there"};
}

double measured(Check::Measure m, const RunRecord& r) {
  switch (m) {
    case Check::Statements: return static_cast<double>(r.steps);
    case Check::Moves: return static_cast<double>(r.moves);
    case Check::Distance: return length(r.path);
  }
  return 0;
}

std::string measureText(Check::Measure m, double v) {
  switch (m) {
    case Check::Statements: return pixels(v) + (v == 1 ? " statement" : " statements");
    case Check::Moves: return pixels(v) + (v == 1 ? " robot move" : " robot moves");
    case Check::Distance: return pixels(v) + " px of driving";
  }
  return pixels(v);
}

Verdict checkEfficiency(const Check& c, const RunRecord& r) {
  double v = measured(c.measure, r);
  for (const auto& [limit, points] : c.tiers)
    if (v <= limit) {
      Verdict verdict{true, measureText(c.measure, v) + ": at most " + pixels(limit) + " earn " + pixels(points) +
                                (points == c.points ? " (the best tier)" : " (at most " + pixels(c.tiers.front().first) +
                                                                               " earn " + pixels(c.points) + ")")};
      verdict.earned = points;
      return verdict;
    }
  return {false, measureText(c.measure, v) + ": more than the " + pixels(c.tiers.back().first) + " that earn points"};
}

Verdict checkPost(const Check& c, const RunRecord& r) {
  std::string name = std::filesystem::path(c.program).filename().string();
  if (c.postIndex >= r.posts.size()) return {false, "the check program " + name + " did not run"};
  const RunRecord::Post& p = r.posts[c.postIndex];
  Verdict v{true, ""};
  std::string failure;
  for (const std::string& line : splitLines(p.output, true)) {
    std::string trimmed = line;
    while (!trimmed.empty() && (trimmed.back() == ' ' || trimmed.back() == '\r')) trimmed.pop_back();
    size_t lead = trimmed.find_first_not_of(' ');
    std::string head = lead == std::string::npos ? "" : trimmed.substr(lead, 5);
    for (char& ch : head) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (head == "fail:") {
      std::string rest = trimmed.substr(lead + 5);
      while (!rest.empty() && rest[0] == ' ') rest.erase(0, 1);
      if (failure.empty()) failure = rest.empty() ? name + " says the check fails" : rest;
      continue;
    }
    v.feedback.push_back(trimmed);
  }
  if (p.error) {
    v.passed = false;
    v.message = p.ran ? "the check program " + name + " stopped at line " + std::to_string(p.error->line) + ": " +
                            p.error->message
                      : "the check program cannot run: " + p.error->message;
    return v;
  }
  if (!failure.empty()) {
    v.passed = false;
    v.message = failure;
    return v;
  }
  v.message = v.feedback.empty() ? name + " finds nothing wrong" : v.feedback.front();
  if (!v.feedback.empty()) v.feedback.erase(v.feedback.begin());
  return v;
}

Verdict evaluate(const Check& c, size_t index, const References& refs, const RunOutcome& run, size_t seedIndex);

Verdict evaluateGroup(const Check& c, const References& refs, const RunOutcome& run, size_t seedIndex) {
  std::vector<std::string> misses;
  for (const Check& m : c.of) {
    Verdict v = evaluate(m, SIZE_MAX, refs, run, seedIndex);
    if (c.kind == Check::AnyOf && v.passed) return {true, m.name + ": " + v.message};
    if (c.kind == Check::AllOf && !v.passed) return {false, m.name + ": " + v.message};
    misses.push_back(m.name + ": " + v.message);
  }
  if (c.kind == Check::AllOf) return {true, "all " + std::to_string(c.of.size()) + " pass"};
  std::string all;
  for (const std::string& m : misses) all += (all.empty() ? "" : "; ") + m;
  return {false, "none of " + std::to_string(c.of.size()) + " passes: " + all};
}

Verdict evaluateKind(const Check& c, size_t index, const References& refs, const RunOutcome& run, size_t seedIndex) {
  if (c.kind == Check::AnyOf || c.kind == Check::AllOf) return evaluateGroup(c, refs, run, seedIndex);
  std::string cannot = unrunnable(run);
  if (c.kind == Check::Clean && run.record) return checkClean(c, *run.record);
  if (!cannot.empty()) return {false, cannot};
  const RunRecord& r = *run.record;
  if (!r.worldError.empty()) return {false, r.worldError};
  const RunOutcome* sol = seedIndex < refs.solution.size() ? &refs.solution[seedIndex] : nullptr;
  switch (c.kind) {
    case Check::Output: return checkOutput(c, run);
    case Check::NoError: {
      std::string stop = stopDescription(r, refs.limits);
      if (!stop.empty()) return {false, stop};
      return {true, "finishes after " + std::to_string(r.steps) + " steps"};
    }
    case Check::NoCrash:
      if (r.crashed) return failedAt(stopDescription(r, refs.limits), r.pos);
      return {true, "the robot never crashes"};
    case Check::Clean: return checkClean(c, r);
    case Check::EndsIn: return checkEndsIn(c, r);
    case Check::Visits: return checkVisits(c, r);
    case Check::Trail: return compareTrails(r.trail, c.reference, c.tolerance, "the reference");
    case Check::Screen: {
      const std::optional<Screen>& picture = index < refs.pictures.size() ? refs.pictures[index] : std::nullopt;
      if (!picture) return {false, "the reference picture could not be read"};
      return screenVerdict(run.screen, *picture, c.tolerance, baseName(c.picture));
    }
    case Check::SolutionOutput: {
      if (!sol) return {false, "the solution did not run"};
      if (run.outputCut || sol->outputCut) return {false, "the output is longer than " + std::to_string(kOutputCap >> 20) + " MB"};
      std::string diff = outputDifference(comparedOutput(*sol, c.prompts), comparedOutput(run, c.prompts), true);
      if (diff.empty()) return {true, "the output is the solution's"};
      return {false, diff + " (the solution's output)"};
    }
    case Check::SolutionTrail:
      if (!sol || !sol->record) return {false, "the solution did not run"};
      return compareTrails(r.trail, sol->record->trail, c.tolerance, "the solution's");
    case Check::SolutionScreen:
      if (!sol || !sol->screen) return {false, "the solution's screen was not captured"};
      return screenVerdict(run.screen, *sol->screen, c.tolerance, "the solution's");
    case Check::Avoid: return checkAvoid(c, r);
    case Check::Touch: return checkTouch(c, r);
    case Check::Post: return checkPost(c, r);
    case Check::Efficiency: return checkEfficiency(c, r);
    case Check::AnyOf:
    case Check::AllOf: break;
  }
  return {false, "unknown check"};
}

/// The check, then its limits on statements, moves and distance.
Verdict evaluate(const Check& c, size_t index, const References& refs, const RunOutcome& run, size_t seedIndex) {
  Verdict v = evaluateKind(c, index, refs, run, seedIndex);
  if (!v.passed || !run.record) return v;
  const std::pair<const std::optional<double>*, Check::Measure> limits[] = {
      {&c.maxStatements, Check::Statements}, {&c.maxMoves, Check::Moves}, {&c.maxDistance, Check::Distance}};
  for (const auto& [limit, measure] : limits) {
    if (!*limit) continue;
    double got = measured(measure, *run.record);
    if (got > **limit)
      return {false, "it works, but takes " + measureText(measure, got) + ": at most " + pixels(**limit) + " allowed"};
  }
  return v;
}

/// Why nothing the program did can earn points, or "".
std::string gateOf(const RunOutcome& run, bool aboutRobot, const LimitNames& limits) {
  // A program that does not compile: said once, not as every check's failure with its hint.
  if (run.record && run.record->status == "rejected" && run.process.kind == JobOutcome::Exited)
    return "the program " + unrunnable(run);
  if (!run.record || run.record->status == "rejected" || run.record->status == "not-run") return "";
  const RunRecord& r = *run.record;
  if (!r.worldError.empty()) return "";
  if (r.statements == 0) return "the program is empty: it has no statement";
  if (aboutRobot && r.moves == 0) {
    std::string stop = stopDescription(r, limits);
    if (!stop.empty()) return stop + "; the robot never moved before that";
    return "the robot never moved: the program never places, moves or turns it";
  }
  return "";
}

}  // namespace

Grading checkAssignment(const Assignment& assignment, const References& refs, const std::vector<RunOutcome>& runs) {
  Grading grading;
  if (!runs.empty()) grading.gate = gateOf(runs[0], refs.aboutRobot, refs.limits);
  for (size_t i = 0; i < assignment.checks.size(); ++i) {
    const Check& c = assignment.checks[i];
    CheckResult result;
    result.name = c.name;
    result.points = c.points;
    result.hint = c.hint;
    result.hidden = c.hidden;
    result.required = c.required;
    if (!grading.gate.empty()) {
      result.checked = false;
      result.message = "not checked: " + grading.gate;
      grading.checks.push_back(std::move(result));
      continue;
    }
    if (!c.after.empty()) {
      const CheckResult* need = nullptr;
      for (const CheckResult& done : grading.checks)
        if (done.name == c.after) need = &done;
      if (need && !need->passed) {
        result.checked = false;
        result.message = "not checked: needs " + quote(c.after) + ", which did not pass";
        grading.checks.push_back(std::move(result));
        continue;
      }
    }
    result.passed = true;
    double earned = c.points;
    for (size_t s = 0; s < runs.size(); ++s) {
      Verdict v = evaluate(c, i, refs, runs[s], s);
      std::string prefix = runs.size() > 1 ? "seed " + std::to_string(runs[s].seed) + ": " : "";
      if (!v.passed) {
        result.passed = false;
        result.message = prefix + v.message;
        result.feedback = std::move(v.feedback);
        if (s == 0) result.at = v.at;  // the pictures show the first seed's run
        earned = 0;
        break;
      }
      if (v.earned >= 0) earned = std::min(earned, v.earned);
      if (s == 0) {
        result.message = v.message;
        result.feedback = std::move(v.feedback);
      }
    }
    result.earned = earned;
    grading.checks.push_back(std::move(result));
  }
  // A required check that failed: nothing else counts.
  for (const CheckResult& req : grading.checks) {
    if (!req.required || req.passed) continue;
    for (CheckResult& other : grading.checks)
      if (&other != &req && other.earned > 0) {
        other.earned = 0;
        other.note = "not counted: the required check " + quote(req.name) + " did not pass";
      }
    break;
  }
  return grading;
}

}  // namespace rb::grade
