#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

#include "base/diagnostic.h"
#include "machine/test_support.h"

using namespace rb;
using rb::test::runProgram;

TEST_CASE("a program runs in-process with a test host", "[interpreter]") {
  auto o = runProgram("for i = 1 to 3\n  s = s + i\nnext\n");
  CHECK(o.loaded);
  CHECK(o.diagnostics ==
        "test.bas:2:7: error: variable 's' is used before it is given a value [rb-runtime-error]\n"
        "    2 |   s = s + i\n"
        "      |       ^\n");
  auto ok = runProgram("s = 0\nfor i = 1 to 3\n  s = s + i\nnext\nprint s\n");
  CHECK(ok.out == "6\n");
  CHECK(ok.result.status == RunStatus::Finished);
}

TEST_CASE("load errors stop the program before anything runs", "[interpreter]") {
  auto o = runProgram("print 1\ngoto Nowhere\n");
  CHECK_FALSE(o.loaded);
  CHECK(o.out.empty());
  CHECK(o.diagnostics.find("test.bas:2:6: error: undefined label 'Nowhere'") == 0);
}

TEST_CASE("statements are counted exactly for --max-steps", "[interpreter]") {
  // Each pass runs 3 statements (the while test, x = x + 1, wend); the limit falls mid-loop.
  RunLimits limits;
  limits.maxSteps = 10;
  auto o = runProgram("x = 0\nwhile x < 100\n  x = x + 1\nwend\n", {}, {}, limits);
  CHECK(o.result.status == RunStatus::StepLimit);
  CHECK(o.result.steps == 10);
  auto full = runProgram("x = 0\nfor i = 1 to 4\n  if i = 2 then x = 1\nnext\nprint x\n");
  // 1 (x = 0) + 1 (for) + 4 * (if + next) + 1 (print) = 11
  CHECK(full.result.steps == 11);
}

TEST_CASE("statements in subs, calls and returns are counted exactly", "[interpreter]") {
  const char* prog =
      "x = 0\nfor i = 1 to 3\n  call F(i, x)\nnext\nprint x + Twice(2)\nend\n"
      "sub F(n, &r)\n  r = r + n\nreturn\nsub Twice(v)\n  return 2 * v\n";
  // x = 0, for, 3 * (call, r = r + n, return, next), print, return 2 * v, end
  auto full = runProgram(prog);
  CHECK(full.out == "10\n");
  CHECK(full.result.steps == 17);
  for (uint64_t limit : {14u, 16u}) {
    RunLimits limits;
    limits.maxSteps = limit;
    auto o = runProgram(prog, {}, {}, limits);
    CHECK(o.result.status == RunStatus::StepLimit);
    CHECK(o.result.steps == limit);
  }
  RunLimits limits;
  limits.maxSteps = 14;
  // The 14th statement is the third `next`.
  CHECK(runProgram(prog, {}, {}, limits).diagnostics.find("test.bas:4:1: error: stopped after 14 steps") == 0);
}

TEST_CASE("nested calls are limited exactly, for subs and for gosubs", "[interpreter]") {
  RunLimits limits;
  limits.maxCallDepth = 300;  // past the first growth of the frame storage
  const char* sub = "call R(%d)\nprint \"done\"\nend\nsub R(n)\n  if n > 1 then call R(n - 1)\nreturn\n";
  const char* gosub = "n = %d\ngosub G\nprint \"done\"\nend\nG:\n  n = n - 1\n  if n > 0 then gosub G\nreturn\n";
  for (const char* form : {sub, gosub}) {
    char text[200];
    std::snprintf(text, sizeof text, form, 300);  // 300 nested: allowed
    auto ok = runProgram(text, {}, {}, limits);
    CHECK(ok.diagnostics == "");
    CHECK(ok.out == "done\n");
    std::snprintf(text, sizeof text, form, 301);
    auto deep = runProgram(text, {}, {}, limits);
    CHECK(deep.result.status == RunStatus::RuntimeError);
    CHECK(deep.diagnostics.find("error: too many nested gosub/call (300): runaway recursion?") != std::string::npos);
    CHECK(deep.out.empty());
  }
}

TEST_CASE("includes come from the reader and errors name their file", "[interpreter]") {
  test::MemoryReader files;
  files.files["lib.bas"] = "sub Two()\n  return 2\n";
  auto o = runProgram("#include \"lib.bas\"\nprint Two() + 1\n", files);
  CHECK(o.out == "3\n");
  files.files["bad.bas"] = "\n  frob 1\n";
  auto b = runProgram("#include \"bad.bas\"\n", files);
  CHECK(b.diagnostics.find("In file included from test.bas:1:\nbad.bas:2:3: error: unknown command 'frob'") == 0);
}

