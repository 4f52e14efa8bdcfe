#include "report.h"
#include "text.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "pictures.h"

using namespace rb::grade;
using rb::record::csvField;

namespace {

CheckResult result(const std::string& name, bool passed, const std::string& message, double points) {
  CheckResult c;
  c.name = name;
  c.passed = passed;
  c.message = message;
  c.points = points;
  c.earned = passed ? points : 0;
  return c;
}

ClassResult sample() {
  ClassResult r;
  r.title = "square";
  r.timestamp = "2026-11-21T10:00:00";
  r.seconds = 1.5;
  ProgramResult pass;
  pass.program = "class/a.bas";
  pass.verdict = "pass";
  pass.checks = {result("trail", true, "ok", 2)};
  pass.points = pass.maxPoints = 2;
  pass.output = "perimeter 480\n";
  ProgramResult fail;
  fail.program = "class/b, \"quoted\".bas";
  fail.verdict = "fail";
  fail.reason = "trail is 60 px from the solution's at its worst, tolerance 3 <&>";
  fail.checks = {result("trail", false, fail.reason, 2)};
  fail.maxPoints = 2;
  fail.output = std::string("caf\xE9 \x01 bell\n");  // Latin-1 and a control character
  ProgramResult skip;
  skip.program = "lib.bas";
  skip.verdict = "skip";
  skip.reason = "not a test";
  r.programs = {pass, fail, skip};
  r.passed = 1;
  r.failed = 1;
  r.skipped = 1;
  return r;
}

}  // namespace

TEST_CASE("the text report: a table, the failed checks, a total", "[grade][report]") {
  std::string text = textReport(sample(), true);
  CHECK(text.find("class/a.bas") != std::string::npos);
  CHECK(text.find("FAIL") != std::string::npos);
  CHECK(text.find("    trail: trail is 60 px") != std::string::npos);
  CHECK(text.find("error output") == std::string::npos);
  CHECK(text.find("3 programs: 1 passed, 1 failed, 1 skipped in 1.50 s\n") != std::string::npos);
  CHECK(textReport(sample(), false).find("    trail:") == std::string::npos);
}

TEST_CASE("the JUnit report escapes and counts", "[grade][report]") {
  std::string xml = junitReport(sample());
  CHECK(xml.find("<testsuite name=\"square\" tests=\"3\" failures=\"1\" errors=\"0\" skipped=\"1\"") != std::string::npos);
  CHECK(xml.find("tolerance 3 &lt;&amp;&gt;") != std::string::npos);
  CHECK(xml.find("name=\"b, &quot;quoted&quot;.bas\"") != std::string::npos);
  CHECK(xml.find("<failure message=\"trail is 60 px") != std::string::npos);
  CHECK(xml.find("type=\"trail\"") != std::string::npos);
  CHECK(xml.find("<skipped message=\"not a test\"/>") != std::string::npos);
  CHECK(xml.find("caf\xC3\xA9 ^A bell") != std::string::npos);  // é from Latin-1, ^A shown
}

TEST_CASE("XML escaping keeps text valid", "[grade][report]") {
  CHECK(xmlEscape("a<b>&\"'") == "a&lt;b&gt;&amp;&quot;&apos;");
  CHECK(xmlEscape("tab\tnew\nline") == "tab\tnew\nline");
  CHECK(xmlEscape("\x1b[31m") == "^[[31m");
  CHECK(xmlEscape("\xE2\x82\xAC") == "\xE2\x82\xAC");  // UTF-8 stays
  CHECK(xmlEscape("\xE2\x82") == "\xC3\xA2\\x82");  // a cut sequence is read as Latin-1, C1 shown
}

TEST_CASE("the JSON and CSV reports", "[grade][report]") {
  nlohmann::json doc = nlohmann::json::parse(jsonReport(sample()));
  CHECK(doc["programs"].size() == 3);
  CHECK(doc["programs"][1]["result"] == "fail");
  CHECK(doc["programs"][1]["checks"][0]["passed"] == false);
  CHECK(doc["summary"]["skipped"] == 1);
  std::string csv = csvReport(sample());
  // Every graded program has the same checks: one column each, with the points it earned.
  CHECK(csv.rfind("program,result,points,max_points,checks_passed,checks,steps,seconds,reason,trail\n", 0) == 0);
  CHECK(csv.find("class/a.bas,pass,2,2,1,1,0,0.000,,2\n") != std::string::npos);
  CHECK(csv.find("\"class/b, \"\"quoted\"\".bas\",fail,0,2,0,1,") != std::string::npos);
  CHECK(csvField("plain") == "plain");
  CHECK(csvField("a\nb") == "\"a\nb\"");
}

