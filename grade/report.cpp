#include "report.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
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

json checksJson(const std::vector<CheckResult>& checks) {
  json out = json::array();
  for (const CheckResult& c : checks)
    out.push_back({{"name", cleanUtf8(c.name, false)},
                   {"passed", c.passed},
                   {"message", cleanUtf8(c.message, false)},
                   {"points", c.points}});
  return out;
}

std::string className(const ProgramResult& p, const ClassResult& r) {
  std::string dir = std::filesystem::path(p.program).parent_path().string();
  return dir.empty() ? r.title : dir;
}

}  // namespace

std::string xmlEscape(const std::string& text) {
  std::string clean = cleanUtf8(text, true), out;
  for (char c : clean) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

std::string textReport(const ClassResult& r, bool details) {
  std::string out;
  size_t nameWidth = 7;
  for (const ProgramResult& p : r.programs) nameWidth = std::max(nameWidth, std::min<size_t>(width(p.program), 60));
  out += pad("program", nameWidth) + "  result  " + padLeft("steps", 9) + "  " + padLeft("time", 7) + "  reason\n";
  for (const ProgramResult& p : r.programs) {
    std::string verdict = p.verdict == "pass" ? "pass" : upper(p.verdict);
    std::string line = pad(p.program, nameWidth) + "  " + pad(verdict, 6) + "  " +
                       padLeft(p.verdict == "skip" ? "-" : std::to_string(p.steps), 9) + "  " +
                       padLeft(seconds(p.seconds, "%.2fs"), 7) + "  " + firstLine(p.reason);
    while (!line.empty() && line.back() == ' ') line.pop_back();
    out += cleanUtf8(line, false) + "\n";
  }
  if (details) {
    bool header = false;
    for (const ProgramResult& p : r.programs) {
      if (p.verdict != "fail" && p.verdict != "error") continue;
      if (!header) out += "\n";
      header = true;
      out += p.program + ":\n";
      for (const CheckResult& c : p.checks)
        if (!c.passed) out += cleanUtf8(indent(c.name + ": " + c.message, "    "), false) + "\n";
      if (p.checks.empty()) out += "    " + p.reason + "\n";
    }
  }
  size_t n = r.programs.size();
  out += "\n" + std::to_string(n) + " program" + (n == 1 ? "" : "s") + ": " + std::to_string(r.passed) +
         " passed, " + std::to_string(r.failed) + " failed";
  if (r.errors) out += ", " + std::to_string(r.errors) + " not graded (rb failed)";
  if (r.skipped) out += ", " + std::to_string(r.skipped) + " skipped";
  out += " in " + seconds(r.seconds, "%.2f") + " s\n";
  return out;
}

std::string jsonReport(const ClassResult& r) {
  json doc;
  doc["title"] = r.title;
  doc["timestamp"] = r.timestamp;
  doc["programs"] = json::array();
  for (const ProgramResult& p : r.programs) {
    json j = {{"program", cleanUtf8(p.program, false)}, {"result", p.verdict}, {"reason", cleanUtf8(p.reason, false)},
              {"steps", p.steps},     {"seconds", p.seconds}, {"points", p.points},
              {"max_points", p.maxPoints}, {"checks", checksJson(p.checks)}};
    if (!p.picture.empty()) j["picture"] = p.picture;
    doc["programs"].push_back(std::move(j));
  }
  doc["summary"] = {{"programs", r.programs.size()}, {"passed", r.passed}, {"failed", r.failed},
                    {"errors", r.errors},           {"skipped", r.skipped}, {"seconds", r.seconds}};
  return doc.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

std::string junitReport(const ClassResult& r) {
  char host[256] = "localhost";
  gethostname(host, sizeof host - 1);
  std::string counts = " tests=\"" + std::to_string(r.programs.size()) + "\" failures=\"" + std::to_string(r.failed) +
                       "\" errors=\"" + std::to_string(r.errors) + "\" skipped=\"" + std::to_string(r.skipped) +
                       "\" time=\"" + seconds(r.seconds) + "\"";
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<testsuites name=\"" + xmlEscape(r.title) + "\"" + counts + ">\n";
  out += "  <testsuite name=\"" + xmlEscape(r.title) + "\"" + counts + " timestamp=\"" + r.timestamp +
         "\" hostname=\"" + xmlEscape(host) + "\">\n";
  for (const ProgramResult& p : r.programs) {
    out += "    <testcase name=\"" + xmlEscape(std::filesystem::path(p.program).filename().string()) +
           "\" classname=\"" + xmlEscape(className(p, r)) + "\" file=\"" + xmlEscape(p.program) +
           "\" time=\"" + seconds(p.seconds) + "\"";
    std::string body;
    if (p.verdict == "skip") {
      body += "      <skipped message=\"" + xmlEscape(p.reason) + "\"/>\n";
    } else if (p.verdict == "fail" || p.verdict == "error") {
      const char* tag = p.verdict == "fail" ? "failure" : "error";
      std::string type = "run", text;
      bool first = true;
      for (const CheckResult& c : p.checks) {
        if (c.passed) continue;
        if (first) type = c.name;
        first = false;
        text += c.name + ": " + c.message + "\n";
      }
      if (text.empty()) text = p.reason + "\n";
      body += "      <" + std::string(tag) + " message=\"" + xmlEscape(firstLine(p.reason)) + "\" type=\"" +
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
    for (const CheckResult& c : p.checks) these.push_back(c.name);
    if (!any) names = these;
    else same = same && names == these;
    any = true;
  }
  if (!same) names.clear();
  std::string out = "program,result,points,max_points,checks_passed,checks,steps,seconds,reason";
  for (const std::string& n : names) {
    out += ',';
    out += csvField(n);
  }
  out += '\n';
  for (const ProgramResult& p : r.programs) {
    size_t passed = 0;
    for (const CheckResult& c : p.checks) passed += c.passed;
    out += csvField(p.program) + "," + p.verdict + "," + pointsText(p.points) + "," + pointsText(p.maxPoints) + "," +
           std::to_string(passed) + "," + std::to_string(p.checks.size()) + "," + std::to_string(p.steps) + "," +
           seconds(p.seconds) + "," + csvField(cleanUtf8(p.reason, false));
    for (size_t i = 0; i < names.size(); ++i) {
      out += ',';
      if (i < p.checks.size()) out += pointsText(p.checks[i].passed ? p.checks[i].points : 0);
    }
    out += '\n';
  }
  return out;
}

}  // namespace rb::grade