TEST_CASE("input gives numbers for numeric lines, strings otherwise", "[interpreter]") {
  auto o = runProgram("input \"n? \", n\ninput s\nprint n * 2, s\n", {}, {"21", "abc"});
  CHECK(o.out == "n? 42abc\n");
}

TEST_CASE("gosub from inside a sub keeps the sub's locals", "[interpreter]") {
  auto o = runProgram(
      "call F(5)\nend\nsub F(a)\n  b = a * 2\n  gosub G\n  print a, b\nreturn\n"
      "G:\n  t = 1 + 2 * 3\nreturn\n");
  CHECK(o.diagnostics == "");
  CHECK(o.out == "510\n");
}

TEST_CASE("deep recursion in subs grows the stack safely", "[interpreter]") {
  auto o = runProgram("print Sum(20000)\nend\nsub Sum(n)\n  if n = 0 then return 0\n  return n + Sum(n - 1)\n");
  CHECK(o.out == "200010000\n");
}

namespace {
/// A live view whose user quits while the program waits: the host asks for the stop and
/// answers the waiting call at once.
class QuittingHost : public rb::test::TestHost {
 public:
  int64_t waitKey(std::string_view) override {
    requestStop();
    return 0;
  }
  std::optional<std::string> inputLine(std::string_view) override {
    requestStop();
    return std::nullopt;  // no line: the machine raises "no more input", which is dropped
  }
};

RunResult runQuitting(const std::string& text, std::string& out) {
  DiagnosticList diags;
  rb::test::MemoryReader reader;
  reader.files["test.bas"] = text;
  auto loaded = loadProgram("test.bas", text, reader, standardBuiltins(), {}, diags);
  auto program = compileProgram(*loaded, {}, diags);
  REQUIRE(program);
  QuittingHost host;
  Machine machine(host, 1);
  RunResult r = Interpreter(*program, machine).run({});
  out = host.out;
  return r;
}
}  // namespace

TEST_CASE("a host that stops the run inside a call ends it as Stopped", "[interpreter]") {
  std::string out;
  RunResult r = runQuitting("print 1\nwaitKey k\nprint 2\n", out);
  CHECK(r.status == RunStatus::Stopped);
  CHECK_FALSE(r.error);
  CHECK(out == "1\n");  // nothing after the call that was answered by the quit
  r = runQuitting("print 1\ninput x\nprint 2\n", out);
  CHECK(r.status == RunStatus::Stopped);
  CHECK_FALSE(r.error);
  CHECK(out == "1\n");
}

namespace {

/// The program compiled as runProgram compiles it (finished unless `finish` is false).
std::unique_ptr<Program> compiled(const std::string& text, bool finish = true) {
  DiagnosticList diags;
  rb::test::MemoryReader reader;
  reader.files["test.bas"] = text;
  auto loaded = loadProgram("test.bas", text, reader, standardBuiltins(), {}, diags);
  CompileOptions options;
  options.finish = finish;
  return compileProgram(*loaded, options, diags);
}

/// The first parameter of `sub` that calls do not copy in (its paramCount when there is none).
uint32_t outputsOf(const Program& p, const std::string& sub) {
  for (const SubInfo& s : p.subs)
    if (s.name == sub) return std::min(s.outputsFrom, s.paramCount);
  FAIL("no sub " << sub);
  return 0;
}

}  // namespace

