#include "report.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <re2/re2.h>

#include "merge.h"
#include "text.h"

namespace rb::grade {

using record::RunRecord;
using record::TextShape;
using record::csvTextField;
using record::shownText;
using record::toUtf8;

using nlohmann::json;

namespace {

std::string seconds(double s, const char* format = "%.3f") {
  char buf[32];
  std::snprintf(buf, sizeof buf, format, s);
  return buf;
}

std::string firstLine(const std::string& s) { return s.substr(0, s.find('\n')); }

std::string indent(const std::string& text, const std::string& by) {
  std::string out = by;
  for (char c : text) {
    out += c;
    if (c == '\n') out += by;
  }
  while (!out.empty() && (out.back() == ' ' || out.back() == '\n')) out.pop_back();
  return out;
}

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

std::string pointsText(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

/// The number of UTF-8 code points, for aligning columns.
size_t width(const std::string& s) {
  size_t n = 0;
  for (unsigned char c : s) n += (c & 0xC0) != 0x80;
  return n;
}

std::string pad(const std::string& s, size_t w) { return s + std::string(w > width(s) ? w - width(s) : 0, ' '); }
std::string padLeft(const std::string& s, size_t w) { return std::string(w > width(s) ? w - width(s) : 0, ' ') + s; }

/// Untrusted text as the reports show it (text.h): a name, a message, a reason on one line.
std::string line(const std::string& s) { return shownText(s, TextShape::Line); }
/// Line `n` (1-based) of a program's text, without its line end; "" when there is none.
std::string sourceLine(const std::string& text, uint32_t n) {
  size_t start = 0;
  for (uint32_t i = 1; i < n; ++i) {
    start = text.find('\n', start);
    if (start == std::string::npos) return "";
    ++start;
  }
  std::string out = text.substr(start, text.find('\n', start) - start);
  if (!out.empty() && out.back() == '\r') out.pop_back();
  return out.size() > 200 ? out.substr(0, 200) + "..." : out;
}

/// Lines: output, errors, a teacher's hint or feedback.
std::string block(const std::string& s) { return shownText(s, TextShape::Block); }

/// A check as a report shows it: hidden ones reduced to their verdict in a student's report.
CheckResult shown(const CheckResult& c, bool student) {
  if (!student || !c.hidden) return c;
  CheckResult h;
  h.name = "hidden check";
  h.passed = c.passed;
  h.checked = c.checked;
  h.message = c.passed ? "passed" : "a hidden check failed";
  h.note = c.note;
  h.points = c.points;
  h.earned = c.earned;
  h.hidden = true;
  return h;
}

/// The first reason a program failed, as a student may see it.
std::string reasonOf(const ProgramResult& p, bool student) {
  if (!student || !p.gate.empty()) return p.reason;
  for (const CheckResult& c : p.checks)
    if (!c.passed) return shown(c, true).message;
  return p.reason;
}

json checksJson(const std::vector<CheckResult>& checks, bool student) {
  json out = json::array();
  for (const CheckResult& raw : checks) {
    CheckResult c = shown(raw, student);
    json j = {{"name", line(c.name)},
              {"passed", c.passed},
              {"checked", c.checked},
              {"message", line(c.message)},
              {"points", c.points},
              {"earned", c.earned}};
    if (!c.note.empty()) j["note"] = line(c.note);
    if (!c.hint.empty() && !c.passed) j["hint"] = block(c.hint);
    if (c.hidden) j["hidden"] = true;
    if (c.required) j["required"] = true;
    if (!c.feedback.empty()) {
      j["feedback"] = json::array();
      for (const std::string& f : c.feedback) j["feedback"].push_back(block(f));
    }
    out.push_back(std::move(j));
  }
  return out;
}

/// The output with what input showed marked: each line an input touched starts with "> " and
/// the text it read is in [brackets]; other lines start with two blanks.
std::string transcript(const ProgramResult& p) {
  std::string out, line;
  bool marked = false;
  size_t next = 0;
  auto endLine = [&] {
    out += (marked ? "> " : "  ") + line + "\n";
    line.clear();
    marked = false;
  };
  for (size_t i = 0; i < p.output.size();) {
    if (next < p.inputs.size() && i == p.inputs[next].start) {
      const RunRecord::InputMark& m = p.inputs[next++];
      marked = true;
      size_t promptEnd = std::min<size_t>(m.promptEnd, p.output.size());
      size_t end = std::min<size_t>(m.end, p.output.size());
      line += p.output.substr(i, promptEnd - i);
      std::string typed = p.output.substr(promptEnd, end - promptEnd);
      if (!typed.empty() && typed.back() == '\n') typed.pop_back();
      line += "[" + typed + "]";
      i = end;
      endLine();
      continue;
    }
    if (p.output[i] == '\n') endLine();
    else line += p.output[i];
    ++i;
  }
  if (!line.empty()) endLine();
  return out;
}

bool outputCheckFailed(const ProgramResult& p) {
  for (const CheckResult& c : p.checks)
    if (!c.passed && c.checked && !c.hidden &&
        (c.name.find("output") != std::string::npos || c.message.find("output") != std::string::npos))
      return true;
  return false;
}

std::string className(const ProgramResult& p, const ClassResult& r) {
  std::string dir = std::filesystem::path(p.program).parent_path().string();
  return dir.empty() ? r.title : dir;
}

bool failed(const ProgramResult& p) { return p.verdict == "fail" || p.verdict == "error" || p.verdict == "missing"; }

/// The details of one failed program, indented, as the text report and the student feedback
/// files show them.
std::string details(const ProgramResult& p, bool student, bool withErrors = true) {
  std::string out;
  for (const std::string& n : p.notes) out += "    note: " + line(n) + "\n";
  if (!p.gate.empty()) {
    out += "    " + line(p.gate) + " (no check counts)\n";
  } else if (p.checks.empty()) {
    out += "    " + line(p.reason) + "\n";
  }
  bool hiddenSaid = false;
  std::vector<CheckResult> list;
  // Messages that several checks fail with (a program that does not compile) are said once,
  // without the hints: the checks could not look at anything.
  std::map<std::string, int> repeats;
  for (const CheckResult& c : p.checks)
    if (!c.passed) ++repeats[c.message];
  std::string voidedBy;
  std::vector<std::string> voided;
  for (const CheckResult& raw : p.checks) {
    if (raw.passed && raw.note.empty()) continue;
    if (!p.gate.empty()) break;
    CheckResult c = shown(raw, student);
    if (c.hidden && student) {
      if (hiddenSaid) continue;
      hiddenSaid = true;
    }
    if (c.passed) {  // passed, not counted: one line for them all
      voidedBy = c.note;
      voided.push_back(c.name);
      continue;
    }
    bool shared = repeats[c.message] > 1;
    if (shared) c.hint.clear();
    if (shared && !list.empty() && !list.back().passed && list.back().message == c.message && c.feedback.empty() &&
        c.note.empty() && list.back().note.empty()) {
      list.back().name += ", " + c.name;
      continue;
    }
    list.push_back(c);
  }
  for (const CheckResult& c : list) {
    out += "    " + line(c.name) + ": " + line(c.message);
    if (!c.note.empty()) out += " (" + line(c.note) + ")";
    out += "\n";
    for (const std::string& f : c.feedback) out += indent(block(f), "      ") + "\n";
    if (!c.hint.empty()) out += indent("hint: " + block(c.hint), "      ") + "\n";
  }
  if (!voided.empty()) {
    std::string names;
    for (const std::string& n : voided) names += (names.empty() ? "" : ", ") + line(n);
    out += "    passed, " + line(voidedBy) + ": " + names + "\n";
  }
  if (outputCheckFailed(p) && !p.output.empty()) {
    out += p.inputs.empty() ? "    what it printed:\n" : "    what it printed (> marks a line where input showed its prompt and read [text]):\n";
    out += indent(block(transcript(p)), "      ") + "\n";
  }
  if (withErrors && !p.errors.empty()) out += "    error output:\n" + indent(block(p.errors), "      ") + "\n";
  return out;
}

/// The output as the JSON report shows it (block()), and where input marked it in that text.
std::pair<std::string, std::vector<RunRecord::InputMark>> shownOutput(const ProgramResult& p) {
  std::vector<size_t> offsets;
  for (const RunRecord::InputMark& m : p.inputs) offsets.insert(offsets.end(), {m.start, m.promptEnd, m.end});
  std::string text = shownText(p.output, TextShape::Block, &offsets);
  std::vector<RunRecord::InputMark> marks;
  for (size_t i = 0; i + 2 < offsets.size(); i += 3) marks.push_back({offsets[i], offsets[i + 1], offsets[i + 2]});
  return {text, marks};
}

}  // namespace

std::string withoutGrants(const std::string& text) {
  // A parenthesis that names what grants access, and "; rb run --allow-spawn allows it".
  static const RE2 aside(R"(\s*\([^()]*(?:--allow-files|--allow-spawn|--trust-comments|--port\b|--real\b|)"
                         R"(ports = true|spawn = true)[^()]*\))");
  static const RE2 clause(R"(;\s*rb (?:run|test) --[a-z-]+[^;()\n]*allows? [^;()\n]*)");
  std::string out = text;
  RE2::GlobalReplace(&out, aside, "");
  RE2::GlobalReplace(&out, clause, "");
  return out;
}

ProgramResult forStudents(ProgramResult p) {
  p.reason = withoutGrants(p.reason);
  p.gate = withoutGrants(p.gate);
  p.errors = withoutGrants(p.errors);
  for (std::string& n : p.notes) n = withoutGrants(n);
  for (ProgramResult::LineMark& m : p.marks) m.message = withoutGrants(m.message);
  for (CheckResult& c : p.checks) {
    c.message = withoutGrants(c.message);
    c.note = withoutGrants(c.note);
    for (std::string& f : c.feedback) f = withoutGrants(f);
  }
  return p;
}

CheckResult shownCheck(const CheckResult& check, bool student) { return shown(check, student); }
std::string shownReason(const ProgramResult& program, bool student) { return reasonOf(program, student); }
std::string outputTranscript(const ProgramResult& program) { return transcript(program); }

std::string markupEscape(const std::string& text, std::string_view apostrophe) {
  std::string clean = block(text), out;
  out.reserve(clean.size());
  for (char c : clean) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += apostrophe; break;
      default: out += c;
    }
  }
  return out;
}

