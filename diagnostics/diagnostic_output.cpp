#include "diagnostic_output.h"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>

#include "base/columns.h"
#include "base/rules.h"

namespace rb::diagnostics {

using nlohmann::json;

namespace {

/// The text of a line of a program ("" when there is none).
std::string_view lineOf(const SourceSet& sources, uint32_t file, uint32_t line) {
  return file < sources.size() ? sources.file(file).lineText(line) : std::string_view();
}

/// gcc's location object: file, line, and the column three ways: "byte-column" in bytes,
/// "display-column" as a terminal shows it (tabs to 8, wide characters 2), and "column" in
/// gcc's default unit, the display column (-fdiagnostics-column-unit=display).
json position(const SourceSet& sources, uint32_t file, uint32_t line, uint32_t byteCol) {
  uint32_t display = displayColumn(lineOf(sources, file, line), byteCol);
  return json{{"file", file < sources.size() ? sources.file(file).name() : std::string()},
              {"line", line}, {"display-column", display}, {"byte-column", byteCol}, {"column", display}};
}

/// The byte column where the character holding byte column `col` starts (an inclusive end
/// may name the last byte of a multi-byte character).
uint32_t charStart(std::string_view line, uint32_t col) {
  while (col > 1 && col - 1 < line.size() && (static_cast<unsigned char>(line[col - 1]) & 0xC0) == 0x80) --col;
  return col;
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

/// A SARIF artifact URI (RFC 3986): a relative path stays relative (to where rb ran, as code
/// scanning expects), an absolute one becomes a file: URI; every byte but the unreserved
/// characters (letters, digits, - . _ ~) and '/' is percent-encoded, so a name with a space,
/// '#', '%', '?', ':' or a non-ASCII letter (its UTF-8 bytes) is still one valid URI path.
std::string sarifUri(const std::string& path) {
  static const char kHex[] = "0123456789ABCDEF";
  std::string out = !path.empty() && path[0] == '/' ? "file://" : "";
  for (char c : path) {
    unsigned char b = static_cast<unsigned char>(c);
    bool unreserved = (b >= 'a' && b <= 'z') || (b >= 'A' && b <= 'Z') || (b >= '0' && b <= '9') || c == '-' ||
                      c == '.' || c == '_' || c == '~';
    if (unreserved || c == '/') out += c;
    else {
      out += '%';
      out += kHex[b >> 4];
      out += kHex[b & 0xF];
    }
  }
  return out;
}

/// A rule's reportingDescriptor: its summary and full description, its level when reported,
/// and where it is documented (GitHub code scanning shows all of them).
json sarifRule(const std::string& id) {
  json r{{"id", id}};
  const Rule* rule = findRule(id);
  if (!rule) {
    r["shortDescription"] = {{"text", id}};
    return r;
  }
  r["shortDescription"] = {{"text", std::string(rule->summary)}};
  r["fullDescription"] = {{"text", ruleText(*rule)}, {"markdown", ruleMarkdown(*rule)}};
  r["defaultConfiguration"] = {{"level", sarifLevel(rule->severity)}};
  r["helpUri"] = ruleUrl(id);
  r["help"] = {{"text", ruleText(*rule) + " See " + ruleUrl(id)},
               {"markdown", ruleMarkdown(*rule) + " [More](" + ruleUrl(id) + ")"}};
  return r;
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
  const Rule* r = findRule(code);
  return r ? r->summary.data() : "";
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
    auto [first, last] = diagnosticColumns(sources, d);
    std::string_view text = lineOf(sources, d.loc.file, d.loc.line);
    json loc;
    loc["caret"] = position(sources, d.loc.file, d.loc.line, first);
    if (last > first) {
      loc["start"] = position(sources, d.loc.file, d.loc.line, first);
      loc["finish"] = position(sources, d.loc.file, d.loc.line, charStart(text, last));
    }
    j["locations"].push_back(loc);
  } else if (d.loc.file < sources.size() && d.severity != Severity::Note && d.code != "rb-unreadable-file") {
    // A file-level error (binary data): the file without a line. A file that could not be
    // read has no location, as gcc reports one (its message names the file).
    j["locations"].push_back(json{{"caret", json{{"file", fileOf(sources, d.loc)}}}});
  }
  json children = json::array();
  for (const Diagnostic& n : d.notes) children.push_back(diagnosticToGccJson(sources, n));
  j["children"] = children;
  if (!d.fixits.empty()) {
    json fixits = json::array();
    for (const FixIt& f : d.fixits) {
      fixits.push_back(json{{"start", position(sources, f.start.file, f.start.line, f.start.col)},
                            {"next", position(sources, f.end.file, f.end.line, f.end.col)},
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
        // Columns in UTF-16 code units, as GitHub's pages index a line's text.
        auto [first, last] = diagnosticColumns(*sources, d);
        std::string_view text = lineOf(*sources, d.loc.file, d.loc.line);
        line += ",line=" + std::to_string(d.loc.line) + ",col=" + std::to_string(utf16Column(text, first));
        if (last > first) line += ",endColumn=" + std::to_string(utf16Column(text, last + 1));
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
        rules_.push_back(sarifRule(rule));
      }
      result["ruleId"] = rule;
      result["ruleIndex"] = ruleIndex;
      result["level"] = sarifLevel(d.severity);
      result["message"] = {{"text", d.message}};
      json physical;
      physical["artifactLocation"] = {{"uri", sarifUri(fileName)}};
      if (d.loc.valid()) {
        auto [first, last] = diagnosticColumns(*sources, d);
        std::string_view text = lineOf(*sources, d.loc.file, d.loc.line);
        physical["region"] = {{"startLine", d.loc.line}, {"startColumn", utf16Column(text, first)},
                              {"endLine", d.loc.line}, {"endColumn", utf16Column(text, last + 1)}};
      } else {
        // A finding about the whole file (binary data, a file that cannot be read): its lines,
        // the minimum a whole-file region gives (the Multitool's SARIF2017).
        uint32_t lines = d.loc.file < sources->size() ? sources->file(d.loc.file).lineCount() : 1;
        physical["region"] = {{"startLine", 1}, {"endLine", std::max<uint32_t>(lines, 1)}};
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
                                 {"region", {{"startLine", n.loc.line},
                                             {"startColumn", utf16Column(lineOf(*sources, n.loc.file, n.loc.line), n.loc.col)}}}}}});
      }
      if (!related.empty()) result["relatedLocations"] = related;
      if (!d.fixits.empty()) {
        json fixes = json::array();
        for (const FixIt& f : d.fixits) {
          fixes.push_back(json{
              {"description", {{"text", (f.start == f.end ? "insert '" : "replace with '") + f.replacement + "'"}}},
              {"artifactChanges",
               json::array({json{{"artifactLocation", {{"uri", sarifUri(fileOf(*sources, f.start))}}},
                                 {"replacements",
                                  json::array({json{{"deletedRegion",
                                                     {{"startLine", f.start.line},
                                                      {"startColumn", utf16Column(lineOf(*sources, f.start.file, f.start.line), f.start.col)},
                                                      {"endLine", f.end.line},
                                                      {"endColumn", utf16Column(lineOf(*sources, f.end.file, f.end.line), f.end.col)}}},
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
      json driver{{"name", "rb"}, {"informationUri", std::string(docsBaseUrl()) + "diagnostics.md"}, {"rules", rules_}};
#ifdef RB_VERSION
      driver["version"] = RB_VERSION;
#endif
      // Columns count UTF-16 code units (SARIF 2.1.0 3.14.27), as GitHub code scanning expects.
      json run{{"tool", {{"driver", driver}}}, {"columnKind", "utf16CodeUnits"}, {"results", items_}};
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

}  // namespace rb::diagnostics
