#include "merge.h"

#include <catch2/catch.hpp>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

#include "html_report.h"
#include "report.h"

using namespace rb::grade;
namespace fs = std::filesystem;

namespace {

CheckResult check(const std::string& name, bool passed, const std::string& message, double points) {
  CheckResult c;
  c.name = name;
  c.passed = passed;
  c.message = message;
  c.points = points;
  c.earned = passed ? points : 0;
  return c;
}

/// A class with a bit of everything a report shows: an assignment's checks (hints, feedback, a
/// hidden one, a required one, one not checked, a note), a gate, notes, output with input marks,
/// Latin-1, a control character and a CR, error output, a source with CRLF and a byte that is not
/// UTF-8, marked lines, pictures, a file that is not a program, a missing student, warnings.
ClassResult sample() {
  ClassResult r;
  r.title = "square";
  r.timestamp = "2026-11-21T10:00:00";
  r.seconds = 1.5;
  r.assignment = true;
  r.maxPoints = 5;
  r.warnings = {"the solution fails its own check 'corners': it misses point 2"};
  r.confinement = "no Landlock: the kernel does not confine file access";
  r.origin.paths = {"class"};
  r.origin.assignmentFile = "square.toml";
  r.origin.assignmentDigest = contentDigest("title = \"square\"\n");
  r.origin.rbVersion = "0.1.0";

  ProgramResult a;
  a.program = "class/ana.bas";
  a.name = "ana.bas";
  a.student = "Ana";
  a.verdict = "pass";
  a.checks = {check("output", true, "ok", 2), check("corners", true, "ok", 3)};
  a.checks[1].feedback = {"well done\nreally"};
  a.points = a.maxPoints = 5;
  a.steps = 42;
  a.seconds = 0.125;
  a.output = "how many? 4\nperimeter 480\n";
  a.inputs = {{0, 10, 12}};
  a.source = "input \"how many? \", n\r\nprint \"perimeter \" + 4 * 120\r\n";
  a.sourceRead = true;
  a.picture = "pics/ana.png";
  a.screen = "pics/ana.screen.png";
  a.replay = "pics/ana.html";

  ProgramResult b;
  b.program = "class/b\x01n.bas";
  b.name = "b_n.bas";
  b.student = "Ben";
  b.verdict = "fail";
  b.reason = "output differs at line 1: expected \"perimeter 480\", got \"caf\xE9\"";
  b.checks = {check("output", false, b.reason, 2), check("corners", false, "misses point 2 by 9 px", 2),
              check("home", false, "a hidden check's message", 1)};
  b.checks[0].hint = "print the perimeter:\n4 * 120";
  b.checks[1].required = true;
  b.checks[1].checked = false;
  b.checks[2].hidden = true;
  b.checks[2].hint = "the secret";
  b.maxPoints = 5;
  b.steps = 7;
  b.seconds = 0.5;
  b.output = "caf\xE9 \x1b[2J\rback\n::error::x\n";
  b.errors = "b.bas:3:1: runtime error: boom\n";
  b.notes = {"ignored // args: --allow-spawn"};
  b.source = "print \"caf\xE9\"\n\tboom\n";
  b.sourceRead = true;
  b.marks = {{3, "runtime error: boom"}};

  ProgramResult c;
  c.program = "class/empty.bas";
  c.name = "empty.bas";
  c.verdict = "fail";
  c.gate = "the program is empty: it has no statement";
  c.reason = c.gate;
  c.checks = {check("output", true, "ok", 2)};
  c.checks[0].earned = 0;
  c.checks[0].note = "not counted: the program is empty";
  c.maxPoints = 5;
  c.source = "";
  c.sourceRead = true;

  ProgramResult t;
  t.program = "class/square.bas.txt";
  t.name = "square.bas.txt";
  t.student = "Lena";
  t.verdict = "fail";
  t.reason = "not graded: not a .bas file (saved as .bas.txt?)";
  t.isProgram = false;
  t.maxPoints = 5;
  t.source = "rForward 120\n";
  t.sourceRead = true;

  ProgramResult m;
  m.program = "class/mo.bas";
  m.name = "mo.bas";
  m.student = "Mo";
  m.verdict = "missing";
  m.reason = "no submission: class/mo.bas is not in the class folder (roster.csv line 5)";
  m.maxPoints = 5;

  r.programs = {a, b, c, t, m};
  r.passed = 1;
  r.failed = 3;
  r.missing = 1;
  return r;
}

/// Every report rb test writes of `r`, as one text: a merge or a read-back must give them all alike.
std::string everyReport(const ClassResult& r) {
  std::string out = textReport(r, true) + "\n---\n" + textReport(r, false) + "\n---\n" + jsonReport(r) + "\n---\n" +
                    junitReport(r) + "\n---\n" + csvReport(r) + "\n---\n";
  std::vector<std::string> pages;
  for (size_t i = 0; i < r.programs.size(); ++i) {
    const ProgramResult& p = r.programs[i];
    out += studentFeedback(p, r) + "\n---\n";
    out += programPage(r, i, p.sourceRead ? &p.source : nullptr, "report", "n0nce") + "\n---\n";
    pages.push_back("programs/" + std::to_string(i) + ".html");
  }
  return out + classPage(r, pages, "report", "n0nce");
}

ClassResult readBack(const ClassResult& r) {
  std::string error;
  std::optional<ClassResult> back = readJsonReport(jsonReport(r), error);
  INFO(error);
  REQUIRE(back);
  return *back;
}

/// Shard K of N of `whole` as rb test --shard K/N grades it: every N-th file, the missing
/// students in shard 1 only, counted again.
ClassResult shardOfClass(const ClassResult& whole, int k, int n, const std::string& timestamp, double seconds) {
  ClassResult s = whole;
  s.programs.clear();
  s.passed = s.failed = s.errors = s.skipped = s.missing = 0;
  size_t i = 0;
  for (const ProgramResult& p : whole.programs) {
    bool mine = p.verdict == "missing" ? k == 1 : static_cast<int>(i++ % static_cast<size_t>(n)) == k - 1;
    if (!mine) continue;
    s.programs.push_back(p);
    if (p.verdict == "pass") ++s.passed;
    else if (p.verdict == "missing") ++s.missing;
    else ++s.failed;
  }
  s.origin.shard = k;
  s.origin.shards = n;
  s.timestamp = timestamp;
  s.seconds = seconds;
  return s;
}

ShardReport shardReport(const ClassResult& r, const std::string& file) {
  ShardReport s;
  s.file = file;
  std::string error;
  std::optional<ClassResult> back = readJsonReport(jsonReport(r), error, &s.similarity);
  INFO(error);
  REQUIRE(back);
  s.result = *back;
  return s;
}

std::string refusal(const std::string& text) {
  std::string error;
  CHECK_FALSE(readJsonReport(text, error));
  return error;
}

void writeFile(const fs::path& p, const std::string& bytes) {
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << bytes;
}

}  // namespace