std::string xmlEscape(const std::string& text) { return markupEscape(text, "&apos;"); }


std::string textReport(const ClassResult& r, bool showDetails) {
  std::string out;
  bool students = false;
  for (const ProgramResult& p : r.programs) students = students || !p.student.empty();
  size_t nameWidth = 7, studentWidth = 7;
  for (const ProgramResult& p : r.programs) {
    nameWidth = std::max(nameWidth, std::min<size_t>(width(line(p.program)), 60));
    studentWidth = std::max(studentWidth, std::min<size_t>(width(line(p.student)), 30));
  }
  out += pad("program", nameWidth) + "  " + (students ? pad("student", studentWidth) + "  " : "") + "result  " +
         (r.assignment ? padLeft("points", 9) + "  " : "") + padLeft("steps", 9) + "  " + padLeft("time", 7) +
         "  reason\n";
  for (const ProgramResult& p : r.programs) {
    std::string verdict = p.verdict == "pass" ? "pass" : upper(p.verdict);
    if (verdict == "MISSING") verdict = "MISS";
    bool ran = p.verdict != "skip" && p.verdict != "missing" && !(p.checks.empty() && p.verdict == "fail");
    std::string row = pad(line(p.program), nameWidth) + "  " + (students ? pad(line(p.student), studentWidth) + "  " : "") +
                      pad(verdict, 6) + "  " +
                      (r.assignment ? padLeft(pointsText(p.points) + "/" + pointsText(p.maxPoints), 9) + "  " : "") +
                      padLeft(ran ? std::to_string(p.steps) : "-", 9) + "  " +
                      padLeft(ran ? seconds(p.seconds, "%.2fs") : "-", 7) + "  " + line(reasonOf(p, r.studentView));
    while (!row.empty() && row.back() == ' ') row.pop_back();
    out += row + "\n";
  }
  if (showDetails) {
    bool header = false;
    for (const ProgramResult& p : r.programs) {
      bool notes = !p.notes.empty();
      for (const CheckResult& c : p.checks) notes = notes || !c.note.empty();
      if (!failed(p) && !notes) continue;
      if (p.verdict == "missing" || (p.checks.empty() && p.gate.empty())) continue;  // the table said it all
      if (!header) out += "\n";
      header = true;
      out += line(p.program) + (p.student.empty() ? "" : " (" + line(p.student) + ")") + ":\n";
      out += details(p, r.studentView);
    }
  }
  if (r.similarity && !r.studentView) out += "\n" + similarityText(*r.similarity);
  if (!r.confinement.empty() && !r.studentView) out += "\nnote: " + line(r.confinement) + "\n";
  size_t n = r.programs.size() - r.missing;
  out += "\n" + std::to_string(n) + " program" + (n == 1 ? "" : "s") + ": " + std::to_string(r.passed) +
         " passed, " + std::to_string(r.failed) + " failed";
  if (r.errors) out += ", " + std::to_string(r.errors) + " not graded (rb failed)";
  if (r.skipped) out += ", " + std::to_string(r.skipped) + " skipped";
  if (r.missing) out += "; " + std::to_string(r.missing) + " student" + (r.missing == 1 ? "" : "s") + " with no submission";
  out += " in " + seconds(r.seconds, "%.2f") + " s\n";
  return out;
}

