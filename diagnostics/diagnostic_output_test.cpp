#include <catch2/catch.hpp>

#include <cstdio>
#include <string>

#include "diagnostic_output.h"

using namespace rb;
using namespace rb::diagnostics;

namespace {
/// What a report writes, through a temporary FILE.
std::string written(DiagOutputOptions opts, const SourceSet& sources, const DiagnosticList& diags) {
  std::FILE* f = std::tmpfile();
  {
    DiagnosticReport r(f, opts);
    r.add(sources, diags);
    r.finish();
  }
  std::rewind(f);
  std::string out;
  char buf[4096];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) out.append(buf, n);
  std::fclose(f);
  return out;
}
}  // namespace

TEST_CASE("the summary line counts errors and warnings", "[diagnostics]") {
  CHECK(countSummary(0, 0).empty());
  CHECK(countSummary(1, 0) == "1 error");
  CHECK(countSummary(2, 1) == "2 errors, 1 warning");
  CHECK(countSummary(0, 3) == "3 warnings");
}

TEST_CASE("json, sarif and github carry the rule, the range, notes and fix-its", "[diagnostics]") {
  SourceSet s;
  s.add("p bas.bas", "goto nowher\nnowhere:\n");
  DiagnosticList diags;
  Diagnostic& d = diags.error({0, 1, 6}, "undefined label 'nowher'; did you mean 'nowhere'?", "rb-undefined-label");
  d.fixits.push_back({{0, 1, 6}, {0, 1, 12}, "nowhere"});
  diags.note({0, 2, 1}, "a label");

  DiagOutputOptions o;
  o.format = DiagFormat::Json;
  nlohmann::json j = nlohmann::json::parse(written(o, s, diags));
  REQUIRE(j.size() == 1);
  CHECK(j[0]["kind"] == "error");
  CHECK(j[0]["option"] == "rb-undefined-label");
  CHECK(j[0]["locations"][0]["caret"]["column"] == 6);
  CHECK(j[0]["locations"][0]["finish"]["column"] == 11);
  CHECK(j[0]["children"][0]["kind"] == "note");
  CHECK(j[0]["fixits"][0]["next"]["column"] == 12);
  CHECK(j[0]["fixits"][0]["string"] == "nowhere");

  o.format = DiagFormat::Sarif;
  nlohmann::json sarif = nlohmann::json::parse(written(o, s, diags));
  CHECK(sarif["version"] == "2.1.0");
  const auto& run = sarif["runs"][0];
  CHECK(run["tool"]["driver"]["name"] == "rb");
  CHECK(run["tool"]["driver"]["rules"][0]["id"] == "rb-undefined-label");
  const auto& res = run["results"][0];
  CHECK(res["ruleId"] == "rb-undefined-label");
  CHECK(res["level"] == "error");
  CHECK(res["locations"][0]["physicalLocation"]["artifactLocation"]["uri"] == "p%20bas.bas");
  CHECK(res["locations"][0]["physicalLocation"]["region"]["endColumn"] == 12);
  CHECK(res["relatedLocations"][0]["message"]["text"] == "a label");

  o.format = DiagFormat::Github;
  CHECK(written(o, s, diags) ==
        "::error file=p bas.bas,line=1,col=6,endColumn=12,title=rb-undefined-label::undefined label "
        "'nowher'; did you mean 'nowhere'?%0Aline 2: a label\n");
}

TEST_CASE("a fix-it that inserts: an empty range in json, an insertion in sarif", "[diagnostics]") {
  SourceSet s;
  s.add("p.bas", "print n \" moves\"\n");
  DiagnosticList diags;
  Diagnostic& d = diags.error({0, 1, 9}, "missing '+' between 'n' and \" moves\"", "rb-missing-operator");
  d.fixits.push_back({{0, 1, 8}, {0, 1, 8}, " +"});

  DiagOutputOptions o;
  o.format = DiagFormat::Json;
  nlohmann::json j = nlohmann::json::parse(written(o, s, diags));
  CHECK(j[0]["fixits"][0]["start"]["column"] == 8);
  CHECK(j[0]["fixits"][0]["next"]["column"] == 8);
  CHECK(j[0]["fixits"][0]["string"] == " +");

  o.format = DiagFormat::Sarif;
  nlohmann::json sarif = nlohmann::json::parse(written(o, s, diags));
  const auto& fix = sarif["runs"][0]["results"][0]["fixes"][0];
  CHECK(fix["description"]["text"] == "insert ' +'");
  const auto& r = fix["artifactChanges"][0]["replacements"][0];
  CHECK(r["deletedRegion"]["startColumn"] == 8);
  CHECK(r["deletedRegion"]["endColumn"] == 8);
  CHECK(r["insertedContent"]["text"] == " +");
}

TEST_CASE("text stops after --max-errors and still counts everything", "[diagnostics]") {
  SourceSet s;
  s.add("p.bas", "a\nb\nc\n");
  DiagnosticList diags;
  for (uint32_t line = 1; line <= 3; ++line) diags.error({0, line, 1}, "bad", "rb-syntax");
  DiagOutputOptions o;
  o.maxErrors = 2;
  std::string out = written(o, s, diags);
  CHECK(out.find("p.bas:2:1") != std::string::npos);
  CHECK(out.find("p.bas:3:1") == std::string::npos);
  CHECK(out.find("stopped after 2 errors") != std::string::npos);
  CHECK(out.substr(out.size() - 9) == "3 errors\n");
}

TEST_CASE("a SARIF artifact uri is percent-encoded as RFC 3986 wants", "[diagnostics]") {
  auto uriOf = [](const std::string& name) {
    SourceSet s;
    s.add(name, "x\n");
    DiagnosticList diags;
    diags.error({0, 1, 1}, "bad", "rb-syntax");
    DiagOutputOptions o;
    o.format = DiagFormat::Sarif;
    nlohmann::json sarif = nlohmann::json::parse(written(o, s, diags));
    return sarif["runs"][0]["results"][0]["locations"][0]["physicalLocation"]["artifactLocation"]["uri"].get<std::string>();
  };
  CHECK(uriOf("class/odd name #1 %?\xC3\xA9:[x].bas") == "class/odd%20name%20%231%20%25%3F%C3%A9%3A%5Bx%5D.bas");
  CHECK(uriOf("a-b_c.d~e/f.bas") == "a-b_c.d~e/f.bas");
  CHECK(uriOf("/home/ann/my square.bas") == "file:///home/ann/my%20square.bas");
}
