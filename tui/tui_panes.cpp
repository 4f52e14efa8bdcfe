#include "tui_panes.h"

#include <algorithm>

namespace rb::tui {

namespace {

/// Text as one terminal line: tabs become spaces to the next multiple of 4, other control
/// characters '?'.
std::string oneLine(std::string_view s) {
  std::string out;
  for (char c : s) {
    if (c == '\t') {
      do out += ' ';
      while (out.size() % 4 != 0);
    } else if (static_cast<unsigned char>(c) < 32 || c == 127) {
      out += '?';
    } else {
      out += c;
    }
  }
  return out;
}

void cut(std::string& s, size_t width) {
  if (s.size() > width) {
    if (width >= 3) {
      s.resize(width - 3);
      s.append(3, '.');
    } else {
      s.resize(width);
    }
  }
}

}  // namespace

std::string paneLineText(std::string_view text, uint32_t number, int numberWidth, char marker,
                         int width) {
  std::string n = std::to_string(number);
  std::string out(1, marker);
  out.append(static_cast<size_t>(std::max(0, numberWidth - static_cast<int>(n.size()))), ' ');
  out += n;
  out += ' ';
  out += oneLine(text);
  if (static_cast<int>(out.size()) > width) out.resize(static_cast<size_t>(std::max(width, 0)));
  return out;
}

std::string valueText(const Value& v, size_t width) {
  std::string out;
  switch (v.type()) {
    case VType::Undef: out.assign(1, '-'); break;
    case VType::Int:
    case VType::Num: out = formatValue(v); break;
    case VType::Str:
      out = '"';
      out += oneLine(v.str());
      out += '"';
      break;
    case VType::Arr: {
      const ArrObj& a = v.arr();
      out.assign(1, '[');
      for (size_t i = 0; i < a.dims.size(); ++i) {
        if (i) out += ',';
        out += std::to_string(a.dims[i]);
      }
      out += "] ";
      // The first elements, as many as fit.
      for (size_t i = 0; i < a.items.size(); ++i) {
        if (width && out.size() > width) break;
        if (i) out += ", ";
        out += valueText(a.items[i], 0);
      }
      break;
    }
  }
  if (width) cut(out, width);
  return out;
}

std::string outputCells(std::string_view line) {
  std::string out;
  out.reserve(line.size());
  for (char c : line) {
    if (c == '\t') {
      do out += ' ';
      while (out.size() % kOutputTab != 0);
    } else if (static_cast<unsigned char>(c) < 32 || c == 127) {
      out += '?';
    } else {
      out += c;
    }
  }
  return out;
}

std::vector<std::string> wrapRows(std::string_view line, int width) {
  std::string cells = outputCells(line);
  size_t w = static_cast<size_t>(std::max(width, 1));
  std::vector<std::string> rows;
  for (size_t at = 0; at < cells.size(); at += w) rows.push_back(cells.substr(at, w));
  if (rows.empty()) rows.emplace_back();
  return rows;
}

std::vector<std::string> wordRows(std::string_view line, int width) {
  std::string cells = outputCells(line);
  size_t w = static_cast<size_t>(std::max(width, 1));
  std::vector<std::string> rows;
  size_t at = 0;
  while (cells.size() - at > w) {
    // The last space that leaves the row's first cell on it; none: the word is cut.
    size_t cut = cells.rfind(' ', at + w);
    if (cut == std::string::npos || cut <= at) {
      rows.push_back(cells.substr(at, w));
      at += w;
      continue;
    }
    rows.push_back(cells.substr(at, cut - at));
    at = cut + 1;
  }
  rows.push_back(cells.substr(at));
  return rows;
}

std::vector<std::string> lastRows(const std::vector<std::string_view>& lines, int width, int rows) {
  std::vector<std::string> out;
  if (rows <= 0) return out;
  // From the newest line back, until the rows are filled: a pane never wraps more than it shows.
  for (size_t i = lines.size(); i-- > 0 && static_cast<int>(out.size()) < rows;) {
    std::vector<std::string> wrapped = wrapRows(lines[i], width);
    for (size_t j = wrapped.size(); j-- > 0 && static_cast<int>(out.size()) < rows;)
      out.push_back(std::move(wrapped[j]));
  }
  std::reverse(out.begin(), out.end());
  return out;
}

std::vector<std::string> watchLines(const std::vector<WatchLine>& watches, int width) {
  std::vector<std::string> out;
  if (watches.empty() || width <= 0) return out;
  std::string header = "-- watch ";
  header.resize(static_cast<size_t>(width), '-');
  out.push_back(header);
  size_t w = static_cast<size_t>(width);
  for (const WatchLine& watch : watches) {
    std::string line = oneLine(watch.expr) + (watch.error ? ": " : " = ") + oneLine(watch.value);
    if (!watch.error) {
      cut(line, w);
      out.push_back(line);
      continue;
    }
    // An error is read whole: its rows after the first are indented under the expression.
    out.push_back(line.substr(0, w));
    for (size_t at = w; at < line.size() && w > 2; at += w - 2)
      out.push_back("  " + line.substr(at, w - 2));
  }
  return out;
}

std::vector<std::string> variableLines(const std::vector<VariableView>& vars, std::string_view sub,
                                       int width) {
  std::vector<std::string> out;
  if (width <= 0) return out;
  size_t nameWidth = 1;
  for (const VariableView& v : vars) nameWidth = std::max(nameWidth, v.name.size());
  nameWidth = std::min<size_t>(nameWidth, static_cast<size_t>(std::max(width / 3, 4)));
  bool inLocals = false;
  for (const VariableView& v : vars) {
    if (v.local && !inLocals) {
      inLocals = true;
      std::string header = "-- in sub ";
      header += sub;
      header += ' ';
      header.resize(static_cast<size_t>(width), '-');
      out.push_back(header);
    }
    std::string line = oneLine(v.name);
    cut(line, nameWidth);
    line.resize(nameWidth, ' ');
    line += ' ';
    int room = width - static_cast<int>(line.size());
    if (room > 0) line += valueText(*v.value, static_cast<size_t>(room));
    if (static_cast<int>(line.size()) > width) line.resize(static_cast<size_t>(width));
    out.push_back(std::move(line));
  }
  return out;
}

}  // namespace rb::tui