std::string studentFeedback(const ProgramResult& program, const ClassResult& r) {
  const ProgramResult p = forStudents(program);
  std::string out = line(r.title) + ": " + line(p.program) + (p.student.empty() ? "" : " (" + line(p.student) + ")") + "\n";
  out += "result: " + std::string(p.verdict == "pass" ? "passed" : p.verdict == "missing" ? "no submission" : "not passed");
  if (r.assignment) out += ", " + pointsText(p.points) + " of " + pointsText(p.maxPoints) + " points";
  out += "\n\n";
  if (p.checks.empty() || !p.gate.empty()) {
    out += line(reasonOf(p, true)) + "\n";
    // The lines where it went wrong, as the program has them: said once, not under every check.
    size_t shownMarks = 0;
    for (const ProgramResult::LineMark& m : p.marks) {
      if (shownMarks++ == 3) break;
      std::string text = sourceLine(p.source, m.line);
      if (!text.empty()) out += "  " + std::to_string(m.line) + " | " + line(text) + "\n";
    }
    if (!p.gate.empty()) return out;
  }
  for (const CheckResult& raw : p.checks) {
    CheckResult c = shown(raw, true);
    std::string mark = !c.checked ? "[ ]" : c.passed ? "[x]" : "[!]";
    std::string pts = r.assignment ? " (" + pointsText(c.earned) + "/" + pointsText(c.points) + ")" : "";
    out += mark + " " + line(c.name) + pts + ": " + line(c.message) + "\n";
    if (!c.note.empty()) out += "      " + line(c.note) + "\n";
    for (const std::string& f : c.feedback) out += indent(block(f), "      ") + "\n";
    if (!c.passed && !c.hint.empty()) out += indent("hint: " + block(c.hint), "      ") + "\n";
  }
  if (!p.output.empty()) {
    out += "\nyour program's output" + std::string(p.inputs.empty() ? "" : " (> marks where input showed its prompt and read [text])") + ":\n";
    out += indent(block(transcript(p)), "  ") + "\n";
  }
  if (!p.errors.empty()) out += "\nerror output:\n" + indent(block(p.errors), "  ") + "\n";
  return out;
}

