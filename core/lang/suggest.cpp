#include "lang/suggest.h"

#include <algorithm>
#include <cctype>

#include "lang/builtins.h"
#include "lang/token.h"

namespace rb {

namespace {
char fold(char c, bool ignoreCase) {
  return ignoreCase ? static_cast<char>(std::tolower(static_cast<unsigned char>(c))) : c;
}
}  // namespace

int editDistance(std::string_view a, std::string_view b, bool ignoreCase) {
  const size_t n = a.size(), m = b.size();
  std::vector<int> prev2(m + 1), prev(m + 1), cur(m + 1);
  for (size_t j = 0; j <= m; ++j) prev[j] = static_cast<int>(j);
  for (size_t i = 1; i <= n; ++i) {
    cur[0] = static_cast<int>(i);
    for (size_t j = 1; j <= m; ++j) {
      int cost = fold(a[i - 1], ignoreCase) == fold(b[j - 1], ignoreCase) ? 0 : 1;
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + cost});
      if (i > 1 && j > 1 && fold(a[i - 1], ignoreCase) == fold(b[j - 2], ignoreCase) &&
          fold(a[i - 2], ignoreCase) == fold(b[j - 1], ignoreCase))
        cur[j] = std::min(cur[j], prev2[j - 2] + 1);
    }
    prev2.swap(prev);
    prev.swap(cur);
  }
  return prev[m];
}

std::string closestMatch(std::string_view word, const std::vector<std::string_view>& candidates,
                         bool ignoreCase) {
  // Close by edit distance: roughly one edit per three characters, at least one, at most four;
  // names of one or two characters are too short to be misspellings of each other.
  int limit = word.size() <= 2 ? 0 : std::clamp(static_cast<int>(word.size()) / 3, 1, 4);
  int best = limit + 1;
  std::string_view bestWord;
  // Or sharing a long beginning (InitializeRobot -> InitializeSimulator): at least 4
  // characters and more than half of the word.
  size_t bestPrefix = 0;
  std::string_view prefixWord;
  for (std::string_view c : candidates) {
    if (c == word) continue;
    if (c.size() == word.size() && editDistance(c, word, true) == 0) return std::string(c);
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
    int d = editDistance(word, c, ignoreCase);
    if (d < best) {
      best = d;
      bestWord = c;
    }
  }
  if (best <= limit) return std::string(bestWord);
  return std::string(prefixWord);
}

std::string suggestCommand(const BuiltinTable& builtins, std::string_view word) {
  std::vector<std::string_view> names = builtins.names(BuiltinKind::Command);
  for (std::string_view k : keywordSpellings()) names.push_back(k);
  return closestMatch(word, names, true);
}

}  // namespace rb
