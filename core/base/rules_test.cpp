#include "base/rules.h"

#include <catch2/catch.hpp>
#include <set>

TEST_CASE("rules: one row per code, each described", "[base]") {
  std::set<std::string_view> ids;
  for (const rb::Rule& r : rb::allRules()) {
    CHECK(r.id.starts_with("rb-"));
    CHECK(ids.insert(r.id).second);
    CHECK(!r.summary.empty());
    CHECK(!r.description.empty());
    CHECK(r.severity != rb::Severity::Note);
  }
  CHECK(rb::findRule("rb-syntax") != nullptr);
  CHECK(rb::findRule("rb-no-such-rule") == nullptr);
}

TEST_CASE("rules: descriptions as plain text and with absolute links", "[base]") {
  const rb::Rule* r = rb::findRule("rb-endless-loop");
  REQUIRE(r);
  std::string text = rb::ruleText(*r);
  CHECK(text.find('`') == std::string::npos);
  CHECK(text.find("](") == std::string::npos);
  CHECK(text.find("Loops that never end") != std::string::npos);
  std::string md = rb::ruleMarkdown(*r);
  CHECK(md.find("(" + std::string(rb::docsBaseUrl()) + "diagnostics.md#loops-that-never-end)") != std::string::npos);
  CHECK(rb::ruleUrl("rb-syntax") == std::string(rb::docsBaseUrl()) + "diagnostics.md#rb-syntax");
}
