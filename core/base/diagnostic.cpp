#include "base/diagnostic.h"

#include "base/columns.h"

#include <algorithm>
#include <cctype>
#include <cstdio>

namespace rb {

Diagnostic& DiagnosticList::error(SourceLoc loc, std::string message, std::string code) {
  return add({Severity::Error, loc, std::move(message), std::move(code)});
}
Diagnostic& DiagnosticList::warning(SourceLoc loc, std::string message, std::string code) {
  return add({Severity::Warning, loc, std::move(message), std::move(code)});
}
Diagnostic& DiagnosticList::note(SourceLoc loc, std::string message) {
  return add({Severity::Note, loc, std::move(message) });
}

Diagnostic& DiagnosticList::add(Diagnostic d) {
  if (capped_) {
    dropped_ = std::move(d);
    return dropped_;
  }
  if (d.severity == Severity::Error && errorCount_ >= kMaxErrors) {
    capped_ = true;
    ++errorCount_;
    items_.push_back({Severity::Error, d.loc,
                      "too many errors: rb stops checking after " + std::to_string(kMaxErrors) +
                          "; fix the first ones and check again",
                      "rb-too-many-errors"});
    dropped_ = std::move(d);
    return dropped_;
  }
  if (d.severity == Severity::Error) {
    ++errorCount_;
    errorLines_.try_emplace(lineKey(d.loc), items_.size());
  }
  if (d.severity == Severity::Warning) ++warningCount_;
  items_.push_back(std::move(d));
  return items_.back();
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
  errorLines_.clear();
  for (size_t i = 0; i < items_.size(); ++i)
    if (items_[i].severity == Severity::Error) errorLines_.try_emplace(lineKey(items_[i].loc), i);
}

Diagnostic* DiagnosticList::firstErrorAt(SourceLoc loc) {
  auto it = errorLines_.find(lineKey(loc));
  if (it == errorLines_.end() || it->second >= items_.size()) return nullptr;
  Diagnostic& d = items_[it->second];
  return d.loc == loc ? &d : nullptr;
}

const char* severityName(Severity s) {
  switch (s) {
    case Severity::Error: return "error";
    case Severity::Warning: return "warning";
    case Severity::Note: return "note";
  }
  return "error";
}

namespace {

bool isWordChar(unsigned char c) { return std::isalnum(c) || c == '_' || c == '$' || c >= 0x80; }

/// The last column of the token that starts at `col` (1-based) in `line`.
uint32_t wordEnd(std::string_view line, uint32_t col) {
  if (col == 0 || col > line.size()) return col;
  size_t i = col - 1;
  unsigned char c = static_cast<unsigned char>(line[i]);
  if (c == '"') {
    size_t close = line.find('"', i + 1);
    return static_cast<uint32_t>(close == std::string_view::npos ? line.size() : close + 1);
  }
  if (std::isdigit(c) || (c == '.' && i + 1 < line.size() && std::isdigit(static_cast<unsigned char>(line[i + 1])))) {
    size_t j = i;
    while (j < line.size() && (std::isalnum(static_cast<unsigned char>(line[j])) || line[j] == '.')) ++j;
    return static_cast<uint32_t>(j);
  }
  if (isWordChar(c)) {
    size_t j = i;
    while (j < line.size() && isWordChar(static_cast<unsigned char>(line[j]))) ++j;
    return static_cast<uint32_t>(j);
  }
  return col;
}

const char* severityColor(Severity s) {
  switch (s) {
    case Severity::Error: return "\033[1;31m";
    case Severity::Warning: return "\033[1;35m";
    case Severity::Note: return "\033[1;36m";
  }
  return "";
}

struct Painter {
  bool on;
  std::string paint(std::string_view text, const char* color) const {
    std::string out;
    if (on) out += color;
    out += text;
    if (on) out += "\033[m";
    return out;
  }
};

/// Spaces (or the tab at the same place, so terminals line them up) under line[0, col-1): as
/// many as each character takes on a terminal (a wide character two, a combining mark none).
std::string padTo(std::string_view line, uint32_t col) {
  std::string out;
  uint32_t i = 1;
  while (i < col) {
    if (i - 1 >= line.size()) {
      out += ' ';
      ++i;
      continue;
    }
    if (line[i - 1] == '\t') {
      out += '\t';
      ++i;
      continue;
    }
    size_t len = 1;
    out.append(static_cast<size_t>(displayWidthAt(line, i - 1, len)), ' ');
    i += static_cast<uint32_t>(len);
  }
  return out;
}

void formatOne(const SourceSet& sources, const Diagnostic& d, const Painter& p, bool brief, std::string& out) {
  // A note without a line (a built-in's usage) names no file either.
  bool named = d.loc.file < sources.size() && (d.loc.valid() || d.severity != Severity::Note);
  bool located = named && d.loc.valid();
  if (named && d.severity != Severity::Note && !brief) {
    // The chain of #include lines that brought the file in, outermost last (as gcc prints it).
    SourceLoc from = sources.file(d.loc.file).includedFrom();
    bool first = true;
    for (int guard = 0; from.valid() && from.file < sources.size() && guard < 64; ++guard) {
      out += first ? "In file included from " : "                 from ";
      out += sources.file(from.file).name();
      out += ':';
      out += std::to_string(from.line);
      first = false;
      from = sources.file(from.file).includedFrom();
      out += from.valid() ? ",\n" : ":\n";
    }
  }
  if (named) {
    std::string where = sources.file(d.loc.file).name();
    if (located) {
      where += ':';
      where += std::to_string(d.loc.line);
      where += ':';
      where += std::to_string(d.loc.col);
    }
    where += ':';
    out += p.paint(where, "\033[1m");
    out += ' ';
  }
  std::string label = severityName(d.severity);
  label += ':';
  out += p.paint(label, severityColor(d.severity));
  out += ' ';
  out += d.message;
  if (!d.code.empty()) {
    out += " [";
    out += p.paint(d.code, severityColor(d.severity));
    out += ']';
  }
  out += '\n';
  if (brief) return;
  if (located) {
    std::string_view line = sources.file(d.loc.file).lineText(d.loc.line);
    std::string number = std::to_string(d.loc.line);
    size_t width = std::max<size_t>(5, number.size() + 1);
    std::string gutter(width - number.size(), ' ');
    std::string blank(width, ' ');
    out += gutter;
    out += number;
    out += " | ";
    out += line;
    out += '\n';
    auto [first, last] = diagnosticColumns(sources, d);
    // The caret, then one mark per terminal column of the rest of the range (a wide character
    // two, as the line above shows it).
    std::string underline = "^";
    if (last > first) {
      uint32_t end = std::min<uint32_t>(last + 1, static_cast<uint32_t>(line.size()) + 1);
      uint32_t firstEnd = first + 1;
      while (firstEnd - 1 < line.size() && (static_cast<unsigned char>(line[firstEnd - 1]) & 0xC0) == 0x80) ++firstEnd;
      while (end - 1 < line.size() && end > 1 && (static_cast<unsigned char>(line[end - 1]) & 0xC0) == 0x80) ++end;
      uint32_t firstWidth = displayColumn(line, firstEnd) - displayColumn(line, first);
      underline.append(firstWidth > 1 ? firstWidth - 1 : 0, '~');
      if (end > firstEnd) underline.append(displayColumn(line, end) - displayColumn(line, firstEnd), '~');
    }
    out += blank;
    out += " | ";
    out += padTo(line, first);
    out += p.paint(underline, "\033[1;32m");
    out += '\n';
    for (const FixIt& f : d.fixits) {
      // The new text at its column; spaces after it cannot be seen (an insertion's " + ").
      std::string_view shown = f.replacement;
      while (!shown.empty() && shown.back() == ' ') shown.remove_suffix(1);
      if (f.start.file != d.loc.file || f.start.line != d.loc.line || shown.empty()) continue;
      out += blank;
      out += " | ";
      out += padTo(line, f.start.col);
      out += p.paint(shown, "\033[1;32m");
      out += '\n';
    }
  }
  for (const Diagnostic& n : d.notes) formatOne(sources, n, p, false, out);
}

}  // namespace

std::pair<uint32_t, uint32_t> diagnosticColumns(const SourceSet& sources, const Diagnostic& d) {
  uint32_t first = d.loc.col == 0 ? 1 : d.loc.col;
  if (!d.loc.valid() || d.loc.file >= sources.size()) return {first, first};
  std::string_view line = sources.file(d.loc.file).lineText(d.loc.line);
  uint32_t last = first;
  if (d.end.valid() && d.end.file == d.loc.file) {
    if (d.end.line > d.loc.line) last = static_cast<uint32_t>(std::max<size_t>(line.size(), first));
    else if (d.end.line == d.loc.line && d.end.col >= first) last = d.end.col;
  } else {
    last = std::max(first, wordEnd(line, first));
  }
  return {first, last};
}

std::string formatDiagnostic(const SourceSet& sources, const Diagnostic& d, const DiagnosticStyle& style) {
  std::string out;
  formatOne(sources, d, Painter{style.color}, style.brief, out);
  return out;
}

}  // namespace rb
