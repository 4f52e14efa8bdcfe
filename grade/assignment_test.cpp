#include "assignment.h"

#include <re2/re2.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace rb::grade;
using rb::record::Region;
namespace fs = std::filesystem;

namespace {

/// Writes `text` as an assignment file in a fresh folder (with a solution.bas beside it) and
/// loads it.
std::optional<Assignment> load(const std::string& text, std::string& error) {
  static int count = 0;
  fs::path dir = fs::temp_directory_path() /
                 ("rb_assignment_test_" + std::to_string(getpid()) + "_" + std::to_string(++count));
  fs::create_directories(dir);
  std::ofstream(dir / "solution.bas") << "print 1\n";
  std::ofstream(dir / "a.toml") << text;
  return loadAssignment((dir / "a.toml").string(), error);
}

std::string errorOf(const std::string& text) {
  std::string error;
  std::optional<Assignment> a = load(text, error);
  CHECK_FALSE(a);
  return error.substr(error.find("a.toml:") + 7);  // "LINE:COL: message"
}

}  // namespace

TEST_CASE("an assignment file with every kind of check", "[grade][assignment]") {
  std::string error;
  std::optional<Assignment> a = load(R"(
title = "Square"
solution = "solution.bas"
[run]
seeds = [1, 2]
max-steps = 5000
timeout = 3
memory = 256
keys = "wasd"
stdin = ["3", "4"]
[[check]]
kind = "output"
text = "12\n"
[[check]]
kind = "output"
regex = ["^Area: \\d+$"]
name = "area"
points = 2.5
[[check]]
kind = "no-error"
[[check]]
kind = "no-crash"
[[check]]
kind = "check"
warnings = true
target = "rb9"
[[check]]
kind = "ends-in"
rect = [420, 320, 380, 280]
[[check]]
kind = "ends-in"
circle = [400, 300, 5]
[[check]]
kind = "visits"
waypoints = [[400, 300], [400, 180]]
in-order = false
[[check]]
kind = "trail"
paths = [[[0, 0], [10, 0]], [[5, 5]]]
tolerance = 2
[[check]]
kind = "solution-output"
[[check]]
kind = "solution-trail"
[[check]]
kind = "solution-screen"
tolerance = 0.02
)", error);
  REQUIRE(a);
  CHECK(error.empty());
  CHECK(a->title == "Square");
  REQUIRE(a->solution);
  CHECK(fs::path(*a->solution).filename() == "solution.bas");
  CHECK(fs::path(*a->solution).is_absolute());
  CHECK(a->seeds == std::vector<uint64_t>{1, 2});
  CHECK(a->maxSteps == 5000);
  CHECK(a->timeout == 3);
  CHECK(a->memoryMb == 256);
  CHECK(a->keys == "wasd");
  CHECK(a->stdinLines == std::vector<std::string>{"3", "4"});
  REQUIRE(a->checks.size() == 12);
  CHECK(a->checks[0].text == "12\n");
  CHECK(a->checks[1].name == "area");
  CHECK(a->checks[1].points == 2.5);
  CHECK(RE2::FullMatch("Area: 42", *a->checks[1].regexes[0]));
  CHECK_FALSE(RE2::FullMatch("Area: 42!", *a->checks[1].regexes[0]));
  CHECK(a->checks[4].allowWarnings);
  CHECK(a->checks[4].target == "rb9");
  CHECK(a->checks[5].regions[0].x1 == 380);  // corners in any order
  CHECK(a->checks[5].regions[0].y2 == 320);
  CHECK(a->checks[6].regions[0].kind == Region::Circle);
  CHECK_FALSE(a->checks[7].inOrder);
  CHECK(a->checks[8].reference.size() == 2);
  CHECK(a->checks[8].tolerance == 2);
  CHECK(a->checks[10].tolerance == 5);     // the default for trails
  CHECK(a->checks[11].tolerance == 0.02);
  CHECK(a->needsSolution());
  CHECK(a->needsScreen());
  CHECK(a->maxPoints() == Approx(13.5));
}

TEST_CASE("an assignment without checks checks that programs run", "[grade][assignment]") {
  std::string error;
  std::optional<Assignment> a = load("title = \"x\"\n", error);
  REQUIRE(a);
  REQUIRE(a->checks.size() == 1);
  CHECK(a->checks[0].kind == Check::NoError);
  CHECK(a->seeds == std::vector<uint64_t>{1});
  CHECK_FALSE(a->needsSolution());
}

