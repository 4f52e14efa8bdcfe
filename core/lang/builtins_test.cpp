#include <catch2/catch.hpp>

#include <stdexcept>

#include "lang/builtins.h"

using namespace rb;

namespace {
using K = BuiltinKind;

BuiltinTable smallTable() {
  return BuiltinTable({
      {"rForward", K::Command, "robot", "distance", nullptr, 0, "moves"},
      {"MsgBox", K::Command, "input", "text [, title]", nullptr, 0, "shows a box"},
      {"MsgBox", K::Function, "input", "text [, title]", nullptr, 0, "shows a box, returns"},
      {"mid", K::Function, "string", "s, start [, count]", nullptr, 0, "part of s"},
      {"pi", K::Function, "math", "[factor]", nullptr, 0, "3.14..."},
      {"min", K::Function, "math", "a, b...", nullptr, 0, "smallest"},
      {"xyText", K::Command, "graphics", "x, y, items...", nullptr, 0, "text at x, y"},
      {"GetKey", K::Command, "input", "[prompt,] &key", nullptr, 0, "waits for a key"},
      {"Red", K::Constant, "colour", "", nullptr, 4, "colour 4"},
  });
}
}  // namespace

TEST_CASE("a table finds names without regard to case, per kind", "[builtins]") {
  BuiltinTable t = smallTable();
  const Builtin* f = t.find("RFORWARD", K::Command);
  REQUIRE(f);
  CHECK(f->name == "rForward");
  CHECK(t.find("rforward", K::Function) == nullptr);
  CHECK(t.find("MSGBOX", K::Command) != t.find("msgbox", K::Function));
  CHECK(t.findAny("red")->kind == K::Constant);
  CHECK(t.findAny("nosuch") == nullptr);
  CHECK(t.find("rForwardX", K::Command) == nullptr);
  CHECK(&t.at(t.indexOf(*f)) == f);
  CHECK(t.names(K::Constant) == std::vector<std::string_view>{"Red"});
}

TEST_CASE("signatures give arity, output parameters and print lists", "[builtins]") {
  BuiltinTable t = smallTable();
  const Builtin* mid = t.find("mid", K::Function);
  CHECK(mid->arityText() == "2 to 3");
  CHECK(mid->param(3, 2).name == "count");
  const Builtin* mn = t.find("min", K::Function);
  CHECK(mn->maxArgs == -1);
  CHECK(mn->arityText() == "at least 2");
  CHECK(mn->param(9, 8).name == "b");
  CHECK(t.find("xyText", K::Command)->printList);
  const Builtin* key = t.find("GetKey", K::Command);
  CHECK(key->acceptsCount(1));
  CHECK(key->acceptsCount(2));
  CHECK(key->param(1, 0).out);
  CHECK_FALSE(key->param(2, 0).out);
  CHECK(key->param(2, 1).out);
}

TEST_CASE("a malformed table is a programming error", "[builtins]") {
  CHECK_THROWS_AS(BuiltinTable({{"a", K::Command, "g", "x [, y", nullptr, 0, "h"}}), std::logic_error);
  CHECK_THROWS_AS(BuiltinTable({{"a", K::Command, "g", "x ]", nullptr, 0, "h"}}), std::logic_error);
  CHECK_THROWS_AS(BuiltinTable({{"a", K::Command, "g", "", nullptr, 0, "h"},
                                {"A", K::Command, "g", "", nullptr, 0, "h"}}),
                  std::logic_error);
}

TEST_CASE("one rule says where a built-in name may stand, with one message shape", "[builtins]") {
  BuiltinTable t = smallTable();
  auto misuse = [&](std::string_view name, NamePlace place) {
    return t.misuse(name, place).value_or("");
  };
  // Names that are no built-in, and built-ins used as what they are.
  CHECK(misuse("speed", NamePlace::Store).empty());
  CHECK(misuse("rForward", NamePlace::Statement).empty());
  CHECK(misuse("red", NamePlace::Value).empty());
  CHECK(misuse("Mid", NamePlace::Call).empty());
  CHECK(misuse("MsgBox", NamePlace::Statement).empty());
  CHECK(misuse("MsgBox", NamePlace::Call).empty());
  CHECK(misuse("Red", NamePlace::Sub).empty());  // a constant is never called

  CHECK(misuse("pi", NamePlace::Statement) ==
        "cannot use 'pi' as a statement: it is a built-in function; use its value, as in x = pi(...)");
  CHECK(misuse("red", NamePlace::Statement) == "cannot use 'red' as a statement: it is a built-in constant");
  CHECK(misuse("PI", NamePlace::Value) == "cannot use 'PI' as a variable: it is a built-in function; write pi()");
  CHECK(misuse("rforward", NamePlace::Value) ==
        "cannot use 'rforward' as a variable: it is a built-in command");
  CHECK(misuse("rForward", NamePlace::Call) ==
        "cannot call 'rForward' as a function: it is a built-in command; write it as a statement");
  // Where the program names something of its own, which built-in has the name: its usage and
  // its help up to the first "; ".
  CHECK(misuse("mid", NamePlace::Array) ==
        "cannot use 'mid' as an array: it is a built-in function (mid(s, start [, count]): part of s)");
  CHECK(misuse("Red", NamePlace::Store) == "cannot assign to 'Red': it is a built-in constant (Red: colour 4)");
  CHECK(misuse("rForward", NamePlace::Store) ==
        "cannot assign to 'rForward': it is a built-in command (rForward distance: moves)");
  CHECK(misuse("mid", NamePlace::Sub) ==
        "cannot use 'mid' as a sub name: it is a built-in function (mid(s, start [, count]): part of s)");
  CHECK(misuse("GetKey", NamePlace::Store) ==
        "cannot assign to 'GetKey': it is a built-in command (GetKey [prompt,] &key: waits for a key)");
}
