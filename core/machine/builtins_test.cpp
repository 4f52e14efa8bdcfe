#include <catch2/catch.hpp>

#include <algorithm>
#include <set>

#include "base/runtime_error.h"
#include "lang/suggest.h"
#include "machine/builtins.h"
#include "machine/builtins_impl.h"
#include "machine/machine.h"
#include "machine/test_support.h"

using namespace rb;

namespace {

/// Calls the built-in `name` of `kind` on `m` with `args` (which an output parameter changes).
Value call(Machine& m, std::string_view name, BuiltinKind kind, std::vector<Value>& args) {
  const Builtin* b = standardBuiltins().find(name, kind);
  REQUIRE(b);
  Args a(*b, args.data(), static_cast<int>(args.size()));
  return b->fn(m, a);
}

/// A host that says how much memory the run holds.
class HoldingHost : public test::TestHost {
 public:
  uint64_t held = 0;
  uint64_t memoryInUse() override { return held; }
};

}  // namespace

TEST_CASE("signatures give arity and output parameters", "[builtins]") {
  const Builtin* mid = standardBuiltins().find("MID", BuiltinKind::Function);
  REQUIRE(mid);
  CHECK(mid->minArgs == 2);
  CHECK(mid->maxArgs == 3);
  CHECK(mid->arityText() == "2 to 3");
  CHECK(mid->param(3, 2).name == "count");
  const Builtin* mn = standardBuiltins().find("min", BuiltinKind::Function);
  CHECK(mn->maxArgs == -1);
  CHECK(mn->param(7, 6).name == "b");
}

TEST_CASE("every built-in has a unique name per kind, a group and help", "[builtins]") {
  std::set<std::string> seen;
  for (const Builtin& b : standardBuiltins().rows()) {
    std::string key = std::to_string(static_cast<int>(b.kind)) + ":";
    for (char c : b.name) key += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    CHECK(seen.insert(key).second);
    CHECK_FALSE(b.help.empty());
    CHECK_FALSE(b.group.empty());
    if (b.kind != BuiltinKind::Constant) CHECK(b.fn != nullptr);
  }
}

TEST_CASE("every built-in has its evidence: a source that names it, or why it is rb's own", "[builtins]") {
  size_t confirmed = 0, own = 0;
  for (const Builtin& b : standardBuiltins().rows()) {
    INFO(b.name);
    CHECK(b.evidence.confirmed() != !b.evidence.reason.empty());
    if (b.evidence.confirmed()) CHECK(b.evidence.instead.empty());
    (b.evidence.confirmed() ? confirmed : own)++;
  }
  // The seed's own names are confirmed; names no source shows are rb's own.
  CHECK(standardBuiltins().find("rSlip", BuiltinKind::Command)->evidence.source == "seed, Figure 1.10");
  const Builtin* trimL = standardBuiltins().find("trimL", BuiltinKind::Function);
  CHECK_FALSE(trimL->evidence.confirmed());
  CHECK(standardBuiltins().find("rtod", BuiltinKind::Function)->evidence.instead == "x * 180 / pi()");
  CHECK(confirmed > 50);
  CHECK(own > 100);
}

TEST_CASE("the evidence table and the built-in table name the same built-ins", "[builtins]") {
  std::vector<Builtin> rows(standardBuiltins().rows().begin(), standardBuiltins().rows().end());
  CHECK_NOTHROW(builtins::applyEvidence(rows));
  // A built-in added without its evidence row is refused...
  std::vector<Builtin> more = rows;
  more.emplace_back("noSuchThing", BuiltinKind::Function, "math", "x", nullptr, 0, "help");
  CHECK_THROWS_WITH(builtins::applyEvidence(more),
                    Catch::Contains("'noSuchThing' has no evidence row"));
  // ...and so is a row left behind when its built-in goes.
  std::vector<Builtin> fewer;
  for (const Builtin& b : rows)
    if (b.name != "trimL") fewer.push_back(b);
  CHECK_THROWS_WITH(builtins::applyEvidence(fewer), Catch::Contains("the row 'trimL' names no built-in"));
}