std::string jsonReport(const ClassResult& r) {
  json doc;
  // What rb test --merge reads back (merge.h): the version of this shape, what tells gradings
  // apart, and below each program's name, source, screen and marks.
  doc["report_version"] = kJsonReportVersion;
  if (!r.origin.rbVersion.empty()) doc["rb_version"] = r.origin.rbVersion;
  doc["title"] = line(r.title);
  doc["timestamp"] = r.timestamp;
  if (r.studentView) doc["student_view"] = true;
  doc["paths"] = json::array();
  for (const std::string& p : r.origin.paths) doc["paths"].push_back(toUtf8(p));
  doc["shard"] = {{"index", r.origin.shard}, {"of", r.origin.shards}};
  if (r.assignment) {
    doc["assignment"] = {{"max_points", r.maxPoints}};
    if (!r.origin.assignmentFile.empty()) doc["assignment"]["file"] = toUtf8(r.origin.assignmentFile);
    if (!r.origin.assignmentDigest.empty()) doc["assignment"]["digest"] = r.origin.assignmentDigest;
  }
  if (!r.warnings.empty()) {
    doc["warnings"] = json::array();
    for (const std::string& w : r.warnings) doc["warnings"].push_back(line(w));
  }
  doc["programs"] = json::array();
  for (const ProgramResult& p : r.programs) {
    json j = {{"program", line(p.program)}, {"result", p.verdict}, {"reason", line(reasonOf(p, r.studentView))},
              {"steps", p.steps},     {"seconds", p.seconds}, {"points", p.points},
              {"max_points", p.maxPoints}, {"checks", checksJson(p.checks, r.studentView)}};
    if (!p.student.empty()) j["student"] = line(p.student);
    if (!p.gate.empty()) j["gate"] = line(p.gate);
    if (!p.notes.empty()) {
      j["notes"] = json::array();
      for (const std::string& n : p.notes) j["notes"].push_back(line(n));
    }
    if (!p.name.empty()) j["name"] = toUtf8(p.name);
    if (!p.isProgram) j["not_a_program"] = true;
    // The text as graded, byte for byte (merging compares it again for --similarity and shows
    // it on the program's page): base64 shows nothing of it to whoever reads the report.
    if (p.sourceRead) j["source_base64"] = base64Encode(p.source);
    if (!p.picture.empty()) j["picture"] = toUtf8(p.picture);
    if (!p.pictureCaption.empty()) j["picture_caption"] = line(p.pictureCaption);
    if (!p.screen.empty()) j["screen"] = toUtf8(p.screen);
    if (!p.replay.empty()) j["replay"] = toUtf8(p.replay);
    if (!p.marks.empty()) {
      j["marks"] = json::array();
      for (const ProgramResult::LineMark& m : p.marks) j["marks"].push_back({{"line", m.line}, {"message", block(m.message)}});
    }
    if (!p.output.empty()) {
      auto [output, marks] = shownOutput(p);
      j["output"] = output;
      if (!marks.empty()) {
        j["inputs"] = json::array();
        for (const RunRecord::InputMark& m : marks)
          j["inputs"].push_back({{"start", m.start}, {"prompt_end", m.promptEnd}, {"end", m.end}});
      }
    }
    if (!p.errors.empty()) j["errors"] = block(p.errors);
    doc["programs"].push_back(std::move(j));
  }
  if (r.similarity && !r.studentView) doc["similarity"] = json::parse(similarityJson(*r.similarity));
  if (!r.confinement.empty() && !r.studentView) doc["confinement"] = line(r.confinement);
  doc["summary"] = {{"programs", r.programs.size() - r.missing}, {"passed", r.passed}, {"failed", r.failed},
                    {"errors", r.errors},           {"skipped", r.skipped}, {"missing", r.missing},
                    {"seconds", r.seconds}};
  // The paths of pictures and replays are kept as they are, to be opened: a "##[" in them (a
  // GitHub runner's older workflow command, looked for anywhere in a line) is written with
  // JSON's escape for the second '#', which reads back as the same path.
  std::string text = doc.dump(2, ' ', false, json::error_handler_t::replace);
  for (size_t at = text.find("##["); at != std::string::npos; at = text.find("##[", at))
    text.replace(at + 1, 1, "\\u0023");
  return text + "\n";
}

