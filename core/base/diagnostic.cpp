#include "base/diagnostic.h"

#include <algorithm>

namespace rb {

void DiagnosticList::error(SourceLoc loc, std::string message) {
  add({Severity::Error, loc, std::move(message)});
}
void DiagnosticList::warning(SourceLoc loc, std::string message) {
  add({Severity::Warning, loc, std::move(message)});
}
void DiagnosticList::note(SourceLoc loc, std::string message) {
  add({Severity::Note, loc, std::move(message)});
}

void DiagnosticList::add(Diagnostic d) {
  if (d.severity == Severity::Error) {
    ++errorCount_;
    errorLines_.insert((uint64_t(d.loc.file) << 32) | d.loc.line);
  }
  if (d.severity == Severity::Warning) ++warningCount_;
  items_.push_back(std::move(d));
}

void DiagnosticList::sort() {
  // Notes stay attached to the diagnostic before them: sort groups, not single items.
  std::vector<std::vector<Diagnostic>> groups;
  for (auto& d : items_) {
    if (d.severity == Severity::Note && !groups.empty()) {
      groups.back().push_back(std::move(d));
    } else {
      groups.push_back({std::move(d)});
    }
  }
  std::stable_sort(groups.begin(), groups.end(), [](const auto& a, const auto& b) {
    const SourceLoc& x = a.front().loc;
    const SourceLoc& y = b.front().loc;
    if (x.file != y.file) return x.file < y.file;
    if (x.line != y.line) return x.line < y.line;
    return x.col < y.col;
  });
  items_.clear();
  for (auto& g : groups)
    for (auto& d : g) items_.push_back(std::move(d));
}

const char* severityName(Severity s) {
  switch (s) {
    case Severity::Error: return "error";
    case Severity::Warning: return "warning";
    case Severity::Note: return "note";
  }
  return "error";
}

std::string formatDiagnostic(const SourceSet& sources, const Diagnostic& d) {
  std::string out;
  bool located = d.loc.valid() && d.loc.file < sources.size();
  if (located) {
    const SourceFile& f = sources.file(d.loc.file);
    out += f.name() + ":" + std::to_string(d.loc.line) + ":" + std::to_string(d.loc.col) + ": ";
  }
  out += severityName(d.severity);
  out += ": ";
  out += d.message;
  out += '\n';
  if (located) {
    std::string_view line = sources.file(d.loc.file).lineText(d.loc.line);
    out += ' ';
    out += line;
    out += '\n';
    // The caret sits under the column; tabs in the line are kept so terminals align it.
    out += ' ';
    for (uint32_t i = 1; i < d.loc.col && i - 1 < line.size(); ++i)
      out += line[i - 1] == '\t' ? '\t' : ' ';
    out += "^\n";
  }
  return out;
}

std::string jsonEscape(std::string_view s) {
  std::string out;
  for (unsigned char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (c < 0x20) {
          static const char* hex = "0123456789abcdef";
          out += "\\u00";
          out += hex[c >> 4];
          out += hex[c & 15];
        } else {
          out += static_cast<char>(c);
        }
    }
  }
  return out;
}

std::string formatDiagnosticJson(const SourceSet& sources, const Diagnostic& d) {
  std::string file = d.loc.file < sources.size() ? sources.file(d.loc.file).name() : "";
  return "{\"file\":\"" + jsonEscape(file) + "\",\"line\":" + std::to_string(d.loc.line) +
         ",\"column\":" + std::to_string(d.loc.col) + ",\"severity\":\"" +
         severityName(d.severity) + "\",\"message\":\"" + jsonEscape(d.message) + "\"}";
}

}  // namespace rb
