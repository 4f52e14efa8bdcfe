#include "report.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>

#include "text.h"

namespace rb::grade {

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

std::string cleanUtf8(const std::string& s, bool xml) { return toUtf8(s, xml); }

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
    json j = {{"name", cleanUtf8(c.name, false)},
              {"passed", c.passed},
              {"checked", c.checked},
              {"message", cleanUtf8(c.message, false)},
              {"points", c.points},
              {"earned", c.earned}};
    if (!c.note.empty()) j["note"] = cleanUtf8(c.note, false);
    if (!c.hint.empty() && !c.passed) j["hint"] = cleanUtf8(c.hint, false);
    if (c.hidden) j["hidden"] = true;
    if (c.required) j["required"] = true;
    if (!c.feedback.empty()) {
      j["feedback"] = json::array();
      for (const std::string& f : c.feedback) j["feedback"].push_back(cleanUtf8(f, false));
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
  for (const std::string& n : p.notes) out += cleanUtf8(indent("note: " + n, "    "), false) + "\n";
  if (!p.gate.empty()) {
    out += "    " + p.gate + " (no check counts)\n";
  } else if (p.checks.empty()) {
    out += "    " + p.reason + "\n";
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
    std::string text = c.name + ": " + c.message;
    if (!c.note.empty()) text += " (" + c.note + ")";
    out += cleanUtf8(indent(text, "    "), false) + "\n";
    for (const std::string& f : c.feedback) out += cleanUtf8(indent(f, "      "), false) + "\n";
    if (!c.hint.empty()) out += cleanUtf8(indent("hint: " + c.hint, "      "), false) + "\n";
  }
  if (!voided.empty()) {
    std::string names;
    for (const std::string& n : voided) names += (names.empty() ? "" : ", ") + n;
    out += cleanUtf8(indent("passed, " + voidedBy + ": " + names, "    "), false) + "\n";
  }
  if (outputCheckFailed(p) && !p.output.empty()) {
    out += p.inputs.empty() ? "    what it printed:\n" : "    what it printed (> marks a line where input showed its prompt and read [text]):\n";
    out += cleanUtf8(indent(transcript(p), "      "), false) + "\n";
  }
  if (withErrors && !p.errors.empty()) out += "    error output:\n" + cleanUtf8(indent(p.errors, "      "), false) + "\n";
  return out;
}

}  // namespace

CheckResult shownCheck(const CheckResult& check, bool student) { return shown(check, student); }
std::string shownReason(const ProgramResult& program, bool student) { return reasonOf(program, student); }
std::string outputTranscript(const ProgramResult& program) { return transcript(program); }

std::string markupEscape(const std::string& text, std::string_view apostrophe) {
  std::string clean = cleanUtf8(text, true), out;
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
    nameWidth = std::max(nameWidth, std::min<size_t>(width(p.program), 60));
    studentWidth = std::max(studentWidth, std::min<size_t>(width(p.student), 30));
  }
  out += pad("program", nameWidth) + "  " + (students ? pad("student", studentWidth) + "  " : "") + "result  " +
         (r.assignment ? padLeft("points", 9) + "  " : "") + padLeft("steps", 9) + "  " + padLeft("time", 7) +
         "  reason\n";
  for (const ProgramResult& p : r.programs) {
    std::string verdict = p.verdict == "pass" ? "pass" : upper(p.verdict);
    if (verdict == "MISSING") verdict = "MISS";
    bool ran = p.verdict != "skip" && p.verdict != "missing" && !(p.checks.empty() && p.verdict == "fail");
    std::string line = pad(p.program, nameWidth) + "  " + (students ? pad(p.student, studentWidth) + "  " : "") +
                       pad(verdict, 6) + "  " +
                       (r.assignment ? padLeft(pointsText(p.points) + "/" + pointsText(p.maxPoints), 9) + "  " : "") +
                       padLeft(ran ? std::to_string(p.steps) : "-", 9) + "  " +
                       padLeft(ran ? seconds(p.seconds, "%.2fs") : "-", 7) + "  " + firstLine(reasonOf(p, r.studentView));
    while (!line.empty() && line.back() == ' ') line.pop_back();
    out += cleanUtf8(line, false) + "\n";
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
      out += p.program + (p.student.empty() ? "" : " (" + p.student + ")") + ":\n";
      out += details(p, r.studentView);
    }
  }
  if (r.similarity && !r.studentView) out += "\n" + similarityText(*r.similarity);
  size_t n = r.programs.size() - r.missing;
  out += "\n" + std::to_string(n) + " program" + (n == 1 ? "" : "s") + ": " + std::to_string(r.passed) +
         " passed, " + std::to_string(r.failed) + " failed";
  if (r.errors) out += ", " + std::to_string(r.errors) + " not graded (rb failed)";
  if (r.skipped) out += ", " + std::to_string(r.skipped) + " skipped";
  if (r.missing) out += "; " + std::to_string(r.missing) + " student" + (r.missing == 1 ? "" : "s") + " with no submission";
  out += " in " + seconds(r.seconds, "%.2f") + " s\n";
  return out;
}

