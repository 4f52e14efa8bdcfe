#pragma once
// The one diagnostic type and its text formatter. Load-time errors, warnings from `rb check` and
// runtime errors are all Diagnostics, printed gcc-style:
//   file:line:col: error: message [rb-rule-code]
//       3 | rForwrd 120
//         | ^~~~~~~
//         | rForward
// (the machine formats, JSON, SARIF and GitHub annotations, are written by cmd/ from the same
// Diagnostics).

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "base/source.h"

namespace rb {

enum class Severity { Error, Warning, Note };

/// A suggested edit: replace the text from `start` up to (not including) `end` on one line by
/// `replacement` (start == end: insert).
struct FixIt {
  SourceLoc start;
  SourceLoc end;
  std::string replacement;
};

struct Diagnostic {
  Diagnostic() = default;
  Diagnostic(Severity severity_, SourceLoc loc_, std::string message_, std::string code_ = {},
             SourceLoc end_ = {})
      : severity(severity_), loc(loc_), message(std::move(message_)), code(std::move(code_)), end(end_) {}

  Severity severity = Severity::Error;
  SourceLoc loc;            ///< where the caret goes: the start of the range
  std::string message;
  std::string code;         ///< the rule ("rb-undefined-label"; docs/diagnostics.md lists them)
  SourceLoc end;            ///< the range's last character (inclusive); invalid: the word at loc
  std::vector<FixIt> fixits;
  /// Notes that belong to this diagnostic (runtime errors: "called from here"). Load-time
  /// notes are separate entries of a DiagnosticList, right after their diagnostic.
  std::vector<Diagnostic> notes;
};

/// A list of diagnostics that remembers whether any of them is an error.
class DiagnosticList {
 public:
  /// Each adds a diagnostic and returns it (valid until the next add), to set its range or
  /// fix-its.
  Diagnostic& error(SourceLoc loc, std::string message, std::string code = {});
  Diagnostic& warning(SourceLoc loc, std::string message, std::string code = {});
  Diagnostic& note(SourceLoc loc, std::string message);
  Diagnostic& add(Diagnostic d);

  /// The most errors a list keeps. The one past it becomes "too many errors" (rule
  /// rb-too-many-errors) and later diagnostics are dropped: the parser and the compiler stop at
  /// capped(), so a file of a million broken lines is rejected in a moment, in every command.
  static constexpr size_t kMaxErrors = 10'000;
  /// True once kMaxErrors errors are in and "too many errors" was added.
  bool capped() const { return capped_; }

  bool hasErrors() const { return errorCount_ > 0; }
  /// True when an error was already reported on that line (so a parser can stay quiet about
  /// the consequences of a lexical error).
  bool hasErrorOnLine(uint32_t file, uint32_t line) const {
    return errorLines_.count(lineKey(SourceLoc{file, line, 0})) > 0;
  }
  /// The first error reported on the line of `loc` when it starts at `loc`, else nullptr: for
  /// adding to a message what a later stage learns (the compiler, which block a misspelt
  /// closer leaves open). Valid until the next add or sort.
  Diagnostic* firstErrorAt(SourceLoc loc);
  size_t errorCount() const { return errorCount_; }
  size_t warningCount() const { return warningCount_; }
  const std::vector<Diagnostic>& all() const { return items_; }
  /// Orders diagnostics by file, line and column (stable for equal positions).
  void sort();

 private:
  static uint64_t lineKey(SourceLoc loc) { return (uint64_t(loc.file) << 32) | loc.line; }
  std::vector<Diagnostic> items_;
  /// The lines with an error ((file << 32) | line), each with the index of its first error.
  std::unordered_map<uint64_t, size_t> errorLines_;
  size_t errorCount_ = 0;
  size_t warningCount_ = 0;
  bool capped_ = false;
  Diagnostic dropped_;  ///< what add() returns for a diagnostic past the cap
};

const char* severityName(Severity s);

/// The columns a diagnostic underlines on its line: [first, last], 1-based. With `end` unset,
/// the word at loc (a name, a number, a string literal) or one character.
std::pair<uint32_t, uint32_t> diagnosticColumns(const SourceSet& sources, const Diagnostic& d);

struct DiagnosticStyle {
  bool color = false;  ///< ANSI colours as gcc uses them (bold location, red error, ...)
  bool brief = false;  ///< the heading line only: no include chain, source quote or notes
};

/// The text form: "[In file included from F:L:\n]file:line:col: error: message [code]\n", then
/// the line in a gutter with the range underlined and any fix-it, then the attached notes. No
/// source part when loc has no line; no location when it has no file either.
std::string formatDiagnostic(const SourceSet& sources, const Diagnostic& d,
                             const DiagnosticStyle& style = {});

}  // namespace rb