TEST_CASE("finished code runs as the plain code does: output, errors and every step", "[interpreter]") {
  const char* programs[] = {
      // & outputs set on both branches, recursion (their slots are reused, call after call)
      "call Fib(12, r)\nprint r\nend\nsub Fib(n, &r)\n  if n < 2\n    r = n\n  else\n"
      "    call Fib(n - 1, a)\n    call Fib(n - 2, b)\n    r = a + b\n  endif\nreturn\n",
      // set on one branch only: the caller's value must come back from the other
      "r = 1\ncall Maybe(0, r)\nprint r\ncall Maybe(1, r)\nprint r\nend\n"
      "sub Maybe(c, &r)\n  if c then r = 5\nreturn\n",
      // read before it is set
      "r = 10\ncall Acc(5, r)\nprint r\nend\nsub Acc(n, &r)\n  r = r + n\nreturn\n",
      // an output before a by-value parameter, and one after
      "call Mixed(p, 3, q)\nprint p, q\nend\nsub Mixed(&r, n, &s)\n  r = n\n  s = n * 2\nreturn\n",
      // set only inside a loop that may not run
      "r = 7\ncall Loop(0, r)\nprint r\ncall Loop(3, r)\nprint r\nend\n"
      "sub Loop(n, &r)\n  for i = 1 to n\n    r = i\n  next\nreturn\n",
      "r = 7\ncall W(0, r)\nprint r\nend\nsub W(n, &r)\n  while n > 0\n    r = n\n    n = n - 1\n"
      "  wend\nreturn\n",
      // an error inside the sub, with an output not yet set
      "call E(r)\nprint r\nend\nsub E(&r)\n  r = q\nreturn\n",
      // the same variable twice, a function with an output, a call among the arguments
      "call Two(x, x)\nprint x\ny = F(3, r) + F(4, t)\nprint y, r, t\ncall P(F(1, z), w)\n"
      "print z, w\nend\nsub Two(&a, &b)\n  a = 1\n  b = 2\nreturn\nsub F(n, &r)\n  r = n * 2\n"
      "return n + 1\nsub P(v, &w)\n  w = v\nreturn\n",
      // strings into outputs, over and over
      "s = \"\"\nfor i = 1 to 5\n  call S(i, t)\n  s = s + t\nnext\nprint s\nend\n"
      "sub S(i, &t)\n  t = \"<\" + i + \">\"\nreturn\n",
      // returns from inside blocks, jumps to returns, an end inside a sub
      "for i = 1 to 6\n  print Kind(i);\nnext\nprint\ncall Stop(2)\nprint \"not here\"\nend\n"
      "sub Kind(n)\n  if n < 2\n    k = \"a\"\n  elseif n < 4\n    k = \"b\"\n  else\n"
      "    return \"c\"\n  endif\nreturn k\nsub Stop(n)\n  if n = 2\n    print \"stop\"\n"
      "    end\n  endif\nreturn\n",
      // jumps to the end of the program
      "for i = 1 to 3\n  if i <> 2\n    print \"no\"\n  else\n    print \"yes\"\n  endif\nnext\n"
      "if i > 3\n  print \"done\"\nelse\n  print \"not done\"\nendif\n",
      // a return reached by a jump, in the wrong place: its error names the return
      "gosub Inside\nend\nsub F(n)\nInside:\n  if 1 < 2\n    k = 1\n  else\n    k = 2\n  endif\n"
      "return 5\n",
      // +, - and * with a constant on the right (their K forms) and every case they leave to
      // the general handlers: overflows, strings, a number over a string, errors
      "x = 9223372036854775807\ny = x + 1\nprint y\nz = -x - 2\nprint z\nm = x * 2\nprint m\n"
      "s = \"a\" + 1\nprint s\nt = \"b\"\nt = t + 2.5\nprint t\nu = 3\nu = u * 0.5\nprint u\n"
      "v = 2.5\nv = v - 1\nprint v\nw = \"s\"\nw = 4 - 1\nprint w\nprint 7 - 0.5, 2 * 3, 2.5 * 2\n",
      "s = \"a\"\nprint s - 1\n",
      "s = \"a\"\nprint s * 2.5\n",
      "print q + 1\n",
      "x = 1e308\nprint x * 10.0\n",
      "x = -1e308\nprint x - 1e308\n",
      // a gosub inside a sub, whose code sets the output
      "call G(r)\nprint r\nend\nsub G(&r)\n  gosub Set\n  return\nSet:\n  r = 2\n  return\n",
      // the interpreter's in-place forms (x = x + y, n = n + 1, n = n - 1, x = x + 0.5) on
      // every kind of value, and x = x + b * c run as one (MulAddSelf), with every case it
      // leaves to the Mul and the AddSelf run one after the other
      "x = 0.5\nt = 0\nfor i = 1 to 5\n  x = x + i * 0.5\n  t = t + i * i\n  t = t + i\nnext\n"
      "print x, t\nm = 1\nm = m + 2.5 * 2\ny = 1.5\ny = y + 3 * 4\ny = y + 1.5 * 2\nprint m, y\n"
      "n = 9223372036854775807\nn = n + 1\nk = 3\nk = k + n * 2\nprint n, k\n"
      "j = 9223372036854775800\nj = j + 3 * 4\nprint j\ns = \"a\"\ns = s + 2 * 3\ns = s + 1\nprint s\n"
      "w = -9223372036854775807\nw = w - 1\nw = w - 1\nprint w\nf = 2\nf = f + 0.25\nprint f\n",
      "z = 1.0\nz = z + 1e308 * 10.0\n",
      "z = 1e308\nz = z + 1e308 * 1.0\n",
      "z = 1e308\nz = z + 1e308\n",
      "x = x + 2 * 3\n",
      "x = 1.5\nx = x + y * 2\n",
      "t = 1\nt = t + \"b\" * 2\n",
      "u = 1\nu = u + 1\nv = v + 1\n",
  };
  for (const char* text : programs) {
    INFO(text);
    CompileOptions plainCode;
    plainCode.finish = false;
    auto finished = runProgram(text);
    auto plain = runProgram(text, {}, {}, {}, plainCode);
    REQUIRE(plain.loaded);
    CHECK(finished.out == plain.out);
    CHECK(finished.diagnostics == plain.diagnostics);
    CHECK(finished.result.status == plain.result.status);
    CHECK(finished.result.steps == plain.result.steps);
    // Finished with a Line instruction before each statement (the web page's runs): the same.
    CompileOptions tracedFinished;
    tracedFinished.lineTracing = tracedFinished.finishTraced = true;
    auto traced = runProgram(text, {}, {}, {}, tracedFinished);
    CHECK(traced.out == plain.out);
    CHECK(traced.diagnostics == plain.diagnostics);
    CHECK(traced.result.status == plain.result.status);
    // After a runtime error traced code also counts the statements begun since the last
    // transfer (its Line instructions mark them; see the next test).
    if (plain.result.status == RunStatus::RuntimeError) CHECK(traced.result.steps >= plain.result.steps);
    else CHECK(traced.result.steps == plain.result.steps);
    // Stopped after every number of steps, both stop at the same statement with the same output.
    for (uint64_t limit = 1; limit < plain.result.steps; ++limit) {
      RunLimits limits;
      limits.maxSteps = limit;
      auto a = runProgram(text, {}, {}, limits);
      auto b = runProgram(text, {}, {}, limits, plainCode);
      CHECK(a.out == b.out);
      CHECK(a.diagnostics == b.diagnostics);
      CHECK(a.result.steps == b.result.steps);
      auto c = runProgram(text, {}, {}, limits, tracedFinished);
      CHECK(c.out == b.out);
      CHECK(c.diagnostics == b.diagnostics);
      CHECK(c.result.steps == b.result.steps);
    }
  }
}