TEST_CASE("edit distance and suggestions", "[suggest]") {
  CHECK(editDistance("prit", "print", false) == 1);
  CHECK(editDistance("pirnt", "print", false) == 1);  // a swap counts once
  CHECK(editDistance("Real", "real", true) == 0);
  CHECK(suggestCommand(standardBuiltins(), "prit") == "print");
  CHECK(suggestCommand(standardBuiltins(), "xyzzy").empty());
  CHECK(closestMatch("InitializeRobot", {"InitializeSimulator", "DrawSquare", "Main"}, false) ==
        "InitializeSimulator");
}

TEST_CASE("the standard table's suggestions: statements, fitting constants", "[suggest]") {
  const BuiltinTable& t = standardBuiltins();
  CHECK(suggestCommand(t, "nxt") == "next");  // not `not`, an operator
  CHECK(suggestCommand(t, "wnd") == "wend");
  CHECK(suggestCommand(t, "rForwad") == "rForward");
  auto fitting = [&](std::string_view name, std::string_view param) {
    return constantsFitting(t, *t.find(name, BuiltinKind::Command), param);
  };
  CHECK(fitting("rPen", "state") == std::vector<std::string_view>{"Up", "Down"});
  CHECK(fitting("flip", "mode") == std::vector<std::string_view>{"On", "Off"});
  std::vector<std::string_view> text = fitting("xyText", "style");
  CHECK(std::find(text.begin(), text.end(), "fs_Bold") != text.end());
  CHECK(std::find(text.begin(), text.end(), "Red") == text.end());
  std::vector<std::string_view> colours = fitting("rLocate", "colour");
  CHECK(colours.size() == 16);
  CHECK(std::find(colours.begin(), colours.end(), "LightGreen") != colours.end());
  CHECK(fitting("rForward", "distance").empty());
  CHECK(suggestValue("dwn", fitting("rPen", "state"), {}, t) == "Down");
  CHECK(suggestValue("yelow", colours, {"yellowish"}, t) == "Yellow");
}

TEST_CASE("a bounded edit distance is the distance, or bound + 1 beyond it", "[suggest]") {
  // Words over a small alphabet, so that near and far pairs both occur; some longer than the
  // 47 characters kept on the stack.
  uint32_t state = 12345;
  auto next = [&] { return state = state * 1103515245u + 12345u, (state >> 16) & 0x7fff; };
  auto word = [&] {
    std::string w(next() % 60, 'a');
    for (char& c : w) c = "abAB"[next() % 4];
    return w;
  };
  for (int i = 0; i < 2000; ++i) {
    std::string a = word(), b = word();
    bool ignoreCase = i % 2;
    int full = editDistance(a, b, ignoreCase);
    CHECK(full == editDistance(b, a, ignoreCase));
    for (size_t bound : {0u, 1u, 3u, 10u, 100u}) {
      INFO(a << " / " << b << " bound " << bound);
      CHECK(editDistance(a, b, ignoreCase, bound) == std::min(full, static_cast<int>(bound) + 1));
    }
  }
}

TEST_CASE("extract and mFromString look at the run's limits every 65,536 fields", "[builtins]") {
  test::TestHost host;
  Machine m(host, 1);
  const std::string many(70000, ',');  // 70,001 empty fields
  std::vector<Value> last{Value::string(many), Value::string(","), Value::integer(70001)};
  CHECK(call(m, "extract", BuiltinKind::Function, last).str().empty());
  std::vector<Value> few{Value::string("a::b::c"), Value::string("::"), Value::integer(2)};
  CHECK(call(m, "extract", BuiltinKind::Function, few).str() == "b");

  m.alarms().raise(RunAlarms::kDeadline);  // the time limit has passed
  CHECK_THROWS_AS(call(m, "extract", BuiltinKind::Function, last), DeadlinePassed);
  std::vector<Value> split{Value::integer(7), Value::string(many)};
  CHECK_THROWS_AS(call(m, "mFromString", BuiltinKind::Command, split), DeadlinePassed);
  CHECK(split[0].isInt());  // no array was made
  // Fewer fields are split before the limits are looked at: the call after them stops the run.
  CHECK(call(m, "extract", BuiltinKind::Function, few).str() == "b");
}