TEST_CASE("base64 round-trips every byte and refuses what is not base64", "[grade][merge]") {
  // RFC 4648's test vectors.
  CHECK(base64Encode("") == "");
  CHECK(base64Encode("f") == "Zg==");
  CHECK(base64Encode("fo") == "Zm8=");
  CHECK(base64Encode("foo") == "Zm9v");
  CHECK(base64Encode("foobar") == "Zm9vYmFy");
  std::string all;
  for (int c = 0; c < 256; ++c) all += static_cast<char>(c);
  for (size_t n = 0; n < 7; ++n) CHECK(base64Decode(base64Encode(all.substr(250 - n))) == all.substr(250 - n));
  CHECK(base64Decode(base64Encode(all)) == all);
  for (const char* bad : {"Zg=", "Z===", "Zg=a", "Zm9v!A==", "=Zg=", "Zg==Zg=="}) CHECK_FALSE(base64Decode(bad));
}

TEST_CASE("a JSON report reads back into the result every report was written from", "[grade][merge]") {
  ClassResult r = sample();
  ClassResult back = readBack(r);
  CHECK(everyReport(back) == everyReport(r));
  // What no report shows as it is, kept as it was.
  CHECK(back.programs[0].source == r.programs[0].source);
  CHECK(back.programs[1].source == r.programs[1].source);
  CHECK(back.programs[0].inputs.size() == 1);
  CHECK(back.programs[1].marks.size() == 1);
  CHECK(back.programs[0].picture == "pics/ana.png");
  CHECK(back.programs[0].screen == "pics/ana.screen.png");
  CHECK_FALSE(back.programs[3].isProgram);
  CHECK_FALSE(back.programs[4].sourceRead);
  CHECK(back.origin.assignmentDigest == r.origin.assignmentDigest);
  CHECK(back.origin.paths == r.origin.paths);
  CHECK(back.warnings == r.warnings);
  CHECK(back.maxPoints == 5);
  CHECK(back.seconds == 1.5);

  SECTION("a report for students reads back as one") {
    r.studentView = true;
    ClassResult student = readBack(r);
    CHECK(student.studentView);
    CHECK(everyReport(student) == everyReport(r));
    CHECK(jsonReport(student).find("the secret") == std::string::npos);
  }
  SECTION("graded against the programs' comments") {
    r.assignment = false;
    r.maxPoints = 0;
    ClassResult comments = readBack(r);
    CHECK_FALSE(comments.assignment);
    CHECK(everyReport(comments) == everyReport(r));
  }
}

