#include "lang/suggest.h"

#include <algorithm>
#include <cctype>

#include "lang/ast.h"
#include "lang/builtins.h"
#include "lang/token.h"

namespace rb {

namespace {
char fold(char c, bool ignoreCase) {
  return ignoreCase ? static_cast<char>(std::tolower(static_cast<unsigned char>(c))) : c;
}
}  // namespace

int editDistance(std::string_view a, std::string_view b, bool ignoreCase) {
  return editDistance(a, b, ignoreCase, std::max(a.size(), b.size()));
}

int editDistance(std::string_view a, std::string_view b, bool ignoreCase, size_t bound) {
  const size_t n = a.size(), m = b.size();
  // Three rows; on the stack for names of up to 47 characters (every candidate is a name), so
  // that trying a word against hundreds of built-ins allocates nothing.
  constexpr size_t kSmall = 48;
  int small[3 * kSmall];
  std::vector<int> large;
  int* rows = small;
  if (m + 1 > kSmall) {
    large.resize(3 * (m + 1));
    rows = large.data();
  }
  const size_t stride = m + 1 > kSmall ? m + 1 : kSmall;
  int* prev2 = rows;
  int* prev = rows + stride;
  int* cur = rows + 2 * stride;
  const int over = static_cast<int>(std::min<size_t>(bound, 1u << 30)) + 1;
  for (size_t j = 0; j <= m; ++j) prev[j] = static_cast<int>(j);
  int prevMin = 0;  // the smallest value of prev
  for (size_t i = 1; i <= n; ++i) {
    cur[0] = static_cast<int>(i);
    int curMin = cur[0];
    for (size_t j = 1; j <= m; ++j) {
      int cost = fold(a[i - 1], ignoreCase) == fold(b[j - 1], ignoreCase) ? 0 : 1;
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + cost});
      if (i > 1 && j > 1 && fold(a[i - 1], ignoreCase) == fold(b[j - 2], ignoreCase) &&
          fold(a[i - 2], ignoreCase) == fold(b[j - 1], ignoreCase))
        cur[j] = std::min(cur[j], prev2[j - 2] + 1);
      curMin = std::min(curMin, cur[j]);
    }
    // Every later cell grows from one of the last two rows: when both are past the bound, so
    // is the answer.
    if (curMin >= over && prevMin >= over) return over;
    prevMin = curMin;
    std::swap(prev2, prev);
    std::swap(prev, cur);
  }
  return std::min(prev[m], over);
}

std::string closestMatch(std::string_view word, const std::vector<std::string_view>& candidates,
                         bool ignoreCase) {
  // Close by edit distance: roughly one edit per three characters, at least one, at most four;
  // names of one or two characters are too short to be misspellings of each other.
  int limit = word.size() <= 2 ? 0 : std::clamp(static_cast<int>(word.size()) / 3, 1, 4);
  int best = limit + 1;
  std::string_view bestWord;
  bool bestFirst = false;  // bestWord begins with the word's first letter
  // Or sharing a long beginning (InitializeRobot -> InitializeSimulator): at least 4
  // characters and more than half of the word.
  size_t bestPrefix = 0;
  std::string_view prefixWord;
  for (std::string_view c : candidates) {
    if (c == word) continue;
    if (c.size() == word.size() && editDistance(c, word, true, 0) == 0) return std::string(c);
    size_t common = 0;
    while (common < c.size() && common < word.size() &&
           fold(c[common], ignoreCase) == fold(word[common], ignoreCase))
      ++common;
    if (common >= 4 && common * 2 > word.size() && common > bestPrefix) {
      bestPrefix = common;
      prefixWord = c;
    }
    int lengthGap = static_cast<int>(c.size()) - static_cast<int>(word.size());
    if (std::abs(lengthGap) > limit) continue;
    // A tie goes to the first candidate that begins as the word does (a slip rarely changes
    // the first letter: "wnd" is wend rather than end).
    bool first = !word.empty() && !c.empty() && fold(word[0], true) == fold(c[0], true);
    int d = editDistance(word, c, ignoreCase, static_cast<size_t>(best));
    if (d < best || (d == best && d <= limit && first && !bestFirst)) {
      best = d;
      bestWord = c;
      bestFirst = first;
    }
  }
  if (best <= limit) return std::string(bestWord);
  return std::string(prefixWord);
}