TEST_CASE("a variable with no value is reported at its name, where rb check warns", "[interpreter]") {
  auto o = runProgram("x = 1\nprint x + zz\n");
  CHECK(o.result.status == RunStatus::RuntimeError);
  REQUIRE(o.result.error);
  CHECK(o.result.error->loc.line == 2);
  CHECK(o.result.error->loc.col == 11);  // zz, not the + at 9
  // The same name twice on a line: the reading nearest the operator that failed.
  auto twice = runProgram("y = 2\nprint (y - 1) * (q + q)\n");
  REQUIRE(twice.result.error);
  CHECK(twice.result.error->loc.col == 18);
  // Other errors stay at their operator.
  auto zero = runProgram("x = 0\nprint 3 / x\n");
  REQUIRE(zero.result.error);
  CHECK(zero.result.error->loc.col == 9);
}

TEST_CASE("a runtime error in line-traced code counts the statements begun", "[interpreter]") {
  // Steps are credited at control transfers: untraced, a crash in the first statements counts
  // none; traced (the web page's runs), their Line instructions say how many began.
  CompileOptions traced;
  traced.lineTracing = true;
  auto crash = runProgram("rLocate 400,300\nx = 1\nrForward 1000\nprint \"not here\"\n", {}, {}, {}, traced);
  CHECK(crash.result.status == RunStatus::RuntimeError);
  CHECK(crash.result.steps == 3);
  // After a loop: the loop's statements as ever, then those begun after it.
  auto after = runProgram("for i = 1 to 3\n  x = i\nnext\nprint 1 / 0\n", {}, {}, {}, traced);
  CHECK(after.result.status == RunStatus::RuntimeError);
  CHECK(after.result.steps == 1 + 3 * 2 + 1);
}

