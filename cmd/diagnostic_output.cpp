#include "diagnostic_output.h"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>

namespace rb::cli {

using nlohmann::json;

namespace {

struct Rule {
  const char* id;
  const char* description;
};

// Every rule code rb reports; docs/diagnostics.md explains each (a test keeps them in step).
constexpr Rule kRules[] = {
    {"rb-unreadable-file", "A program file could not be read."},
    {"rb-binary-input", "The file is binary data, not program text."},
    {"rb-unexpected-character", "A character that is not part of RobotBASIC."},
    {"rb-unterminated-comment", "A /* comment that never closes."},
    {"rb-unterminated-string", "A string without its closing quote on the same line."},
    {"rb-number-too-large", "A hexadecimal or binary literal that does not fit in 64 bits."},
    {"rb-syntax", "The line does not follow RobotBASIC's grammar."},
    {"rb-unknown-directive", "A # line other than #include."},
    {"rb-nesting-too-deep", "An expression nested more than 200 levels deep."},
    {"rb-block-in-line-if", "A block statement (for, while, ...) inside a single-line if."},
    {"rb-unknown-command", "A statement that is neither a command, a sub nor an assignment."},
    {"rb-unknown-function", "A call of a function that is neither built in nor a sub."},
    {"rb-misplaced-builtin", "A built-in's name where it cannot stand (assigned, used as a label, ...)."},
    {"rb-duplicate-label", "Two labels with the same name."},
    {"rb-duplicate-sub", "Two subs with the same name."},
    {"rb-duplicate-parameter", "A sub parameter named twice."},
    {"rb-label-is-sub", "A label with the name of a sub."},
    {"rb-sub-as-label", "goto or gosub to a sub (subs are called with call)."},
    {"rb-unmatched-block", "A block closer (next, wend, endif, ...) that does not match the open block."},
    {"rb-unclosed-block", "A loop or sub that is never closed."},
    {"rb-outside-loop", "break or continue outside a loop."},
    {"rb-undefined-label", "goto or gosub to a label that does not exist."},
    {"rb-too-many-arguments", "More than 65535 items in one statement."},
    {"rb-too-many-indices", "An array index with more than 64 dimensions."},
    {"rb-program-too-large", "More than 67,108,864 variables, constants or temporaries in one place."},
    {"rb-argument-count", "A built-in or sub called with the wrong number of arguments."},
    {"rb-output-argument", "A built-in's output argument that is not a variable."},
    {"rb-reference-argument", "A by-reference (&) sub argument that is not a variable."},
    {"rb-return-outside-sub", "return with a value outside a sub."},
    {"rb-include-depth", "#include nested more than 32 files deep."},
    {"rb-include-not-found", "An #include file that does not exist."},
    {"rb-include-refused", "An #include file outside the program's folder and the library folders."},
    {"rb-too-many-errors", "More than 10,000 errors: the rest of the program is not checked."},
    {"rb-include-unreadable", "An #include file that exists but cannot be read."},
    {"rb-unclosed-if", "An if without endif: the block runs to the end of the file or sub."},
    {"rb-unassigned-variable", "A variable that is read but never assigned."},
    {"rb-endless-loop", "A while or repeat loop whose condition nothing in the loop changes."},
    {"rb-robot-not-placed", "A robot statement or sensor that runs before rLocate places the robot."},
    {"rb-jump-into-sub", "goto or gosub to a label inside a sub, from outside that sub."},
    {"rb-unused-sub", "A sub that is never called."},
    {"rb-unused-label", "A label that no goto or gosub jumps to."},
    {"rb-rb9-unsupported", "A function the RB-9 robot has nothing behind (rb check --target rb9)."},
    {"rb-rb9-long-move", "A move longer than the RB-9 makes in one command (rb check --target rb9)."},
    {"rb-runtime-error", "The program stopped with an error while running."},
    {"rb-robot-crash", "The robot ran into something while the program ran."},
    {"rb-limit", "The run was stopped by --max-steps or --timeout."},
};

/// gcc's location object: file, line, 1-based display and byte columns.
json position(const std::string& file, uint32_t line, uint32_t col) {
  return json{{"file", file}, {"line", line}, {"display-column", col}, {"byte-column", col},
              {"column", col}};
}

std::string fileOf(const SourceSet& sources, const SourceLoc& loc) {
  return loc.file < sources.size() ? sources.file(loc.file).name() : std::string();
}

const char* sarifLevel(Severity s) {
  switch (s) {
    case Severity::Error: return "error";
    case Severity::Warning: return "warning";
    case Severity::Note: return "note";
  }
  return "error";
}

/// A SARIF artifact URI: a relative path as it is (relative to where rb ran, as code scanning
/// expects), an absolute one as a file: URI, spaces and % escaped.
std::string sarifUri(const std::string& path) {
  std::string out = !path.empty() && path[0] == '/' ? "file://" : "";
  for (char c : path) {
    if (c == ' ') out += "%20";
    else if (c == '%') out += "%25";
    else out += c;
  }
  return out;
}

/// GitHub workflow commands: % \r \n escaped in the message, also , and : in properties.
std::string githubEscape(const std::string& s, bool property) {
  std::string out;
  for (char c : s) {
    if (c == '%') out += "%25";
    else if (c == '\r') out += "%0D";
    else if (c == '\n') out += "%0A";
    else if (property && c == ':') out += "%3A";
    else if (property && c == ',') out += "%2C";
    else out += c;
  }
  return out;
}

}  // namespace

const char* ruleDescription(const std::string& code) {
  for (const Rule& r : kRules)
    if (code == r.id) return r.description;
  return "";
}

DiagFormat parseDiagFormat(const std::string& name) {
  if (name == "json") return DiagFormat::Json;
  if (name == "sarif") return DiagFormat::Sarif;
  if (name == "github") return DiagFormat::Github;
  return DiagFormat::Text;
}

bool useColor(const std::string& mode, std::FILE* out) {
  if (mode == "always") return true;
  if (mode == "never") return false;
  const char* noColor = std::getenv("NO_COLOR");
  if (noColor && *noColor) return false;
  const char* term = std::getenv("TERM");
  if (term && std::string(term) == "dumb") return false;
  return isatty(fileno(out)) == 1;
}

std::string countSummary(size_t errors, size_t warnings) {
  std::string out;
  if (errors) out = std::to_string(errors) + (errors == 1 ? " error" : " errors");
  if (warnings) {
    if (!out.empty()) out += ", ";
    out += std::to_string(warnings) + (warnings == 1 ? " warning" : " warnings");
  }
  return out;
}

json diagnosticToGccJson(const SourceSet& sources, const Diagnostic& d) {
  json j;
  j["kind"] = severityName(d.severity);
  j["message"] = d.message;
  if (!d.code.empty()) j["option"] = d.code;
  j["locations"] = json::array();
  if (d.loc.valid() && d.loc.file < sources.size()) {
    std::string file = fileOf(sources, d.loc);
    auto [first, last] = diagnosticColumns(sources, d);
    json loc;
    loc["caret"] = position(file, d.loc.line, first);
    if (last > first) {
      loc["start"] = position(file, d.loc.line, first);
      loc["finish"] = position(file, d.loc.line, last);
    }
    j["locations"].push_back(loc);
  } else if (d.loc.file < sources.size() && d.severity != Severity::Note) {
    j["locations"].push_back(json{{"caret", json{{"file", fileOf(sources, d.loc)}}}});
  }
  json children = json::array();
  for (const Diagnostic& n : d.notes) children.push_back(diagnosticToGccJson(sources, n));
  j["children"] = children;
  if (!d.fixits.empty()) {
    json fixits = json::array();
    for (const FixIt& f : d.fixits) {
      std::string file = fileOf(sources, f.start);
      fixits.push_back(json{{"start", position(file, f.start.line, f.start.col)},
                            {"next", position(file, f.end.line, f.end.col)},
                            {"string", f.replacement}});
    }
    j["fixits"] = fixits;
  }
  j["column-origin"] = 1;
  j["escape-source"] = false;
  return j;
}

DiagnosticReport::DiagnosticReport(std::FILE* out, DiagOutputOptions options)
    : out_(out), opts_(options) {}

DiagnosticReport::~DiagnosticReport() = default;

void DiagnosticReport::add(const SourceSet& sources, const DiagnosticList& diags, bool errorsOnly) {
  // Load-time notes are entries of their own: attach them to the diagnostic before them.
  std::vector<Diagnostic> grouped;
  bool lastShown = false;
  for (const Diagnostic& d : diags.all()) {
    if (d.severity == Severity::Note) {
      if (lastShown && !grouped.empty()) grouped.back().notes.push_back(d);
      continue;
    }
    lastShown = !errorsOnly || d.severity == Severity::Error;
    if (lastShown) grouped.push_back(d);
  }
  for (const Diagnostic& d : grouped) add(sources, d);
}

void DiagnosticReport::add(const SourceSet& sources, const Diagnostic& d) {
  one(&sources, d, fileOf(sources, d.loc));
}

void DiagnosticReport::addUnreadable(const std::string& file, const std::string& why) {
  SourceSet sources;
  sources.add(file, "");
  Diagnostic d{Severity::Error, SourceLoc{0, 0, 0}, "cannot read '" + file + "': " + why,
               "rb-unreadable-file"};
  one(&sources, d, file);
}

void DiagnosticReport::one(const SourceSet* sources, const Diagnostic& d, const std::string& fileName) {
  if (d.severity == Severity::Error) ++errors_;
  if (d.severity == Severity::Warning) ++warnings_;
  // --max-errors holds for every format: what follows the last error shown is counted, not shown.
  if (truncated_) return;
  if (opts_.maxErrors && d.severity == Severity::Error && shownErrors_ == opts_.maxErrors) {
    truncated_ = true;
    return;
  }
  if (d.severity == Severity::Error) ++shownErrors_;
  switch (opts_.format) {
    case DiagFormat::Text: {
      std::string text = formatDiagnostic(*sources, d, DiagnosticStyle{opts_.color});
      std::fwrite(text.data(), 1, text.size(), out_);
      return;
    }
    case DiagFormat::Json:
      items_.push_back(diagnosticToGccJson(*sources, d));
      return;
    case DiagFormat::Github: {
      // ::error file=F,line=L,col=C,endColumn=E,title=RULE::message
      const char* cmd = d.severity == Severity::Error ? "error" : d.severity == Severity::Warning ? "warning" : "notice";
      std::string line = std::string("::") + cmd + " file=" + githubEscape(fileName, true);
      if (d.loc.valid()) {
        auto [first, last] = diagnosticColumns(*sources, d);
        line += ",line=" + std::to_string(d.loc.line) + ",col=" + std::to_string(first);
        if (last > first) line += ",endColumn=" + std::to_string(last + 1);
      }
      if (!d.code.empty()) line += ",title=" + githubEscape(d.code, true);
      std::string message = d.message;
      for (const Diagnostic& n : d.notes) {
        message += "\n";
        if (n.loc.valid()) message += "line " + std::to_string(n.loc.line) + ": ";
        message += n.message;
      }
      line += "::" + githubEscape(message, false) + "\n";
      std::fwrite(line.data(), 1, line.size(), out_);
      return;
    }
    case DiagFormat::Sarif: {
      json result;
      std::string rule = d.code.empty() ? "rb-runtime-error" : d.code;
      auto known = std::find(ruleIds_.begin(), ruleIds_.end(), rule);
      size_t ruleIndex = static_cast<size_t>(known - ruleIds_.begin());
      if (known == ruleIds_.end()) {
        ruleIds_.push_back(rule);
        rules_.push_back(json{{"id", rule},
                              {"shortDescription", {{"text", ruleDescription(rule)}}},
                              {"help", {{"text", "See docs/diagnostics.md, section " + rule + "."}}}});
      }
      result["ruleId"] = rule;
      result["ruleIndex"] = ruleIndex;
      result["level"] = sarifLevel(d.severity);
      result["message"] = {{"text", d.message}};
      json physical;
      physical["artifactLocation"] = {{"uri", sarifUri(fileName)}};
      if (d.loc.valid()) {
        auto [first, last] = diagnosticColumns(*sources, d);
        physical["region"] = {{"startLine", d.loc.line}, {"startColumn", first},
                              {"endLine", d.loc.line}, {"endColumn", last + 1}};
      }
      result["locations"] = json::array({json{{"physicalLocation", physical}}});
      json related = json::array();
      int id = 0;
      for (const Diagnostic& n : d.notes) {
        if (!n.loc.valid()) {
          result["message"]["text"] = d.message + " (" + n.message + ")";
          continue;
        }
        related.push_back(json{{"id", id++},
                               {"message", {{"text", n.message}}},
                               {"physicalLocation",
                                {{"artifactLocation", {{"uri", sarifUri(fileOf(*sources, n.loc))}}},
                                 {"region", {{"startLine", n.loc.line}, {"startColumn", n.loc.col}}}}}});
      }
      if (!related.empty()) result["relatedLocations"] = related;
      if (!d.fixits.empty()) {
        json fixes = json::array();
        for (const FixIt& f : d.fixits) {
          fixes.push_back(json{
              {"description", {{"text", "replace with '" + f.replacement + "'"}}},
              {"artifactChanges",
               json::array({json{{"artifactLocation", {{"uri", sarifUri(fileOf(*sources, f.start))}}},
                                 {"replacements",
                                  json::array({json{{"deletedRegion",
                                                     {{"startLine", f.start.line}, {"startColumn", f.start.col},
                                                      {"endLine", f.end.line}, {"endColumn", f.end.col}}},
                                                    {"insertedContent", {{"text", f.replacement}}}}})}}})}});
        }
        result["fixes"] = fixes;
      }
      items_.push_back(result);
      return;
    }
  }
}

void DiagnosticReport::finish() {
  std::string text;
  const std::string stopped = truncated_ ? "stopped after " + std::to_string(opts_.maxErrors) +
                                               " errors (--max-errors; --max-errors 0 shows them all)"
                                         : "";
  switch (opts_.format) {
    case DiagFormat::Text:
      if (truncated_) text += stopped + "\n";
      if (opts_.summary && (errors_ || warnings_)) text += countSummary(errors_, warnings_) + "\n";
      break;
    case DiagFormat::Github:
      if (truncated_) text += "::notice title=rb check::" + githubEscape(stopped, false) + "\n";
      break;
    case DiagFormat::Json:
      // gcc's shape has no place for it but a diagnostic: a note without a location.
      if (truncated_)
        items_.push_back(json{{"kind", "note"}, {"message", stopped}, {"locations", json::array()},
                              {"children", json::array()}, {"column-origin", 1}, {"escape-source", false}});
      text = items_.dump(2) + "\n";
      break;
    case DiagFormat::Sarif: {
      json log;
      log["$schema"] = "https://json.schemastore.org/sarif-2.1.0.json";
      log["version"] = "2.1.0";
      json driver{{"name", "rb"}, {"rules", rules_}};
#ifdef RB_VERSION
      driver["version"] = RB_VERSION;
#endif
      json run{{"tool", {{"driver", driver}}}, {"results", items_}};
      if (truncated_)
        run["invocations"] = json::array({json{
            {"executionSuccessful", true},
            {"toolExecutionNotifications", json::array({json{{"level", "note"}, {"message", {{"text", stopped}}}}})}}});
      log["runs"] = json::array({run});
      text = log.dump(2) + "\n";
      break;
    }
  }
  std::fwrite(text.data(), 1, text.size(), out_);
}

}  // namespace rb::cli