std::string junitReport(const ClassResult& r) {
  char host[256] = "localhost";
  gethostname(host, sizeof host - 1);
  // The shape of Jenkins' xunit plugin's junit-10.xsd (testdata/grade/jenkins-junit-10.xsd),
  // which pytest's xunit2 reports also follow: `skipped` is counted on the testsuite only, and a
  // test case has no `file` attribute; each program's path is a property of the suite instead
  // ("file: NAME" = path), the place that schema gives.
  std::string counts = " tests=\"" + std::to_string(r.programs.size()) + "\" failures=\"" +
                       std::to_string(r.failed + r.missing) + "\" errors=\"" + std::to_string(r.errors) + "\"";
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<testsuites name=\"" + xmlEscape(r.title) + "\"" + counts + " time=\"" + seconds(r.seconds) + "\">\n";
  out += "  <testsuite name=\"" + xmlEscape(r.title) + "\"" + counts + " skipped=\"" + std::to_string(r.skipped) +
         "\" time=\"" + seconds(r.seconds) + "\" timestamp=\"" + r.timestamp + "\" hostname=\"" + xmlEscape(host) +
         "\">\n";
  auto caseName = [](const ProgramResult& p) {
    std::string name = std::filesystem::path(p.program).filename().string();
    if (name.empty()) name = p.program;
    if (!p.student.empty()) name += " (" + p.student + ")";
    return name;
  };
  if (!r.programs.empty() || (!r.confinement.empty() && !r.studentView)) {
    out += "    <properties>\n";
    if (!r.confinement.empty() && !r.studentView)
      out += "      <property name=\"confinement\" value=\"" + xmlEscape(line(r.confinement)) + "\"/>\n";
    for (const ProgramResult& p : r.programs)
      out += "      <property name=\"file: " + xmlEscape(caseName(p)) + "\" value=\"" + xmlEscape(p.program) + "\"/>\n";
    out += "    </properties>\n";
  }
  for (const ProgramResult& p : r.programs) {
    std::string name = caseName(p);
    out += "    <testcase name=\"" + xmlEscape(name) + "\" classname=\"" + xmlEscape(className(p, r)) +
           "\" time=\"" + seconds(p.seconds) + "\"";
    std::string body;
    if (p.verdict == "skip") {
      body += "      <skipped message=\"" + xmlEscape(p.reason) + "\"/>\n";
    } else if (failed(p)) {
      const char* tag = p.verdict == "error" ? "error" : "failure";
      std::string type = p.verdict == "missing" ? "missing" : "run";
      for (const CheckResult& c : p.checks)
        if (!c.passed) {
          type = shown(c, r.studentView).name;
          break;
        }
      if (!p.gate.empty()) type = "gate";
      std::string text = details(p, r.studentView, false);  // the errors are in <system-err>
      if (text.empty()) text = p.reason + "\n";
      body += "      <" + std::string(tag) + " message=\"" + xmlEscape(firstLine(reasonOf(p, r.studentView))) + "\" type=\"" +
              xmlEscape(type) + "\">" + xmlEscape(text) + "</" + tag + ">\n";
    }
    if (!p.output.empty()) body += "      <system-out>" + xmlEscape(p.output) + "</system-out>\n";
    if (!p.errors.empty()) body += "      <system-err>" + xmlEscape(p.errors) + "</system-err>\n";
    out += body.empty() ? "/>\n" : ">\n" + body + "    </testcase>\n";
  }
  out += "  </testsuite>\n</testsuites>\n";
  return out;
}