TEST_CASE("the JSON report keeps what it had, and adds what merging needs", "[grade][merge]") {
  nlohmann::json doc = nlohmann::json::parse(jsonReport(sample()));
  // What readers of the earlier report read is where it was.
  for (const char* key : {"title", "timestamp", "programs", "summary", "confinement"}) CHECK(doc.contains(key));
  CHECK(doc["programs"][1]["reason"].get<std::string>().find("caf\xC3\xA9") != std::string::npos);
  CHECK(doc["summary"]["programs"] == 4);
  // What it adds.
  CHECK(doc["report_version"] == kJsonReportVersion);
  CHECK(doc["shard"] == nlohmann::json({{"index", 1}, {"of", 1}}));
  CHECK(doc["assignment"]["file"] == "square.toml");
  CHECK(doc["programs"][0]["name"] == "ana.bas");
  CHECK(doc["programs"][0]["source_base64"] == base64Encode(sample().programs[0].source));
  CHECK(doc["programs"][3]["not_a_program"] == true);
  CHECK_FALSE(doc["programs"][4].contains("source_base64"));
}

TEST_CASE("readJsonReport refuses what is not a report it can read", "[grade][merge]") {
  nlohmann::json good = nlohmann::json::parse(jsonReport(sample()));
  CHECK(refusal("{").find("not JSON") == 0);
  CHECK(refusal("[]").find("not a report of rb test") == 0);
  nlohmann::json old = good;
  old.erase("report_version");
  CHECK(refusal(old.dump()).find("older rb test") != std::string::npos);
  nlohmann::json newer = good;
  newer["report_version"] = kJsonReportVersion + 1;
  CHECK(refusal(newer.dump()).find("report_version 3") == 0);
  nlohmann::json verdict = good;
  verdict["programs"][0]["result"] = "great";
  CHECK(refusal(verdict.dump()).find("'great' is none of rb's") != std::string::npos);
  nlohmann::json counts = good;
  counts["summary"]["passed"] = 4;
  CHECK(refusal(counts.dump()).find("its summary does not count its programs") == 0);
  nlohmann::json source = good;
  source["programs"][0]["source_base64"] = "not base64!";
  CHECK(refusal(source.dump()).find("not base64") != std::string::npos);
  nlohmann::json marks = good;
  marks["programs"][0]["inputs"][0]["end"] = 1000;
  CHECK(refusal(marks.dump()).find("input mark") != std::string::npos);
  nlohmann::json shard = good;
  shard["shard"]["index"] = 3;
  CHECK(refusal(shard.dump()).find("shard 3 of 1") != std::string::npos);
  nlohmann::json type = good;
  type["programs"][0]["steps"] = "many";
  CHECK(refusal(type.dump()).find("not a report rb test wrote") == 0);
}