TEST_CASE("mistakes in an assignment file say where and what", "[grade][assignment]") {
  CHECK(errorOf("[[check]]\nkind = \"trial\"\n") == "2:8: unknown check kind 'trial'; did you mean 'trail'?");
  CHECK(errorOf("[[check]]\nkind = \"trail\"\npath = [[0, 0]]\ntolerence = 3\n") ==
        "4:1: unknown key 'tolerence' in check 'trail'; did you mean 'tolerance'?");
  CHECK(errorOf("[run]\nseed = [1]\n") == "2:1: unknown key 'seed' in [run]; did you mean 'seeds'?");
  CHECK(errorOf("[run]\nmax-steps = -1\n").find("max-steps must be a whole number") != std::string::npos);
  CHECK(errorOf("[[check]]\nkind = \"ends-in\"\nrect = [1, 2, 3]\n") == "3:8: rect must be a list of 4 numbers");
  CHECK(errorOf("[[check]]\nkind = \"trail\"\npath = [[nan, 300], [400, 180]]\n") ==
        "3:10: each point of path's entries must be a finite number, not nan");
  CHECK(errorOf("[run]\ntimeout = inf\n") == "2:11: timeout must be a finite number, not inf");
  CHECK(errorOf("[[check]]\nkind = \"screen\"\nreference = \"nope.png\"\n").find("no such file") != std::string::npos);
  CHECK(errorOf("[[check]]\nkind = \"solution-screen\"\n").find("need the reference solution") != std::string::npos);
  CHECK(errorOf("[[check]]\nkind = \"solution-screen\"\ntolerance = 5\nsolution = \"x\"\n")
            .find("unknown key 'solution'") != std::string::npos);
  CHECK(errorOf("[[check]]\nkind = \"output\"\nregex = \"(\"\n").find("bad regex '('") != std::string::npos);
  CHECK(errorOf("[[check]]\nkind = \"output\"\n").find("needs either text") != std::string::npos);
  CHECK(errorOf("title = \"unclosed\n").rfind("1:", 0) == 0);  // TOML syntax errors keep their place
  std::string error;
  CHECK_FALSE(loadAssignment("/no/such/assignment.toml", error));
  CHECK(error == "/no/such/assignment.toml: no such file");
}

TEST_CASE("text toml++ cannot read safely is refused with its place", "[grade][assignment]") {
  std::string error;
  // Not ASCII outside a string or comment (toml++ 3.3 classifies it with undefined code).
  CHECK_FALSE(load("x = 0%11\xCF\x91\n", error));
  CHECK(error.find(":1:9: a character that is not ASCII outside a string or comment") != std::string::npos);
  // Quotes inside a bare word open no string: toml++ reads on through the word (found by
  // rb_fuzz_grade).
  CHECK_FALSE(load("x = 0%1\"\"\"1\xCF\x91" "c\n", error));
  CHECK(error.find(":1:12: a character that is not ASCII outside a string or comment") != std::string::npos);
  CHECK_FALSE(load("x = a'b\xC3\xA9'\n", error));
  CHECK(error.find(":1:8: a character that is not ASCII") != std::string::npos);
  // First after a multi-line string's line-ending backslash, even after blanks.
  CHECK_FALSE(load("title = \"\"\"\\\n   \xC2\xA7\"\"\"\n", error));
  CHECK(error.find(":2:4: a character that is not ASCII first after a line-ending backslash") != std::string::npos);
  // Not UTF-8.
  CHECK_FALSE(load("title = \"a\xFF\"\n", error));
  CHECK(error.find(":1:11: the file is not UTF-8 text") != std::string::npos);
  CHECK_FALSE(load("title = \"\xED\xA0\x80\"\n", error));  // a surrogate
  CHECK(error.find("not UTF-8") != std::string::npos);
  // Strings, comments and keys in quotes may hold any character.
  std::optional<Assignment> a = load("title = \"Caf\xC3\xA9 \xE2\x82\xAC\"  # \xC3\xA9t\xC3\xA9\n"
                                     "[[check]]\nname = 'd\xC3\xA9j\xC3\xA0'\nkind = \"no-error\"\n"
                                     "hint = \"\"\"\\\n  x \xC3\xA9\"\"\"\n", error);
  INFO(error);
  REQUIRE(a);
  CHECK(a->title == "Caf\xC3\xA9 \xE2\x82\xAC");
  CHECK(a->checks[0].name == "d\xC3\xA9j\xC3\xA0");
  CHECK(a->checks[0].hint == "x \xC3\xA9");
}