std::string csvReport(const ClassResult& r) {
  // One column per check when every graded program has the same checks (an assignment).
  std::vector<std::string> names;
  bool same = true, any = false;
  for (const ProgramResult& p : r.programs) {
    if (p.checks.empty()) continue;
    std::vector<std::string> these;
    for (const CheckResult& c : p.checks) these.push_back(shown(c, r.studentView).name);
    if (!any) names = these;
    else same = same && names == these;
    any = true;
  }
  if (!same) names.clear();
  bool students = false;
  for (const ProgramResult& p : r.programs) students = students || !p.student.empty();
  std::string out = std::string(students ? "student," : "") +
                    "program,result,points,max_points,checks_passed,checks,steps,seconds,reason";
  for (const std::string& n : names) {
    out += ',';
    out += csvTextField(n);
  }
  out += '\n';
  for (const ProgramResult& p : r.programs) {
    size_t passed = 0;
    for (const CheckResult& c : p.checks) passed += c.passed;
    out += (students ? csvTextField(p.student) + "," : "") + csvTextField(p.program) + "," + p.verdict + "," +
           pointsText(p.points) + "," + pointsText(p.maxPoints) + "," + std::to_string(passed) + "," +
           std::to_string(p.checks.size()) + "," + std::to_string(p.steps) + "," + seconds(p.seconds) + "," +
           csvTextField(reasonOf(p, r.studentView));
    for (size_t i = 0; i < names.size(); ++i) {
      out += ',';
      if (i < p.checks.size()) out += pointsText(p.checks[i].earned);
      else if (p.checks.empty()) out += "0";
    }
    out += '\n';
  }
  return out;
}

}  // namespace rb::grade