TEST_CASE("shards merge into the class as one run grades it", "[grade][merge]") {
  ClassResult whole = sample();
  // Three shards, started a second apart, the last to end 4.5 s after the first started.
  std::vector<ShardReport> shards = {
      shardReport(shardOfClass(whole, 3, 3, "2026-11-21T10:00:01", 3.5), "r3.json"),
      shardReport(shardOfClass(whole, 1, 3, "2026-11-21T10:00:00", 1.25), "r1.json"),
      shardReport(shardOfClass(whole, 2, 3, "2026-11-21T10:00:02", 1.0), "r2.json"),
  };
  CHECK(shards[1].result.missing == 1);
  CHECK(shards[0].result.missing == 0);
  MergeOutcome m = mergeShards(shards);
  INFO(m.error);
  REQUIRE(m.code == 0);
  CHECK(m.result.timestamp == "2026-11-21T10:00:00");
  CHECK(m.result.seconds == 4.5);
  CHECK(m.result.warnings == whole.warnings);  // each shard said it: once
  CHECK(m.result.confinement == whole.confinement);
  CHECK(m.result.origin.shard == 1);
  CHECK(m.result.origin.shards == 1);
  whole.seconds = 4.5;
  CHECK(everyReport(m.result) == everyReport(whole));

  SECTION("the shards' confinement notes, each once") {
    shards[2].result.confinement = "no seccomp";
    MergeOutcome two = mergeShards(shards);
    CHECK(two.result.confinement == whole.confinement + "; no seccomp");
  }
  SECTION("a class graded whole merges to itself") {
    MergeOutcome one = mergeShards({shardReport(whole, "whole.json")});
    REQUIRE(one.code == 0);
    CHECK(everyReport(one.result) == everyReport(whole));
  }
}

TEST_CASE("mergeShards refuses reports that are not one class's shards", "[grade][merge]") {
  ClassResult whole = sample();
  auto shard = [&](int k, int n) { return shardReport(shardOfClass(whole, k, n, whole.timestamp, 1), "r" + std::to_string(k) + ".json"); };
  auto refused = [](std::vector<ShardReport> shards, int code) {
    MergeOutcome m = mergeShards(std::move(shards));
    CHECK(m.code == code);
    return m.error;
  };
  CHECK(refused({}, 64) == "no reports to merge");
  CHECK(refused({shard(1, 3), shard(3, 3)}, 66) == "shard 2 of 3 is missing: merge the reports of every shard");
  CHECK(refused({shard(2, 4), shard(3, 4)}, 66) == "shards 1 and 4 of 4 are missing: merge the reports of every shard");
  ShardReport again = shard(1, 2);
  again.file = "copy.json";
  CHECK(refused({shard(1, 2), again, shard(2, 2)}, 64) == "r1.json and copy.json are both shard 1 of 2");
  CHECK(refused({shard(1, 2), shard(2, 3)}, 64).find("split the class differently") != std::string::npos);

  ShardReport other = shard(2, 2);
  other.result.title = "yard";
  CHECK(refused({shard(1, 2), other}, 64).find("is of 'square', r2.json (shard 2 of 2) of 'yard'") != std::string::npos);
  other = shard(2, 2);
  other.result.origin.assignmentDigest = contentDigest("title = \"square\"\n# changed\n");
  CHECK(refused({shard(1, 2), other}, 64).find("graded against one assignment") != std::string::npos);
  other = shard(2, 2);
  other.result.origin.paths = {"other"};
  CHECK(refused({shard(1, 2), other}, 64).find("grade the same files and folders") != std::string::npos);
  other = shard(2, 2);
  other.result.studentView = true;
  CHECK(refused({shard(1, 2), other}, 64).find("is a report for students") != std::string::npos);
  other = shard(2, 2);
  other.result.origin.rbVersion = "0.2.0";
  CHECK(refused({shard(1, 2), other}, 64).find("by rb 0.2.0") != std::string::npos);
  other = shard(2, 2);
  other.result.programs.push_back(shard(1, 2).result.programs.front());
  CHECK(refused({shard(1, 2), other}, 64).find("class/ana.bas is in both r1.json (shard 1 of 2) and r2.json") == 0);
}

