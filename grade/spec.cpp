#include "spec.h"

#include <cctype>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace rb::grade {

namespace fs = std::filesystem;

namespace {

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }
bool isWord(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

std::string rstrip(std::string s) {
  while (!s.empty() && isSpace(s.back())) s.pop_back();
  return s;
}

/// After "//" at `i`: skips blanks and returns the position after `word`, or npos.
size_t afterComment(const std::string& line, size_t i, const std::string& word) {
  size_t j = i + 2;
  while (j < line.size() && isSpace(line[j])) ++j;
  if (line.compare(j, word.size(), word) != 0) return std::string::npos;
  return j + word.size();
}

/// Where the next "//  expect" starts at or after `from`, minus the blanks before it.
size_t nextExpectStart(const std::string& line, size_t from) {
  for (size_t i = line.find("//", from); i != std::string::npos; i = line.find("//", i + 1)) {
    if (afterComment(line, i, "expect") != std::string::npos) {
      while (i > from && isSpace(line[i - 1])) --i;
      return i;
    }
  }
  return line.size();
}

struct ExpectMatch {
  std::string kind;  ///< "", "-error", "-warning", "-runtime-error" or "-stderr"
  std::string text;
};

/// Every `// expect...: TEXT` on the line; each text runs up to the next "// expect".
std::vector<ExpectMatch> expectations(const std::string& line) {
  static const char* kinds[] = {"-error", "-warning", "-runtime-error", "-stderr", ""};
  std::vector<ExpectMatch> out;
  size_t i = line.find("//");
  while (i != std::string::npos) {
    size_t j = afterComment(line, i, "expect");
    bool matched = false;
    if (j != std::string::npos) {
      for (const char* kind : kinds) {
        std::string k = kind;
        if (line.compare(j, k.size() + 1, k + ":") != 0) continue;
        size_t start = j + k.size() + 1;
        if (start < line.size() && isSpace(line[start])) ++start;
        size_t end = nextExpectStart(line, start);
        out.push_back({k, line.substr(start, end - start)});
        i = line.find("//", end);
        matched = true;
        break;
      }
    }
    if (!matched) i = line.find("//", i + 1);
  }
  return out;
}

std::optional<double> toDouble(const std::string& s) {
  try {
    size_t used = 0;
    double v = std::stod(s, &used);
    if (used != s.size()) return std::nullopt;
    return v;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

std::optional<int> toInt(const std::string& s) {
  int v = 0;
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return v;
}

bool startsWithInclude(const std::string& line, std::string& file) {
  size_t i = 0;
  while (i < line.size() && isSpace(line[i])) ++i;
  static const std::string kw = "#include";
  if (line.size() - i < kw.size()) return false;
  for (size_t k = 0; k < kw.size(); ++k)
    if (std::tolower(static_cast<unsigned char>(line[i + k])) != kw[k]) return false;
  i += kw.size();
  size_t blanks = i;
  while (i < line.size() && isSpace(line[i])) ++i;
  if (i == blanks || i >= line.size() || line[i] != '"') return false;
  size_t close = line.find('"', i + 1);
  if (close == std::string::npos || close == i + 1) return false;
  file = line.substr(i + 1, close - i - 1);
  return true;
}

void parseFile(const fs::path& path, bool main, CommentSpec& spec, std::set<std::string>& seen) {
  std::error_code ec;
  fs::path real = fs::weakly_canonical(path, ec);
  if (ec) real = path;
  if (!seen.insert(real.string()).second) return;
  std::ifstream in(path, std::ios::binary);
  if (!in) return;
  std::stringstream buffer;
  buffer << in.rdbuf();
  std::vector<std::string> includes;
  parseComments(buffer.str(), path.filename().string(), main, spec, &includes);
  for (const std::string& inc : includes) {
    fs::path target = path.parent_path() / inc;
    if (fs::exists(target, ec)) parseFile(target, false, spec, seen);
  }
}

}  // namespace

void parseComments(const std::string& text, const std::string& name, bool main, CommentSpec& spec,
                   std::vector<std::string>* includes) {
  static const char* keys[] = {"stdin", "args", "check-args", "skip", "nontest",
                               "timeout", "exit", "expect-empty-line"};
  uint32_t number = 0;
  size_t pos = 0;
  while (pos <= text.size()) {
    size_t nl = text.find('\n', pos);
    std::string line = text.substr(pos, nl == std::string::npos ? std::string::npos : nl - pos);
    pos = nl == std::string::npos ? text.size() + 1 : nl + 1;
    ++number;

    std::vector<ExpectMatch> found = expectations(line);
    for (const ExpectMatch& m : found) {
      if (m.kind.empty()) {
        if (!main) continue;
        std::string out = m.text;
        while (!out.empty() && out.back() == '\r') out.pop_back();
        spec.output.push_back(out);
        continue;
      }
      Expected e{name, number, rstrip(m.text)};
      if (m.kind == "-error") spec.errors.insert(e);
      else if (m.kind == "-warning") spec.warnings.insert(e);
      else if (m.kind == "-runtime-error") spec.runtime = e;
      else spec.stderrHas.push_back(e.message);
    }
    if (!found.empty()) continue;

    // The first "// KEY" on the line with a known key.
    for (size_t i = line.find("//"); main && i != std::string::npos; i = line.find("//", i + 1)) {
      std::string key;
      size_t after = std::string::npos;
      for (const char* k : keys) {
        after = afterComment(line, i, k);
        if (after != std::string::npos && (after == line.size() || !isWord(line[after]) ||
                                           !isWord(line[after - 1]))) {
          key = k;
          break;
        }
        after = std::string::npos;
      }
      if (key.empty()) continue;
      if (after < line.size() && line[after] == ':') ++after;
      if (after < line.size() && isSpace(line[after])) ++after;
      std::string value = rstrip(line.substr(std::min(after, line.size())));
      std::string where = name + ":" + std::to_string(number) + ": ";
      if (key == "stdin") {
        spec.stdinLines.push_back(value);
      } else if (key == "args" || key == "check-args") {
        std::optional<std::vector<std::string>> words = splitWords(value);
        std::vector<std::string>& into = key == "args" ? spec.args : spec.checkArgs;
        if (!words) spec.problems.push_back(where + "unclosed quote in // " + key);
        else into.insert(into.end(), words->begin(), words->end());
      } else if (key == "skip") {
        spec.skip = value.empty() ? "skipped" : value;
      } else if (key == "nontest") {
        if (number == 1) spec.nontest = true;
      } else if (key == "timeout") {
        if (std::optional<double> t = toDouble(value); t && *t > 0) spec.timeout = *t, spec.timeoutSet = true;
        else spec.problems.push_back(where + "// timeout wants a number of seconds above 0, not '" + value + "'" +
                                     (t && *t == 0 ? " (a comment may not switch the time limit off)" : ""));
      } else if (key == "exit") {
        if (std::optional<int> code = toInt(value)) spec.exit = *code;
        else spec.problems.push_back(where + "// exit wants a whole number, not '" + value + "'");
      } else if (key == "expect-empty-line") {
        spec.output.push_back("");
      }
      break;
    }
    std::string file;
    if (includes && startsWithInclude(line, file)) includes->push_back(file);
  }
}

std::optional<CommentSpec> readCommentSpec(const std::string& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return std::nullopt;
  CommentSpec spec;
  std::set<std::string> seen;
  parseFile(path, true, spec, seen);
  return spec;
}

std::optional<std::vector<std::string>> splitWords(const std::string& text) {
  std::vector<std::string> words;
  std::string word;
  bool inWord = false;
  for (size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    if (isSpace(c)) {
      if (inWord) words.push_back(word);
      word.clear();
      inWord = false;
    } else if (c == '\'') {
      size_t close = text.find('\'', i + 1);
      if (close == std::string::npos) return std::nullopt;
      word += text.substr(i + 1, close - i - 1);
      i = close;
      inWord = true;
    } else if (c == '"') {
      size_t j = i + 1;
      for (; j < text.size() && text[j] != '"'; ++j) {
        if (text[j] == '\\' && j + 1 < text.size() &&
            (text[j + 1] == '"' || text[j + 1] == '\\' || text[j + 1] == '$' || text[j + 1] == '`'))
          ++j;
        word += text[j];
      }
      if (j >= text.size()) return std::nullopt;
      i = j;
      inWord = true;
    } else if (c == '\\' && i + 1 < text.size()) {
      word += text[++i];
      inWord = true;
    } else {
      word += c;
      inWord = true;
    }
  }
  if (inWord) words.push_back(word);
  return words;
}

}  // namespace rb::grade