TEST_CASE("line-traced code is finished only when asked (the web page's Step)", "[interpreter]") {
  const std::string text = "call Two(x, y)\nend\nsub Two(&a, &b)\n  a = 1\n  b = 2\nreturn\n";
  auto compileWith = [&](bool finishTraced) {
    DiagnosticList diags;
    rb::test::MemoryReader reader;
    auto loaded = loadProgram("test.bas", text, reader, standardBuiltins(), {}, diags);
    CompileOptions options;
    options.lineTracing = true;
    options.finishTraced = finishTraced;
    return compileProgram(*loaded, options, diags);
  };
  auto plain = compileWith(false), finished = compileWith(true);
  REQUIRE((plain && finished));
  CHECK_FALSE(plain->finished);  // the live view shows the copies in
  CHECK(finished->finished);
  CHECK(finished->code.size() == plain->code.size() - 2);
}

TEST_CASE("by-reference parameters set before every read and return are not copied in", "[interpreter]") {
  auto p = compiled("sub Fib(n, &r)\n  if n < 2\n    r = n\n  else\n    call Fib(n - 1, a)\n"
                    "    call Fib(n - 2, b)\n    r = a + b\n  endif\nreturn\n"
                    "sub Maybe(c, &r)\n  if c then r = 5\nreturn\n"
                    "sub Acc(n, &r)\n  r = r + n\nreturn\n"
                    "sub Mixed(&r, n, &s)\n  r = n\n  s = n * 2\nreturn\n"
                    "sub Two(&a, &b)\n  a = 1\n  b = 2\nreturn\n"
                    "sub G(&r)\n  gosub Set\n  return\nSet:\n  r = 2\n  return\n");
  REQUIRE(p);
  CHECK(outputsOf(*p, "Fib") == 1);
  CHECK(outputsOf(*p, "Maybe") == 2);  // not set when c is 0
  CHECK(outputsOf(*p, "Acc") == 2);    // read first
  CHECK(outputsOf(*p, "Mixed") == 2);    // s only: r is before a by-value parameter
  CHECK(outputsOf(*p, "Two") == 0);
  CHECK(outputsOf(*p, "G") == 1);      // a gosub: not followed
  auto plain = compiled("call Two(x, y)\nend\nsub Two(&a, &b)\n  a = 1\n  b = 2\nreturn\n", false);
  auto finished = compiled("call Two(x, y)\nend\nsub Two(&a, &b)\n  a = 1\n  b = 2\nreturn\n");
  REQUIRE((plain && finished));
  CHECK(finished->code.size() == plain->code.size() - 2);  // both copies in are gone
  CHECK(outputsOf(*plain, "Two") == 2);
}

namespace {

/// Files on disk, for the golden programs and what they include.
class DiskReader : public SourceReader {
 public:
  std::optional<std::string> find(const std::string& path) override {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
    return std::filesystem::weakly_canonical(path, ec).string();
  }
  std::optional<std::string> read(const std::string& canonical) override {
    std::ifstream in(canonical, std::ios::binary);
    if (!in) return std::nullopt;
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }
};

}  // namespace

TEST_CASE("every golden program runs the same with its code finished and plain", "[interpreter]") {
  // rb test runs golden programs line-traced, that is with plain code; rb run finishes the
  // code (compiler_finish.cpp). Here each runs both ways, in-process: the same output, error
  // and statement count. Programs that need command-line options (// args:) are left out.
  size_t compared = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(RB_TESTDATA_DIR)) {
    if (entry.path().extension() != ".bas") continue;
    std::string path = entry.path().string();
    std::string text = *DiskReader().read(path);
    if (text.rfind("// nontest", 0) == 0 || text.find("// args:") != std::string::npos ||
        text.find("// skip:") != std::string::npos)
      continue;
    INFO(path);
    // As rb test runs it: seed 1 (runSource's machine) and its // stdin: lines.
    std::deque<std::string> input;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);)
      if (auto at = line.find("// stdin: "); at != std::string::npos) input.push_back(line.substr(at + 10));
    RunLimits limits;
    limits.maxSteps = 300'000;  // enough for nearly all; a longer one is compared up to there
    CompileOptions plainCode;
    plainCode.finish = false;
    DiskReader reader;
    auto finished = rb::test::runSource(path, text, reader, input, limits);
    auto plain = rb::test::runSource(path, text, reader, input, limits, plainCode);
    REQUIRE(finished.loaded == plain.loaded);
    if (!plain.loaded) continue;
    CHECK(finished.out == plain.out);
    CHECK(finished.diagnostics == plain.diagnostics);
    CHECK(finished.result.status == plain.result.status);
    CHECK(finished.result.steps == plain.result.steps);
    ++compared;
  }
  CHECK(compared > 150);
}
