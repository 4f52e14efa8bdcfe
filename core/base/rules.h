#pragma once
// The one table of diagnostic rules: every rule code rb reports, with its severity, a one-line
// summary and a full description (Markdown, as docs/diagnostics.md shows it). Every front end
// reads it: the text and machine formats (SARIF's rule metadata), the language server (a
// diagnostic's link and hover), and docs/diagnostics.md's table, which is generated from it
// (scripts/gen_rules_doc.py; a test fails when they drift).

#include <span>
#include <string>
#include <string_view>

#include "base/diagnostic.h"

namespace rb {

struct Rule {
  std::string_view id;           ///< "rb-undefined-label"
  Severity severity;             ///< what rb reports it as
  std::string_view summary;      ///< one line, plain text
  std::string_view description;  ///< the full description: Markdown, links relative to docs/diagnostics.md
};

/// Every rule, in the order docs/diagnostics.md lists them.
std::span<const Rule> allRules();

/// The rule with that code, or nullptr.
const Rule* findRule(std::string_view id);

/// Where rb's documentation is published (a folder URL ending in '/'; the build's RB_DOCS_URL).
std::string_view docsBaseUrl();

/// The rule's section of docs/diagnostics.md, as an absolute URL.
std::string ruleUrl(std::string_view id);

/// The full description as plain text: Markdown code spans and links reduced to their text.
std::string ruleText(const Rule& rule);

/// The full description as Markdown whose links are absolute (for a reader outside docs/).
std::string ruleMarkdown(const Rule& rule);

}  // namespace rb