TEST_CASE("the feedback picture draws the student's trail over the solution's", "[grade][report]") {
  PictureInput in;
  in.reference = {{{100, 100}, {200, 100}}};
  in.student = {{{100, 110}, {200, 110}}};
  rb::render::RgbImage img = feedbackPicture(in);
  CHECK(img.width == 800);
  CHECK(img.height == kPictureHeight);
  CHECK(img.pixel(150, 100) == kReferenceColour);
  CHECK(img.pixel(150, 110) == kStudentColour);
  CHECK(img.pixel(150, 300) == 0xFFFFFF);
}

TEST_CASE("reports for students hide the hidden checks' details", "[grade][report]") {
  ClassResult r = sample();
  r.assignment = true;
  ProgramResult& p = r.programs[1];
  CheckResult secret = result("secret corner", false, "misses point 3 (500, 200) by 9 px", 1);
  secret.hidden = true;
  secret.hint = "look at the third turn";
  p.checks.insert(p.checks.begin(), secret);
  p.reason = secret.message;
  std::string teacher = textReport(r, true);
  CHECK(teacher.find("secret corner: misses point 3") != std::string::npos);
  CHECK(teacher.find("hint: look at the third turn") != std::string::npos);
  r.studentView = true;
  for (const std::string& report : {textReport(r, true), jsonReport(r), junitReport(r), csvReport(r),
                                    studentFeedback(p, r)}) {
    CHECK(report.find("secret") == std::string::npos);
    CHECK(report.find("500, 200") == std::string::npos);
    CHECK(report.find("third turn") == std::string::npos);
    CHECK(report.find("a hidden check failed") != std::string::npos);
  }
}

TEST_CASE("a failed output check shows the transcript with input marked", "[grade][report]") {
  ClassResult r = sample();
  ProgramResult& p = r.programs[1];
  p.checks = {result("solution-output", false, "output differs at line 1", 1)};
  p.output = "How many sides? 6\nsides: 6\n";
  p.inputs = {{0, 16, 18}};
  p.errors = "rb run: something\n";
  std::string text = textReport(r, true);
  CHECK(text.find("      > How many sides? [6]\n        sides: 6\n") != std::string::npos);
  CHECK(text.find("    error output:\n      rb run: something\n") != std::string::npos);
  size_t first = text.find("rb run: something");
  CHECK(text.find("rb run: something", first + 1) == std::string::npos);  // once
  nlohmann::json doc = nlohmann::json::parse(jsonReport(r));
  CHECK(doc["programs"][1]["inputs"][0]["prompt_end"] == 16);
}

TEST_CASE("points, notes and missing students in the reports", "[grade][report]") {
  ClassResult r = sample();
  r.assignment = true;
  ProgramResult& p = r.programs[1];
  CheckResult ran = result("no-error", true, "finishes", 1);
  ran.earned = 0;
  ran.note = "not counted: the required check 'corners' did not pass";
  p.checks.push_back(ran);
  p.maxPoints = 3;
  ProgramResult missing;
  missing.program = "bob.bas";
  missing.student = "Bob";
  missing.verdict = "missing";
  missing.reason = "no submission";
  missing.maxPoints = 3;
  r.programs.push_back(missing);
  r.missing = 1;
  std::string text = textReport(r, true);
  CHECK(text.find("0/3") != std::string::npos);
  CHECK(text.find("    passed, not counted: the required check 'corners' did not pass: no-error\n") != std::string::npos);
  CHECK(text.find("MISS") != std::string::npos);
  CHECK(text.find("1 student with no submission") != std::string::npos);
  std::string csv = csvReport(r);
  CHECK(csv.rfind("student,program,", 0) == 0);
  CHECK(csv.find("Bob,bob.bas,missing,0,3,") != std::string::npos);
  std::string xml = junitReport(r);
  CHECK(xml.find("name=\"bob.bas (Bob)\"") != std::string::npos);
  CHECK(xml.find("failures=\"2\"") != std::string::npos);
}