const std::vector<std::string_view>& statementKeywords() {
  static const std::vector<std::string_view> words = [] {
    std::vector<std::string_view> w;
    for (std::string_view k : keywordSpellings()) {
      switch (keywordKind(k)) {
        case Tok::KwAnd: case Tok::KwOr: case Tok::KwNot: case Tok::KwMod:
        case Tok::KwThen: case Tok::KwTo: case Tok::KwStep:
          break;  // operators and the words inside a statement
        default: w.push_back(k);
      }
    }
    return w;
  }();
  return words;
}

std::string suggestCommand(const BuiltinTable& builtins, std::string_view word) {
  std::vector<std::string_view> names = builtins.names(BuiltinKind::Command);
  for (std::string_view k : statementKeywords()) names.push_back(k);
  return closestMatch(word, names, true);
}

namespace {
bool isNameChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '$'; }

/// `word` appears in `text` as a whole word (case-sensitive: the help writes constants as
/// they are spelt, "Down", where "up" is an ordinary word).
bool namesWord(std::string_view text, std::string_view word) {
  for (size_t at = text.find(word); at != std::string_view::npos; at = text.find(word, at + 1)) {
    bool before = at > 0 && isNameChar(text[at - 1]);
    bool after = at + word.size() < text.size() && isNameChar(text[at + word.size()]);
    if (!before && !after) return true;
  }
  return false;
}

bool isColourParameter(std::string_view p) {
  return p == "colour" || p == "background" || p == "outline" || p == "fill";
}

std::string lowered(std::string_view s) {
  std::string r(s);
  for (char& c : r) c = fold(c, true);
  return r;
}
}  // namespace

std::vector<std::string_view> constantsFitting(const BuiltinTable& builtins, const Builtin& builtin,
                                               std::string_view param) {
  std::vector<std::string_view> out;
  bool colour = isColourParameter(param);
  for (std::string_view name : builtins.names(BuiltinKind::Constant)) {
    const Builtin* c = builtins.find(name, BuiltinKind::Constant);
    if ((colour && c && c->group == "colour") || namesWord(builtin.help, name)) out.push_back(name);
  }
  return out;
}

std::string suggestValue(std::string_view word, const std::vector<std::string_view>& fitting,
                         const std::vector<std::string_view>& variables, const BuiltinTable& builtins) {
  std::vector<std::string_view> names = fitting;
  names.insert(names.end(), variables.begin(), variables.end());
  for (std::string_view c : builtins.names(BuiltinKind::Constant))
    if (std::find(fitting.begin(), fitting.end(), c) == fitting.end()) names.push_back(c);
  return closestMatch(word, names, true);
}

namespace {
void addNamesOf(const ast::Expr* e, std::unordered_set<std::string>& out) {
  if (!e) return;
  if (e->kind == ast::ExprKind::Var || e->kind == ast::ExprKind::Index || e->kind == ast::ExprKind::Call)
    out.insert(lowered(e->text));
  for (const ast::Expr* a : e->args) addNamesOf(a, out);
}
}  // namespace

void addNamesOf(const ast::Stmt& s, std::unordered_set<std::string>& out) {
  if (!s.name.empty() && s.kind != ast::StmtKind::Include) out.insert(lowered(s.name));
  for (const ast::Param& p : s.params) out.insert(lowered(p.name));
  addNamesOf(s.target, out);
  addNamesOf(s.value, out);
  for (const ast::Expr* e : s.exprs) addNamesOf(e, out);
  for (const ast::Stmt* b : s.body) addNamesOf(*b, out);
}

std::string freeName(std::string_view name, const BuiltinTable& builtins,
                     const std::unordered_set<std::string>& taken) {
  // The built-in's own spelling makes the better name: "myLength" for "LENGTH".
  if (const Builtin* b = builtins.findAny(name)) name = b->name;
  auto isFree = [&](const std::string& n) {
    std::string low = lowered(n);
    return !builtins.findAny(n) && keywordKind(low) == Tok::Ident && !taken.count(low);
  };
  std::string mine = "my" + std::string(name);
  if (name.size() > 0) mine[2] = static_cast<char>(std::toupper(static_cast<unsigned char>(name[0])));
  if (isFree(mine)) return mine;
  for (size_t i = 1;; ++i) {  // `taken` is finite: some number is free
    std::string numbered = std::string(name) + std::to_string(i);
    if (isFree(numbered)) return numbered;
  }
}

}  // namespace rb