TEST_CASE("a shard's pictures are found where the report says or beside it, and copied", "[grade][merge]") {
  fs::path dir = fs::temp_directory_path() / ("rb-merge-test-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  // An artifact downloaded into dir/report-1: the report and the pictures folder beside it.
  writeFile(dir / "report-1" / "rb-test.json", "{}");
  writeFile(dir / "report-1" / "pictures" / "ana.png", "PNG of ana");
  writeFile(dir / "report-1" / "pictures" / "ana.screen.png", "screen of ana");
  writeFile(dir / "elsewhere" / "ana.html", "replay of ana");
  ShardReport s;
  s.file = (dir / "report-1" / "rb-test.json").string();
  s.result = sample();
  s.result.programs[0].picture = "rb-report/pictures/ana.png";   // as the shard's job wrote it
  s.result.programs[0].screen = "/runner/work/pictures/ana.screen.png";
  s.result.programs[0].replay = (dir / "elsewhere" / "ana.html").string();  // still there
  s.result.programs[1].picture = "rb-report/pictures/gone.png";
  std::vector<MissingPicture> missing;
  findShardPictures(s, "", missing);
  CHECK(s.result.programs[0].picture == (dir / "report-1" / "pictures" / "ana.png").string());
  CHECK(s.result.programs[0].screen == (dir / "report-1" / "pictures" / "ana.screen.png").string());
  CHECK(s.result.programs[0].replay == (dir / "elsewhere" / "ana.html").string());
  REQUIRE(missing.size() == 1);
  CHECK(missing[0].recorded == "rb-report/pictures/gone.png");
  CHECK(missing[0].report == s.file);
  CHECK(s.result.programs[1].picture.empty());

  SECTION("--merge-pictures: only there") {
    ShardReport t;
    t.file = s.file;
    t.result = sample();
    t.result.programs[0].replay = "x/ana.html";
    missing.clear();
    findShardPictures(t, (dir / "elsewhere").string(), missing);
    CHECK(t.result.programs[0].replay == (dir / "elsewhere" / "ana.html").string());
    CHECK(missing.size() == 2);  // ana.png and ana.screen.png are not in elsewhere/
  }
  SECTION("copied into the merged report's pictures folder") {
    fs::create_directories(dir / "merged");
    std::vector<std::string> errors;
    copyPictures(s.result, (dir / "merged").string(), errors);
    CHECK(errors.empty());
    CHECK(s.result.programs[0].picture == (dir / "merged" / "ana.png").string());
    CHECK(s.result.programs[0].replay == (dir / "merged" / "ana.html").string());
    std::ifstream in(dir / "merged" / "ana.screen.png", std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    CHECK(bytes == "screen of ana");
    s.result.programs[2].picture = (dir / "nowhere.png").string();
    copyPictures(s.result, (dir / "merged").string(), errors);
    REQUIRE(errors.size() == 1);
    CHECK(errors[0].find("nowhere.png") != std::string::npos);
  }
  fs::remove_all(dir);
}

TEST_CASE("similarity over a merged class compares its programs, as graded", "[grade][merge]") {
  ClassResult r;
  std::string body = "for i = 1 to 4\n  rForward 120\n  rTurn 90\nnext\nprint \"perimeter \" + 4 * 120\n";
  body += body;
  for (const char* name : {"class/a.bas", "class/b.bas", "class/c.bas.txt"}) {
    ProgramResult p;
    p.program = name;
    p.verdict = "pass";
    p.source = "rLocate 400, 300\n" + body;
    p.sourceRead = true;
    r.programs.push_back(p);
  }
  r.programs[2].isProgram = false;  // not a program: never compared
  ProgramResult m;
  m.program = "class/d.bas";
  m.verdict = "missing";
  r.programs.push_back(m);
  SimilarityReport s = classSimilarity(r, {});
  CHECK(s.programs == 2);
  REQUIRE(s.pairs.size() == 1);
  CHECK(s.pairs[0].a == "class/a.bas");
  CHECK(s.pairs[0].b == "class/b.bas");
}