TEST_CASE("mFromString counts its array and strings against --max-memory before making them", "[builtins]") {
  HoldingHost host;
  Machine m(host, 1);
  m.memoryLimit = 4 << 20;
  // 100,001 empty strings: each an element and a string object, 6 MiB in all.
  std::vector<Value> strings{Value::integer(7), Value::string(std::string(100000, ','))};
  CHECK_THROWS_WITH(call(m, "mFromString", BuiltinKind::Command, strings),
                    "out of memory: mFromString's 100001 fields would need 6 MiB, more than the 4 MiB "
                    "of the --max-memory limit");
  CHECK(strings[0].isInt());  // nothing was made

  // Numbers take no string: 100,001 of them are 1.5 MiB, which fit...
  std::string ones = "1";
  for (int i = 0; i < 100000; ++i) ones += ",1";
  std::vector<Value> numbers{Value::integer(7), Value::string(ones)};
  call(m, "mFromString", BuiltinKind::Command, numbers);
  REQUIRE(numbers[0].isArr());
  CHECK(numbers[0].arr().items.size() == 100001);
  CHECK(numbers[0].arr().items[100000].i() == 1);
  // ... unless the run holds 3 MiB already.
  host.held = 3 << 20;
  numbers[0] = Value::integer(7);
  CHECK_THROWS_WITH(call(m, "mFromString", BuiltinKind::Command, numbers),
                    "out of memory: mFromString's 100001 fields would need 1 MiB beside the 3 MiB the "
                    "run holds already, more than the 4 MiB of the --max-memory limit");
  CHECK(numbers[0].isInt());
}

TEST_CASE("polygon and mPolygon look at the run's limits between the edges of an outline", "[builtins]") {
  test::TestHost host;
  Machine m(host, 1);
  Value flat = Value::array({8});
  Value rows = Value::array({4, 2});
  for (Value* v : {&flat, &rows})
    for (size_t i = 0; i < 8; ++i) v->arr().items[i] = Value::integer(static_cast<int64_t>(10 + 10 * (i % 3)));
  m.alarms().raise(RunAlarms::kDeadline);
  std::vector<Value> polygon{flat};
  CHECK_THROWS_AS(call(m, "polygon", BuiltinKind::Command, polygon), DeadlinePassed);
  std::vector<Value> mFlat{flat};
  CHECK_THROWS_AS(call(m, "mPolygon", BuiltinKind::Command, mFlat), DeadlinePassed);
  std::vector<Value> mRows{rows};
  CHECK_THROWS_AS(call(m, "mPolygon", BuiltinKind::Command, mRows), DeadlinePassed);
}

TEST_CASE("the machine keeps each sensor's last reading and the statement that read it", "[builtins]") {
  test::TestHost host;
  Machine m(host, 1);
  CHECK(m.lastReadings().empty());
  std::vector<Value> locate{Value::integer(400), Value::integer(40)};
  call(m, "rLocate", BuiltinKind::Command, locate);
  std::vector<Value> none;
  m.setLocation({0, 3, 1});
  CHECK(call(m, "rFeel", BuiltinKind::Function, none).i() == 0);
  m.setLocation({0, 4, 1});
  std::vector<Value> ahead;
  const int64_t range = call(m, "rRange", BuiltinKind::Function, ahead).i();
  m.setLocation({0, 5, 1});
  std::vector<Value> turn{Value::integer(-180)};
  call(m, "rTurn", BuiltinKind::Command, turn);  // no reading
  m.setLocation({0, 6, 1});
  call(m, "rFeel", BuiltinKind::Function, none);
  const std::vector<SensorReading>& r = m.lastReadings();
  REQUIRE(r.size() == 2);  // one per sensor, in the order first read
  CHECK(r[0].name == "rFeel");
  CHECK(r[0].loc.line == 6);
  CHECK(r[1].name == "rRange");
  CHECK(r[1].value == static_cast<double>(range));
  CHECK(r[1].loc.line == 4);
  CHECK(r[0].order > r[1].order);  // rFeel was read last
}
