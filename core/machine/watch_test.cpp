#include "machine/watch.h"

#include <catch2/catch.hpp>

#include <functional>

#include "machine/test_support.h"

using namespace rb;

namespace {

/// A host that looks at the program's variables before each statement of one line.
class LookingHost : public test::TestHost {
 public:
  void onLine(SourceLoc loc) override {
    if (loc.line == line && look) look(interp->variables(), *machine);
  }
  uint32_t line = 0;
  std::function<void(const std::vector<VariableView>&, Machine&)> look;
  const Interpreter* interp = nullptr;
  Machine* machine = nullptr;
};

/// Runs `text` (compiled with line tracing) and calls `look` before line `line` runs.
void runLooking(const std::string& text, uint32_t line,
                std::function<void(const std::vector<VariableView>&, Machine&)> look) {
  test::MemoryReader reader;
  reader.files["test.bas"] = text;
  DiagnosticList diags;
  auto loaded = loadProgram("test.bas", text, reader, standardBuiltins(), {}, diags);
  CompileOptions options;
  options.lineTracing = true;
  auto program = compileProgram(*loaded, options, diags);
  REQUIRE(program);
  LookingHost host;
  host.line = line;
  host.look = std::move(look);
  Machine machine(host, 1);
  Interpreter interp(*program, machine);
  host.interp = &interp;
  host.machine = &machine;
  RunResult r = interp.run({});
  REQUIRE(r.status == RunStatus::Finished);
}

const char* const kPrelude =
    "x = 7\n"
    "y = 2.5\n"
    "n = -3\n"
    "s = \"robot\"\n"
    "big = 9000000000000000000\n"
    "dim a[4]\n"
    "a[1] = 10\n"
    "a[3] = 30\n"
    "dim g[2, 3]\n"
    "g[1, 2] = 12\n";
constexpr uint32_t kAfterPrelude = 11;

/// The watch's value or error with the prelude's variables, as text.
std::string watched(const std::string& expr) {
  std::string out;
  runLooking(std::string(kPrelude) + "print 0\n", kAfterPrelude,
             [&](const std::vector<VariableView>& vars, Machine& m) {
               WatchResult r = Watch(expr).evaluate(vars, m);
               out = r.value ? formatValue(*r.value) : "error: " + r.error;
             });
  return out;
}

}  // namespace

TEST_CASE("watch: values as the interpreter computes them", "[machine][watch]") {
  // Each expression is printed by the program itself and computed by a watch: the same text.
  for (const char* expr :
       {"x * 2", "x / 2", "x / 7", "-x / -1", "x % 3", "n mod 2", "y * 2", "x ^ 2", "2 ^ -1",
        "big + big", "big * 3", "big - -big", "s + x", "x + s", "s + y", "x > 3", "s = \"robot\"",
        "s < \"s\"", "x = s", "x <> s", "x and 0", "x or 0", "not x", "!0", "-x", "~x", "x & 3",
        "x | 8", "x << 2", "n >> 1", "a[3] + 1", "a[1.9]", "g[1, 2]", "left(s, 2)",
        "mid(s, 2, 3)", "length(s) + 1", "abs(n)", "sqrt(16)", "max(x, y, 3)", "Red",
        "toString(y, 2)", "pi()", "(x + 1) * (y - 1)", "x == 7", "upper(s) + \"!\"",
        "2 ^ 0.5", "7 / 2.0", "x >= 7.0"}) {
    CAPTURE(expr);
    test::Outcome o = test::runProgram(std::string(kPrelude) + "print " + expr + "\n");
    REQUIRE(o.result.status == RunStatus::Finished);
    std::string printed = o.out.substr(0, o.out.size() - 1);  // without the line end
    CHECK(watched(expr) == printed);
  }
}

TEST_CASE("watch: the interpreter's errors, in place of a value", "[machine][watch]") {
  for (const char* expr : {"x / 0", "x % 0", "s - 1", "a[4]", "a[-1]", "g[1]", "g[2, 0]",
                           "x and s", "sqrt(-1)", "left(s)", "x(1)", "s[1]", "big * big * big ^ 40",
                           "-s", "s < 1"}) {
    CAPTURE(expr);
    test::Outcome o = test::runProgram(std::string(kPrelude) + "print " + expr + "\n");
    std::string got = watched(expr);
    REQUIRE(got.starts_with("error: "));
    if (o.loaded) {
      // Where the program runs at all, it stops with the same message.
      REQUIRE(o.result.status == RunStatus::RuntimeError);
      CHECK(o.diagnostics.find(got.substr(7)) != std::string::npos);
    }
  }
}

TEST_CASE("watch: names the program does not have, values it has not yet", "[machine][watch]") {
  CHECK(watched("zz") == "error: the program has no variable 'zz'");
  CHECK(watched("bigg + 1") == "error: the program has no variable 'bigg'; did you mean 'big'?");
  CHECK(watched("x +") == "error: expected an expression, found end of line");
  CHECK(watched("x 1") == "error: unexpected '1' after the end of the expression");
  std::string later;
  runLooking("u = 0\nif u = 1 then v = 1\nprint u\n", 3,
             [&](const std::vector<VariableView>& vars, Machine& m) {
               later = Watch("v * 2").evaluate(vars, m).error;
             });
  CHECK(later == "v is not assigned yet");
}

TEST_CASE("watch: calls only what computes", "[machine][watch]") {
  CHECK(watched("random(5)") == "error: a watch calls only the math and string functions, not random()");
  CHECK(watched("rRandom(1)") == "error: a watch calls only the math and string functions, not rRandom()");
  CHECK(watched("timer()") == "error: a watch calls only the math and string functions, not timer()");
  CHECK(watched("rRange()").starts_with("error: a watch calls only"));
  CHECK(watched("Area(2)") == "error: a watch calls no sub ('Area' is not a built-in function)");
  CHECK(isPureBuiltin("left"));
  CHECK(isPureBuiltin("SQRT"));
  CHECK_FALSE(isPureBuiltin("random"));
  CHECK_FALSE(isPureBuiltin("rForward"));
}

TEST_CASE("watch: in a sub its own names first, _name the global", "[machine][watch]") {
  std::vector<std::string> got;
  runLooking("x = 1\ncall F(5)\nend\nsub F(x)\n  y = x * 10\n  print y\nendsub\n", 6,
             [&](const std::vector<VariableView>& vars, Machine& m) {
               for (const char* e : {"x", "_x", "y * 2", "_y"}) {
                 WatchResult r = Watch(e).evaluate(vars, m);
                 got.push_back(r.value ? formatValue(*r.value) : r.error);
               }
             });
  CHECK(got == std::vector<std::string>{"5", "1", "100", "the program has no variable 'y'"});
}

TEST_CASE("watch: an array is shown whole", "[machine][watch]") {
  runLooking("dim a[3]\na[0] = 4\nprint a[0]\n", 3,
             [&](const std::vector<VariableView>& vars, Machine& m) {
               WatchResult r = Watch("a").evaluate(vars, m);
               REQUIRE(r.value);
               REQUIRE(r.value->isArr());
               CHECK(r.value->arr().items[0].i() == 4);
             });
}
