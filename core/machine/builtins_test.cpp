#include <catch2/catch.hpp>

#include <algorithm>
#include <set>

#include "lang/suggest.h"
#include "machine/builtins.h"

using namespace rb;

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
