#pragma once
// The one diagnostic type and its formatter. Load-time errors, warnings from `rb check` and
// runtime errors are all Diagnostics, printed gcc-style:
//   file:line:col: error: message
//    source line
//        ^

#include <string>
#include <unordered_set>
#include <vector>

#include "base/source.h"

namespace rb {

enum class Severity { Error, Warning, Note };

struct Diagnostic {
  Severity severity = Severity::Error;
  SourceLoc loc;
  std::string message;
};

/// A list of diagnostics that remembers whether any of them is an error.
class DiagnosticList {
 public:
  void error(SourceLoc loc, std::string message);
  void warning(SourceLoc loc, std::string message);
  void note(SourceLoc loc, std::string message);
  void add(Diagnostic d);

  bool hasErrors() const { return errorCount_ > 0; }
  /// True when an error was already reported on that line (so a parser can stay quiet about
  /// the consequences of a lexical error).
  bool hasErrorOnLine(uint32_t file, uint32_t line) const {
    return errorLines_.count((uint64_t(file) << 32) | line) > 0;
  }
  size_t errorCount() const { return errorCount_; }
  size_t warningCount() const { return warningCount_; }
  const std::vector<Diagnostic>& all() const { return items_; }
  /// Orders diagnostics by file, line and column (stable for equal positions).
  void sort();

 private:
  std::vector<Diagnostic> items_;
  std::unordered_set<uint64_t> errorLines_;
  size_t errorCount_ = 0;
  size_t warningCount_ = 0;
};

const char* severityName(Severity s);

/// "file:line:col: error: message\n source line\n     ^\n" (no source part when loc is invalid).
std::string formatDiagnostic(const SourceSet& sources, const Diagnostic& d);

/// One JSON object on one line: {"file":..,"line":..,"column":..,"severity":..,"message":..}.
std::string formatDiagnosticJson(const SourceSet& sources, const Diagnostic& d);

/// Escapes a string for a JSON string literal (without the quotes).
std::string jsonEscape(std::string_view s);

}  // namespace rb