std::string studentFeedback(const ProgramResult& p, const ClassResult& r) {
  std::string out = r.title + ": " + p.program + (p.student.empty() ? "" : " (" + p.student + ")") + "\n";
  out += "result: " + std::string(p.verdict == "pass" ? "passed" : p.verdict == "missing" ? "no submission" : "not passed");
  if (r.assignment) out += ", " + pointsText(p.points) + " of " + pointsText(p.maxPoints) + " points";
  out += "\n\n";
  if (p.checks.empty() || !p.gate.empty()) {
    out += reasonOf(p, true) + "\n";
    if (!p.gate.empty()) return out;
  }
  for (const CheckResult& raw : p.checks) {
    CheckResult c = shown(raw, true);
    std::string mark = !c.checked ? "[ ]" : c.passed ? "[x]" : "[!]";
    std::string pts = r.assignment ? " (" + pointsText(c.earned) + "/" + pointsText(c.points) + ")" : "";
    out += cleanUtf8(mark + " " + c.name + pts + ": " + c.message, false) + "\n";
    if (!c.note.empty()) out += "      " + cleanUtf8(c.note, false) + "\n";
    for (const std::string& f : c.feedback) out += cleanUtf8(indent(f, "      "), false) + "\n";
    if (!c.passed && !c.hint.empty()) out += cleanUtf8(indent("hint: " + c.hint, "      "), false) + "\n";
  }
  if (!p.output.empty()) {
    out += "\nyour program's output" + std::string(p.inputs.empty() ? "" : " (> marks where input showed its prompt and read [text])") + ":\n";
    out += cleanUtf8(indent(transcript(p), "  "), false) + "\n";
  }
  if (!p.errors.empty()) out += "\nerror output:\n" + cleanUtf8(indent(p.errors, "  "), false) + "\n";
  return out;
}

std::string jsonReport(const ClassResult& r) {
  json doc;
  doc["title"] = r.title;
  doc["timestamp"] = r.timestamp;
  if (r.studentView) doc["student_view"] = true;
  doc["programs"] = json::array();
  for (const ProgramResult& p : r.programs) {
    json j = {{"program", cleanUtf8(p.program, false)}, {"result", p.verdict}, {"reason", cleanUtf8(reasonOf(p, r.studentView), false)},
              {"steps", p.steps},     {"seconds", p.seconds}, {"points", p.points},
              {"max_points", p.maxPoints}, {"checks", checksJson(p.checks, r.studentView)}};
    if (!p.student.empty()) j["student"] = cleanUtf8(p.student, false);
    if (!p.gate.empty()) j["gate"] = cleanUtf8(p.gate, false);
    if (!p.notes.empty()) {
      j["notes"] = json::array();
      for (const std::string& n : p.notes) j["notes"].push_back(cleanUtf8(n, false));
    }
    if (!p.picture.empty()) j["picture"] = p.picture;
    if (!p.replay.empty()) j["replay"] = p.replay;
    if (!p.output.empty()) j["output"] = cleanUtf8(p.output, false);
    if (!p.inputs.empty()) {
      j["inputs"] = json::array();
      for (const RunRecord::InputMark& m : p.inputs)
        j["inputs"].push_back({{"start", m.start}, {"prompt_end", m.promptEnd}, {"end", m.end}});
    }
    if (!p.errors.empty()) j["errors"] = cleanUtf8(p.errors, false);
    doc["programs"].push_back(std::move(j));
  }
  if (r.similarity && !r.studentView) doc["similarity"] = json::parse(similarityJson(*r.similarity));
  doc["summary"] = {{"programs", r.programs.size() - r.missing}, {"passed", r.passed}, {"failed", r.failed},
                    {"errors", r.errors},           {"skipped", r.skipped}, {"missing", r.missing},
                    {"seconds", r.seconds}};
  return doc.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
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
  if (!r.programs.empty()) {
    out += "    <properties>\n";
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
    out += csvField(n);
  }
  out += '\n';
  for (const ProgramResult& p : r.programs) {
    size_t passed = 0;
    for (const CheckResult& c : p.checks) passed += c.passed;
    out += (students ? csvField(cleanUtf8(p.student, false)) + "," : "") + csvField(p.program) + "," + p.verdict + "," +
           pointsText(p.points) + "," + pointsText(p.maxPoints) + "," + std::to_string(passed) + "," +
           std::to_string(p.checks.size()) + "," + std::to_string(p.steps) + "," + seconds(p.seconds) + "," +
           csvField(cleanUtf8(reasonOf(p, r.studentView), false));
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