namespace {

/// A class with one program whose every text is hostile: a file name with a line feed and a
/// workflow command, a spreadsheet formula for a student's name, output that clears the
/// terminal, moves its cursor to print a "pass" row and sets its clipboard (OSC 52), C1 CSI.
ClassResult hostileClass() {
  ClassResult r = sample();
  r.assignment = true;
  ProgramResult& p = r.programs[1];
  p.program = "class/x\n::error::forged\r##[error]old.bas";
  p.student = "@SUM(1)";
  p.reason = "=HYPERLINK(\"http://x\",\"y\")";
  p.checks = {result("solution-output", false, "output differs: got \x1b[2J", 1)};
  p.checks[0].note = "note\x07";
  p.checks[0].hint = "hint\x1b]52;c;aGk=\x07";
  p.notes = {"ignored // args: \x1b[31m"};
  p.output = std::string("\x1b[2J\x1b[1;1Hclass/b.bas  pass  2/2\n::error file=a.bas::forged\n\xC2\x9B" "2J\x9b" "2J\n") +
             std::string("a\0b\x7f\n", 5) + "  ##[warning]x\n";
  p.errors = "\x1b]52;c;ZXZpbA==\x07\n    ::add-mask::secret\n";
  return r;
}

/// What a report must never carry from a student: a control character but LF (and tab), a C1
/// control, a line a GitHub runner would take as a workflow command.
void checkInert(const std::string& report) {
  INFO(report);
  for (size_t i = 0; i < report.size(); ++i) {
    unsigned char c = static_cast<unsigned char>(report[i]);
    CHECK((c >= 0x20 || c == '\n' || c == '\t'));
    CHECK(c != 0x7F);
    if (c == 0xC2 && i + 1 < report.size()) CHECK(!(static_cast<unsigned char>(report[i + 1]) >= 0x80 &&
                                                    static_cast<unsigned char>(report[i + 1]) <= 0x9F));
  }
  CHECK(report.find("##[") == std::string::npos);
  size_t start = 0;
  while (start <= report.size()) {
    size_t end = report.find('\n', start);
    if (end == std::string::npos) end = report.size();
    std::string lineText = report.substr(start, end - start);
    size_t first = lineText.find_first_not_of(" \t");
    CHECK((first == std::string::npos || lineText.compare(first, 2, "::") != 0));
    start = end + 1;
  }
}

}  // namespace

TEST_CASE("no report carries a student's control characters or workflow commands", "[grade][report]") {
  ClassResult r = hostileClass();
  const ProgramResult& p = r.programs[1];
  std::string text = textReport(r, true);
  for (const std::string& report : {text, studentFeedback(p, r), jsonReport(r), junitReport(r), csvReport(r)})
    checkInert(report);
  // Shown, not dropped: the escapes say what was there.
  CHECK(text.find("class/x\\n::error::forged\\r\\x23#[error]old.bas") != std::string::npos);
  CHECK(text.find("output differs: got ^[[2J") != std::string::npos);
  CHECK(text.find("  ^[[2J^[[1;1Hclass/b.bas  pass  2/2\n") != std::string::npos);
  CHECK(text.find("\\x3a:error file=a.bas::forged") != std::string::npos);
  CHECK(text.find("\\x9b2J\\x9b2J") != std::string::npos);
  CHECK(text.find("a^@b^?") != std::string::npos);
  CHECK(text.find("^[]52;c;ZXZpbA==^G") != std::string::npos);
  CHECK(text.find("hint: hint^[]52;c;aGk=^G") != std::string::npos);
  // The JSON text reads back to the same shown text, output on lines.
  nlohmann::json doc = nlohmann::json::parse(jsonReport(r));
  CHECK(doc["programs"][1]["output"].get<std::string>().find("\n\\x3a:error file=a.bas::forged\n") != std::string::npos);
  CHECK(doc["programs"][1]["student"] == "@SUM(1)");
}

TEST_CASE("the CSV grade book starts no formula", "[grade][report]") {
  ClassResult r = hostileClass();
  std::string csv = csvReport(r);
  CHECK(csv.find("\n'@SUM(1),") != std::string::npos);
  CHECK(csv.find(",\"'=HYPERLINK(\"\"http://x\"\",\"\"y\"\")\"") != std::string::npos);
  CHECK(csv.find(",=") == std::string::npos);
  CHECK(csv.find("\n@") == std::string::npos);
}

TEST_CASE("the JSON report's input marks point into the output shown", "[grade][report]") {
  ClassResult r = sample();
  ProgramResult& p = r.programs[1];
  p.checks = {result("solution-output", false, "output differs at line 1", 1)};
  p.output = "\x1b[1mHow many?\x1b[0m 6\nsides: 6\n";  // bold prompt: each ESC is shown as two characters
  p.inputs = {{0, 18, 20}};
  nlohmann::json doc = nlohmann::json::parse(jsonReport(r));
  std::string output = doc["programs"][1]["output"];
  const nlohmann::json& mark = doc["programs"][1]["inputs"][0];
  CHECK(mark["start"] == 0);
  CHECK(mark["prompt_end"] == 20);
  CHECK(mark["end"] == 22);
  CHECK(output.substr(0, 20) == "^[[1mHow many?^[[0m ");
  CHECK(output.substr(20, 2) == "6\n");
}

TEST_CASE("the JSON report keeps a picture's path whole but writes no workflow command", "[grade][report]") {
  ClassResult r = sample();
  r.programs[0].picture = "pictures/##[error]x.png";
  std::string json = jsonReport(r);
  CHECK(json.find("##[") == std::string::npos);
  CHECK(nlohmann::json::parse(json)["programs"][0]["picture"] == "pictures/##[error]x.png");
}
