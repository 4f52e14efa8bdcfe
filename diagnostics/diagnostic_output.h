#pragma once
// Writing diagnostics for people and for machines: text (gcc-style, with colour, a limit on
// errors and a summary line), JSON in the shape of gcc's -fdiagnostics-format=json, SARIF 2.1.0
// (GitHub code scanning) and GitHub Actions workflow commands. The text form itself is core's
// one formatter (base/diagnostic.h); this file only chooses and counts.

#include <cstdio>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "base/diagnostic.h"

namespace rb::diagnostics {

enum class DiagFormat { Text, Json, Sarif, Github };

/// "text", "json", "sarif", "github".
DiagFormat parseDiagFormat(const std::string& name);

/// --color=auto|always|never: auto means colour when `out` is a terminal and NO_COLOR is unset
/// or empty (https://no-color.org); always/never override NO_COLOR.
bool useColor(const std::string& mode, std::FILE* out);

struct DiagOutputOptions {
  DiagFormat format = DiagFormat::Text;
  bool color = false;
  size_t maxErrors = 20;  ///< every format: stop showing diagnostics after this many errors (0: no limit)
  bool summary = true;    ///< text: end with "2 errors, 1 warning"
};

/// Diagnostics of one or more programs, written as they come (text, github) or at finish()
/// (json, sarif: one document).
class DiagnosticReport {
 public:
  DiagnosticReport(std::FILE* out, DiagOutputOptions options);
  ~DiagnosticReport();

  /// Adds a program's diagnostics (errors, warnings and their notes); with `errorsOnly`, only
  /// errors and their notes.
  void add(const SourceSet& sources, const DiagnosticList& diags, bool errorsOnly = false);
  /// Adds one diagnostic (a runtime error, with its attached notes).
  void add(const SourceSet& sources, const Diagnostic& d);
  /// A file that could not be read at all.
  void addUnreadable(const std::string& file, const std::string& why);
  /// Writes what is still owed: the summary line, or the JSON/SARIF document.
  void finish();

  size_t errors() const { return errors_; }
  size_t warnings() const { return warnings_; }

 private:
  void one(const SourceSet* sources, const Diagnostic& d, const std::string& fileName);
  std::FILE* out_;
  DiagOutputOptions opts_;
  size_t errors_ = 0, warnings_ = 0;
  size_t shownErrors_ = 0;
  bool truncated_ = false;
  nlohmann::json items_ = nlohmann::json::array();
  nlohmann::json rules_ = nlohmann::json::array();
  std::vector<std::string> ruleIds_;
};

/// "2 errors, 1 warning" ("" when there are none).
std::string countSummary(size_t errors, size_t warnings);

/// One diagnostic in gcc's JSON shape: kind, message, option (the rule code), locations with
/// caret/start/finish, children (notes), fixits.
nlohmann::json diagnosticToGccJson(const SourceSet& sources, const Diagnostic& d);

/// The one-line summary of every rule: ruleId -> short description (docs/diagnostics.md has the
/// long form).
const char* ruleDescription(const std::string& code);

}  // namespace rb::diagnostics
