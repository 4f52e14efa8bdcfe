#include "similarity.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <utility>

#include "base/diagnostic.h"
#include "base/source.h"
#include "lang/lexer.h"
#include "machine/builtins.h"
#include "text.h"

namespace rb::grade {

using record::TextShape;
using record::shownText;
using record::toUtf8;

namespace {

namespace fs = std::filesystem;

// The limits the header promises.
constexpr size_t kMaxFileBytes = size_t(4) << 20;
constexpr size_t kMaxLineBytes = size_t(16) << 10;
constexpr size_t kMaxTokens = 500000;
constexpr size_t kMaxLexErrors = 256;
constexpr size_t kMaxBlocks = 100;
constexpr size_t kMaxBlockLines = 100;
constexpr size_t kMaxLineText = 240;
/// Blocks: each fingerprint of a is matched with at most this many places of b that have its
/// hash (repetitive code would otherwise match every copy with every copy), and a pair gets at
/// most kMaxMatches matches in all.
constexpr size_t kMaxOccurrences = 16;
constexpr size_t kMaxMatches = 200000;

// What a normalised token is: a token kind other than the four below is its own code (1 + the
// kind); names, numbers (with built-in constants) and strings are one code each; a built-in
// command or function is its row in the table.
constexpr uint32_t kName = 300;
constexpr uint32_t kNumber = 301;
constexpr uint32_t kString = 302;
constexpr uint32_t kBuiltinBase = 1024;

struct NormToken {
  uint32_t code;
  uint32_t line;
};

/// One program read and normalised.
struct Lexed {
  std::vector<NormToken> tokens;
  std::string skip;                    ///< why the program cannot be compared; empty when it can
  std::vector<std::string> cuts;       ///< what of it was left out
  std::unique_ptr<SourceSet> sources;  ///< its text, when asked for
};

/// Reads at most kMaxFileBytes of a regular file.
bool readCapped(const std::string& path, std::string& out, bool& cut, std::string& why) {
  std::error_code ec;
  fs::file_status st = fs::status(path, ec);
  if (ec || !fs::exists(st)) {
    why = "cannot read it (it does not exist)";
    return false;
  }
  if (!fs::is_regular_file(st)) {
    why = "not a regular file";
    return false;
  }
  uintmax_t size = fs::file_size(path, ec);
  if (ec) size = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    why = "cannot read it";
    return false;
  }
  // One byte more than the limit, to know whether there is more; a file that grew since its
  // size was taken is read up to its old size plus one byte, which is all that is promised.
  out.assign(static_cast<size_t>(std::min<uintmax_t>(size, kMaxFileBytes)) + 1, '\0');
  in.read(out.data(), static_cast<std::streamsize>(out.size()));
  if (in.bad()) {
    why = "cannot read it";
    return false;
  }
  out.resize(static_cast<size_t>(in.gcount()));
  cut = out.size() > kMaxFileBytes;
  if (cut) out.resize(kMaxFileBytes);
  return true;
}

/// Cuts every line longer than kMaxLineBytes to that length (line numbers stay); true when one
/// was cut.
bool cutLongLines(std::string& text) {
  bool any = false;
  for (size_t start = 0; start < text.size() && !any;) {
    size_t nl = text.find('\n', start);
    size_t end = nl == std::string::npos ? text.size() : nl;
    any = end - start > kMaxLineBytes;
    start = end + 1;
  }
  if (!any) return false;
  std::string out;
  out.reserve(text.size());
  for (size_t start = 0; start < text.size();) {
    size_t nl = text.find('\n', start);
    size_t end = nl == std::string::npos ? text.size() : nl;
    out.append(text, start, std::min(end - start, kMaxLineBytes));
    if (nl != std::string::npos) out += '\n';
    start = end + 1;
  }
  text = std::move(out);
  return true;
}

/// The code of a word (an Ident token): a built-in where the language lets a built-in of that
/// kind stand (a constant is a number), else a name. Built-ins are looked up without regard to
/// case. As rb reads a line: a statement starts the line, or follows a label, `then` or `else`;
/// a command is the first word of a statement, a function is called with '(' and a constant is
/// a value. So a label, the word after gosub, goto, sub and call, a word assigned to
/// (`length = 90`) or used as an array, and a function's name without '(' are names, whatever
/// they are spelled like.
uint32_t wordCode(const std::vector<Token>& line, size_t i, const BuiltinTable& builtins) {
  auto kindAt = [&](size_t j) { return j < line.size() ? line[j].kind : Tok::Newline; };
  Tok before = i > 0 ? line[i - 1].kind : Tok::Newline;
  Tok after = kindAt(i + 1);
  if (i == 0 && after == Tok::Colon) return kName;  // a label
  if (before == Tok::KwGosub || before == Tok::KwGoto || before == Tok::KwSub || before == Tok::KwCall)
    return kName;
  bool statement = i == 0 || before == Tok::KwThen || before == Tok::KwElse ||
                   (i == 2 && line[0].kind == Tok::Ident && line[1].kind == Tok::Colon);
  if (statement) {
    switch (after) {
      case Tok::Assign:
      case Tok::PlusAssign:
      case Tok::MinusAssign:
      case Tok::StarAssign:
      case Tok::SlashAssign:
      case Tok::PlusPlus:
      case Tok::MinusMinus:
      case Tok::LBracket: return kName;  // a variable or an array receives a value
      default: break;
    }
  }
  std::string_view word = line[i].text;
  const Builtin* b = nullptr;
  if (statement) b = builtins.find(word, BuiltinKind::Command);
  if (!b && after == Tok::LParen) b = builtins.find(word, BuiltinKind::Function);
  if (b) return kBuiltinBase + builtins.indexOf(*b);
  // A constant is a number with a name (GREEN is 2): changing it is changing a number.
  return builtins.find(word, BuiltinKind::Constant) ? kNumber : kName;
}

void normaliseLine(const std::vector<Token>& line, const BuiltinTable& builtins,
                   std::vector<NormToken>& out) {
  for (size_t i = 0; i < line.size(); ++i) {
    const Token& t = line[i];
    uint32_t code = 0;
    switch (t.kind) {
      case Tok::Eof:
      case Tok::Newline: continue;
      case Tok::Int:
      case Tok::Float: code = kNumber; break;
      case Tok::String: code = kString; break;
      case Tok::Ident: code = wordCode(line, i, builtins); break;
      default: code = 1 + static_cast<uint32_t>(t.kind); break;
    }
    out.push_back({code, t.loc.line});
  }
}

/// Reads, decodes and lexes one file into normalised tokens; keeps its text when `keepText`.
Lexed lexProgram(const std::string& path, bool keepText, const SimilarityOptions& options) {
  Lexed r;
  std::string raw;
  bool cut = false;
  std::optional<std::string> given = options.source ? options.source(path) : std::nullopt;
  if (given) {
    raw = std::move(*given);
    cut = raw.size() > kMaxFileBytes;
    if (cut) raw.resize(kMaxFileBytes);
  } else if (!readCapped(path, raw, cut, r.skip)) {
    return r;
  }
  if (cut) r.cuts.push_back("only its first 4 MiB are compared");
  DecodedText decoded = decodeSourceText(std::move(raw));
  if (decoded.kind == DecodedText::Binary) {
    r.skip = "a binary file, not a program (it holds " + decoded.why + ")";
    return r;
  }
  if (cutLongLines(decoded.text)) r.cuts.push_back("lines longer than 16 KiB are cut");
  auto sources = std::make_unique<SourceSet>();
  uint32_t file = sources->add(path, std::move(decoded.text));
  const BuiltinTable& builtins = standardBuiltins();
  DiagnosticList diags;
  LineLexer lexer(*sources, file, diags);
  std::vector<Token> line;
  for (;;) {
    lexer.next(line);
    if (diags.errorCount() > kMaxLexErrors) {
      r.tokens = {};
      r.skip = "not RobotBASIC: more than " + std::to_string(kMaxLexErrors) + " characters rb cannot read";
      return r;
    }
    if (line.empty() || line.front().kind == Tok::Eof) break;
    normaliseLine(line, builtins, r.tokens);
    if (r.tokens.size() >= kMaxTokens) {
      r.tokens.resize(kMaxTokens);
      r.cuts.push_back("only its first 500,000 tokens are compared");
      break;
    }
  }
  r.tokens.shrink_to_fit();
  if (keepText) r.sources = std::move(sources);
  return r;
}

uint64_t finish(uint64_t x) {  // splitmix64's finaliser: every bit of x moves every bit
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ull;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebull;
  x ^= x >> 31;
  return x;
}

/// The hash of every k-gram: a polynomial of its codes (mod 2^64, rolled from one k-gram to the
/// next), finished so that the hashes look random to winnowing's minimum.
std::vector<uint64_t> kgramHashes(const std::vector<NormToken>& t, size_t k) {
  if (t.size() < k) return {};
  constexpr uint64_t kBase = 0x100000001b3ull;  // odd
  uint64_t top = 1;                             // kBase^(k-1)
  for (size_t j = 1; j < k; ++j) top *= kBase;
  std::vector<uint64_t> out(t.size() - k + 1);
  uint64_t h = 0;
  for (size_t j = 0; j < k; ++j) h = h * kBase + t[j].code;
  out[0] = finish(h);
  for (size_t p = 1; p < out.size(); ++p) {
    h = (h - top * t[p - 1].code) * kBase + t[p + k - 1].code;
    out[p] = finish(h);
  }
  return out;
}

struct Fingerprint {
  uint64_t hash;
  uint32_t pos;  ///< the k-gram's first token
};

/// Robust winnowing: the minimum of every window of w hashes (the rightmost of equal ones),
/// each selected position once, in order. A deque holds the window's candidates: positions
/// whose hashes increase strictly, so its front is the window's rightmost minimum.
std::vector<Fingerprint> winnow(const std::vector<uint64_t>& h, size_t w) {
  std::vector<Fingerprint> out;
  if (h.empty()) return out;
  w = std::min(w, h.size());
  std::deque<size_t> q;
  size_t last = std::numeric_limits<size_t>::max();
  for (size_t i = 0; i < h.size(); ++i) {
    while (!q.empty() && h[q.back()] >= h[i]) q.pop_back();
    q.push_back(i);
    if (i + 1 < w) continue;
    while (q.front() + w <= i) q.pop_front();
    if (q.front() != last) {
      last = q.front();
      out.push_back({h[last], static_cast<uint32_t>(last)});
    }
  }
  return out;
}

struct Program {
  std::string path;
  std::vector<Fingerprint> prints;  ///< in order of position, without the ignored files' hashes
  uint32_t tokens = 0;
  std::vector<uint32_t> groups;  ///< its distinct hashes (index into the class's groups)
  size_t counted = 0;            ///< of those, the ones not dropped as boilerplate
};

/// Every hash in the class once, sorted, with the programs that have it and whether it counts.
struct Index {
  std::vector<uint64_t> hash;
  std::vector<uint32_t> start;  ///< group g's programs are programs[start[g] .. start[g+1])
  std::vector<uint32_t> programs;
  std::vector<char> counts;

  bool counted(uint64_t h) const {
    auto it = std::lower_bound(hash.begin(), hash.end(), h);
    return it != hash.end() && *it == h && counts[static_cast<size_t>(it - hash.begin())];
  }
};

struct Candidate {
  uint32_t a, b;
  uint32_t shared;
  double score;
};

/// Half-open token ranges already taken by a block, to keep blocks apart.
class Taken {
 public:
  bool overlaps(uint32_t s, uint32_t e) const {
    auto it = ranges_.upper_bound(s);
    if (it != ranges_.begin() && std::prev(it)->second > s) return true;
    return it != ranges_.end() && it->first < e;
  }
  void add(uint32_t s, uint32_t e) { ranges_[s] = e; }

 private:
  std::map<uint32_t, uint32_t> ranges_;
};

struct Match {
  uint32_t a, b;  ///< the k-gram's first token in each file
};

/// Matches in order in both files, merged; then the tokens of both files it covers.
struct Run {
  std::vector<Match> anchors;
  uint32_t s = 0, e = 0;  ///< a's tokens [s, e)
  uint32_t t = 0, f = 0;  ///< b's tokens [t, f)
  size_t tokens = 0;
};

std::string cutLine(std::string_view s) {
  if (s.size() > kMaxLineText) {
    size_t n = kMaxLineText;
    while (n > 0 && (static_cast<unsigned char>(s[n]) & 0xC0) == 0x80) --n;  // a whole character
    s = s.substr(0, n);
  }
  return toUtf8(s);
}

std::vector<std::string> linesOf(const SourceFile& f, LineRange r) {
  std::vector<std::string> out;
  for (uint32_t l = r.first; l <= r.last && out.size() < kMaxBlockLines; ++l)
    out.push_back(cutLine(f.lineText(l)));
  return out;
}

/// Which tokens are in a k-gram of the template (`ignored`: sorted hashes).
std::vector<char> templateTokens(const std::vector<NormToken>& tokens, const std::vector<uint64_t>& ignored,
                                 size_t k) {
  std::vector<char> in(tokens.size(), 0);
  if (ignored.empty()) return in;
  std::vector<uint64_t> h = kgramHashes(tokens, k);
  size_t coveredTo = 0;  // tokens before this are marked already
  for (size_t p = 0; p < h.size(); ++p) {
    if (!std::binary_search(ignored.begin(), ignored.end(), h[p])) continue;
    for (size_t i = std::max(p, coveredTo); i < p + k; ++i) in[i] = 1;
    coveredTo = p + k;
  }
  return in;
}

/// The rows of a block shown side by side. `pairs`: lines of a and b that hold matching tokens,
/// in order in both. Lines between them that match nothing (comments, blank lines, code of one
/// file only) are shown next to each other as they come, then alone.
std::vector<SharedBlock::Row> alignRows(const std::vector<SharedBlock::Row>& pairs, LineRange a,
                                        LineRange b) {
  std::vector<SharedBlock::Row> rows;
  uint32_t nextA = a.first, nextB = b.first;  // the first line not shown yet on each side
  auto flush = [&](uint32_t toA, uint32_t toB) {
    while ((nextA < toA || nextB < toB) && rows.size() < kMaxBlockLines) {
      SharedBlock::Row r;
      if (nextA < toA) r.a = nextA++;
      if (nextB < toB) r.b = nextB++;
      rows.push_back(r);
    }
  };
  for (const SharedBlock::Row& p : pairs) {
    flush(p.a, p.b);
    if (rows.size() >= kMaxBlockLines) break;
    SharedBlock::Row r;
    if (p.a >= nextA) r.a = p.a, nextA = p.a + 1;
    if (p.b >= nextB) r.b = p.b, nextB = p.b + 1;
    if (r.a || r.b) rows.push_back(r);
  }
  flush(a.last + 1, b.last + 1);
  return rows;
}

/// The blocks of code a and b share, from their counted fingerprints and their tokens.
std::vector<SharedBlock> findBlocks(const Program& pa, const Program& pb, const Lexed& la, const Lexed& lb,
                                    const Index& index, const std::vector<uint64_t>& ignored, size_t k,
                                    size_t w) {
  std::vector<Fingerprint> inB;
  for (const Fingerprint& f : pb.prints)
    if (index.counted(f.hash)) inB.push_back(f);
  std::sort(inB.begin(), inB.end(), [](const Fingerprint& x, const Fingerprint& y) {
    return x.hash != y.hash ? x.hash < y.hash : x.pos < y.pos;
  });
  std::vector<Match> matches;
  for (const Fingerprint& f : pa.prints) {
    auto it = std::lower_bound(inB.begin(), inB.end(), f.hash,
                               [](const Fingerprint& x, uint64_t h) { return x.hash < h; });
    for (size_t n = 0; it != inB.end() && it->hash == f.hash && n < kMaxOccurrences; ++it, ++n)
      matches.push_back({f.pos, it->pos});
    if (matches.size() >= kMaxMatches) break;
  }
  std::sort(matches.begin(), matches.end(),
            [](const Match& x, const Match& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; });

  // Runs: a match continues the open run it follows in both files within `gap` tokens, the one
  // whose step is most alike in both (a copy keeps its diagonal), else it starts a run.
  const uint32_t gap = static_cast<uint32_t>(std::min<size_t>(w + k, 1u << 20));
  const uint32_t kk = static_cast<uint32_t>(k);
  std::vector<Run> runs;
  std::vector<size_t> open;
  for (const Match& m : matches) {
    open.erase(std::remove_if(open.begin(), open.end(),
                              [&](size_t r) { return m.a > runs[r].anchors.back().a + gap; }),
               open.end());
    size_t best = runs.size();
    uint32_t bestSkew = std::numeric_limits<uint32_t>::max();
    for (size_t r : open) {
      const Match& last = runs[r].anchors.back();
      if (m.a <= last.a || m.b <= last.b || m.b - last.b > gap) continue;
      uint32_t da = m.a - last.a, db = m.b - last.b;
      uint32_t skew = da > db ? da - db : db - da;
      if (skew < bestSkew) {
        bestSkew = skew;
        best = r;
      }
    }
    if (best < runs.size()) {
      runs[best].anchors.push_back(m);
    } else {
      runs.emplace_back().anchors.push_back(m);
      open.push_back(runs.size() - 1);
    }
  }

  // Token ranges: without the template's tokens at their ends, widened over the identical
  // tokens around them that are not the template's.
  const std::vector<NormToken>& ta = la.tokens;
  const std::vector<NormToken>& tb = lb.tokens;
  const uint32_t na = static_cast<uint32_t>(ta.size()), nb = static_cast<uint32_t>(tb.size());
  std::vector<char> inTemplateA = templateTokens(ta, ignored, k);
  std::vector<char> inTemplateB = templateTokens(tb, ignored, k);
  auto same = [&](uint32_t i, uint32_t j) {
    return ta[i].code == tb[j].code && !inTemplateA[i] && !inTemplateB[j];
  };
  for (Run& r : runs) {
    uint32_t s = r.anchors.front().a, t = r.anchors.front().b;
    uint32_t e = std::min(r.anchors.back().a + kk, na);
    uint32_t f = std::min(r.anchors.back().b + kk, nb);
    while (s < e && t < f && (inTemplateA[s] || inTemplateB[t])) ++s, ++t;
    while (s < e && t < f && (inTemplateA[e - 1] || inTemplateB[f - 1])) --e, --f;
    if (s == e || t == f) continue;  // tokens stays 0: nothing of the students' own
    for (uint32_t n = 0; n < gap && s > 0 && t > 0 && same(s - 1, t - 1); ++n) --s, --t;
    for (uint32_t n = 0; n < gap && e < na && f < nb && same(e, f); ++n) ++e, ++f;
    r.s = s, r.e = e, r.t = t, r.f = f;
    r.tokens = std::min(e - s, f - t);
  }
  std::stable_sort(runs.begin(), runs.end(), [](const Run& x, const Run& y) {
    return x.tokens != y.tokens ? x.tokens > y.tokens : x.s < y.s;
  });

  // Longest first, each run becomes a block: the tokens that correspond in it (in order in
  // both files: the widened start, each anchor's k-gram, the widened end; a pair only when it
  // follows the last one in both files and its tokens are the same), without those a longer
  // block has taken; of what is left, the longest stretch not broken by a taken pair, if it
  // still holds k tokens.
  std::vector<SharedBlock> blocks;
  Taken takenA, takenB;
  const SourceFile& fa = la.sources->file(0);
  const SourceFile& fb = lb.sources->file(0);
  std::vector<Match> pairs;
  for (const Run& r : runs) {
    if (blocks.size() >= kMaxBlocks) break;
    if (r.tokens == 0) continue;
    pairs.clear();
    auto take = [&](uint32_t i, uint32_t j) {
      if (i < r.s || i >= r.e || j < r.t || j >= r.f || ta[i].code != tb[j].code) return;
      if (!pairs.empty() && (i <= pairs.back().a || j <= pairs.back().b)) return;
      pairs.push_back({i, j});
    };
    for (uint32_t n = 0; r.s + n < r.anchors.front().a; ++n) take(r.s + n, r.t + n);
    for (const Match& m : r.anchors)
      for (uint32_t d = 0; d < kk; ++d) take(m.a + d, m.b + d);
    const Match& end = r.anchors.back();
    for (uint32_t n = kk; end.a + n < r.e; ++n) take(end.a + n, end.b + n);

    size_t bestFrom = 0, bestTo = 0;  // pairs[bestFrom, bestTo): the longest free stretch
    for (size_t from = 0; from < pairs.size();) {
      // pairs[q] joins the stretch when neither it nor the tokens since the stretch's last pair
      // are taken.
      auto free = [&](size_t q) {
        uint32_t a0 = q > from ? pairs[q - 1].a + 1 : pairs[q].a;
        uint32_t b0 = q > from ? pairs[q - 1].b + 1 : pairs[q].b;
        return !takenA.overlaps(a0, pairs[q].a + 1) && !takenB.overlaps(b0, pairs[q].b + 1);
      };
      size_t to = from;
      while (to < pairs.size() && free(to)) ++to;
      if (to - from > bestTo - bestFrom) bestFrom = from, bestTo = to;
      from = to + 1;
    }
    if (bestTo - bestFrom < kk) continue;
    const Match& first = pairs[bestFrom];
    const Match& last = pairs[bestTo - 1];
    takenA.add(first.a, last.a + 1);
    takenB.add(first.b, last.b + 1);
    SharedBlock b;
    b.a = {ta[first.a].line, ta[last.a].line};
    b.b = {tb[first.b].line, tb[last.b].line};
    b.tokens = std::min(last.a - first.a, last.b - first.b) + 1;
    b.linesA = linesOf(fa, b.a);
    b.linesB = linesOf(fb, b.b);
    // The lines that hold corresponding tokens, side by side.
    std::vector<SharedBlock::Row> lines;
    for (size_t p = bestFrom; p < bestTo; ++p) {
      SharedBlock::Row row{ta[pairs[p].a].line, tb[pairs[p].b].line};
      if (lines.empty() || lines.back().a != row.a || lines.back().b != row.b) lines.push_back(row);
    }
    b.rows = alignRows(lines, b.a, b.b);
    blocks.push_back(std::move(b));
  }
  std::stable_sort(blocks.begin(), blocks.end(), [](const SharedBlock& x, const SharedBlock& y) {
    return x.tokens != y.tokens ? x.tokens > y.tokens : x.a.first < y.a.first;
  });
  return blocks;
}

/// The few programs' tokens and text that blocks are being found for, read again.
class LexedCache {
 public:
  /// The program read again, or as read for the last pairs. A reference stays valid until the
  /// cache has been asked for 8 other programs (the one asked for moves to the back; the front
  /// is forgotten first).
  explicit LexedCache(const SimilarityOptions& options) : options_(options) {}
  const Lexed& get(uint32_t program, const std::string& path) {
    for (size_t i = 0; i < items_.size(); ++i) {
      if (items_[i].first != program) continue;
      std::rotate(items_.begin() + static_cast<ptrdiff_t>(i), items_.begin() + static_cast<ptrdiff_t>(i) + 1,
                  items_.end());
      return *items_.back().second;
    }
    if (items_.size() >= 8) items_.erase(items_.begin());
    items_.emplace_back(program, std::make_unique<Lexed>(lexProgram(path, true, options_)));
    return *items_.back().second;
  }

 private:
  const SimilarityOptions& options_;
  std::vector<std::pair<uint32_t, std::unique_ptr<Lexed>>> items_;
};

}  // namespace

SimilarityReport findSimilar(const std::vector<std::string>& paths, const SimilarityOptions& options) {
  SimilarityReport report;
  report.minScore = options.minScore;
  const size_t k = std::max<size_t>(options.k, 1);
  const size_t w = std::max<size_t>(options.window, 1);

  // The template's k-grams, every one of them.
  std::vector<uint64_t> ignored;
  std::vector<fs::path> ignoredFiles;
  for (const std::string& path : options.ignore) {
    Lexed lexed = lexProgram(path, false, options);
    if (!lexed.skip.empty()) {
      report.notes.push_back(path + ": not used as a template: " + lexed.skip);
      continue;
    }
    std::vector<uint64_t> h = kgramHashes(lexed.tokens, k);
    ignored.insert(ignored.end(), h.begin(), h.end());
    ignoredFiles.emplace_back(path);
  }
  std::sort(ignored.begin(), ignored.end());
  ignored.erase(std::unique(ignored.begin(), ignored.end()), ignored.end());

  // Every program's fingerprints.
  std::vector<Program> programs;
  programs.reserve(paths.size());
  for (const std::string& path : paths) {
    bool isTemplate = false;
    for (const fs::path& t : ignoredFiles) {
      std::error_code ec;
      isTemplate = isTemplate || fs::equivalent(t, path, ec);
    }
    if (isTemplate) {
      report.notes.push_back(path + ": skipped: it is one of the ignored files (the template)");
      ++report.skipped;
      continue;
    }
    Lexed lexed = lexProgram(path, false, options);
    if (lexed.skip.empty() && lexed.tokens.size() < k)
      lexed.skip = "too short to compare (" + std::to_string(lexed.tokens.size()) + " tokens; it takes " +
                   std::to_string(k) + ")";
    if (!lexed.skip.empty()) {
      report.notes.push_back(path + ": skipped: " + lexed.skip);
      ++report.skipped;
      continue;
    }
    for (const std::string& cut : lexed.cuts) report.notes.push_back(path + ": " + cut);
    Program p;
    p.path = path;
    p.tokens = static_cast<uint32_t>(lexed.tokens.size());
    p.prints = winnow(kgramHashes(lexed.tokens, k), w);
    if (!ignored.empty())
      std::erase_if(p.prints, [&](const Fingerprint& f) {
        return std::binary_search(ignored.begin(), ignored.end(), f.hash);
      });
    p.prints.shrink_to_fit();
    programs.push_back(std::move(p));
  }
  report.programs = programs.size();
  const size_t n = programs.size();

  // The inverted index: each hash with the programs that have it.
  Index index;
  {
    std::vector<std::pair<uint64_t, uint32_t>> entries;
    for (uint32_t i = 0; i < n; ++i)
      for (const Fingerprint& f : programs[i].prints) entries.emplace_back(f.hash, i);
    std::sort(entries.begin(), entries.end());
    entries.erase(std::unique(entries.begin(), entries.end()), entries.end());
    index.programs.reserve(entries.size());
    for (size_t e = 0; e < entries.size(); ++e) {
      if (e == 0 || entries[e].first != entries[e - 1].first) {
        index.hash.push_back(entries[e].first);
        index.start.push_back(static_cast<uint32_t>(e));
      }
      index.programs.push_back(entries[e].second);
      programs[entries[e].second].groups.push_back(static_cast<uint32_t>(index.hash.size() - 1));
    }
    index.start.push_back(static_cast<uint32_t>(entries.size()));
  }
  const size_t groups = index.hash.size();
  index.counts.assign(groups, 1);
  const double commonAbove = options.commonShare * static_cast<double>(n);
  for (size_t g = 0; g < groups; ++g) {
    size_t have = index.start[g + 1] - index.start[g];
    if (have >= options.commonMinPrograms && static_cast<double>(have) > commonAbove) {
      index.counts[g] = 0;
      ++report.common;
    }
  }
  size_t empty = 0;
  for (Program& p : programs) {
    for (uint32_t g : p.groups) p.counted += index.counts[g] ? 1 : 0;
    if (p.counted == 0) ++empty;
  }
  if (empty > 0)
    report.notes.push_back(
        std::to_string(empty) + (empty == 1 ? " program has" : " programs have") +
        " no code of its own to compare: all of it is in the template or common to most programs");

  // Each program against the later ones that share a counted hash with it.
  auto better = [&](const Candidate& x, const Candidate& y) {
    if (x.score != y.score) return x.score > y.score;
    if (x.shared != y.shared) return x.shared > y.shared;
    const std::string& xa = programs[x.a].path;
    const std::string& ya = programs[y.a].path;
    if (xa != ya) return xa < ya;
    return programs[x.b].path < programs[y.b].path;
  };
  std::vector<Candidate> kept;
  std::vector<uint32_t> count(n, 0);
  std::vector<uint32_t> touched;
  const size_t limit = options.maxPairs;
  for (uint32_t i = 0; i < n; ++i) {
    for (uint32_t g : programs[i].groups) {
      if (!index.counts[g]) continue;
      auto begin = index.programs.begin() + index.start[g];
      auto end = index.programs.begin() + index.start[g + 1];
      for (auto it = std::upper_bound(begin, end, i); it != end; ++it)
        if (count[*it]++ == 0) touched.push_back(*it);
    }
    for (uint32_t j : touched) {
      uint32_t shared = count[j];
      count[j] = 0;
      double si = double(shared) / double(programs[i].counted);
      double sj = double(shared) / double(programs[j].counted);
      double score = std::max(si, sj);
      if (score < options.minScore || shared < options.minShared) continue;
      ++report.matching;
      kept.push_back({i, j, shared, score});
      if (limit > 0 && kept.size() >= 2 * limit + 1024) {
        std::nth_element(kept.begin(), kept.begin() + static_cast<ptrdiff_t>(limit), kept.end(), better);
        kept.resize(limit);
      }
    }
    touched.clear();
  }
  std::sort(kept.begin(), kept.end(), better);
  if (limit > 0 && kept.size() > limit) kept.resize(limit);

  // The kept pairs, with their blocks.
  LexedCache cache(options);
  for (const Candidate& c : kept) {
    const Program& pa = programs[c.a];
    const Program& pb = programs[c.b];
    SimilarPair pair;
    pair.a = pa.path;
    pair.b = pb.path;
    pair.shared = c.shared;
    pair.fingerprintsA = pa.counted;
    pair.fingerprintsB = pb.counted;
    pair.shareA = double(c.shared) / double(pa.counted);
    pair.shareB = double(c.shared) / double(pb.counted);
    pair.score = c.score;
    const Lexed& la = cache.get(c.a, pa.path);
    const Lexed& lb = cache.get(c.b, pb.path);
    bool sameA = la.skip.empty() && la.tokens.size() == pa.tokens;
    bool sameB = lb.skip.empty() && lb.tokens.size() == pb.tokens;
    if (sameA && sameB) {
      pair.blocks = findBlocks(pa, pb, la, lb, index, ignored, k, w);
    } else {
      std::string note =
          (sameA ? pb.path : pa.path) + ": changed while it was compared; no blocks shown for it";
      if (std::find(report.notes.begin(), report.notes.end(), note) == report.notes.end())
        report.notes.push_back(note);
    }
    report.pairs.push_back(std::move(pair));
  }
  return report;
}

namespace {

/// A share as a whole percentage, rounded to the nearest, but 100% only for the whole and 0%
/// only for nothing.
std::string percent(double share) {
  long p = std::lround(share * 100);
  if (p >= 100 && share < 1) p = 99;
  if (p <= 0 && share > 0) p = 1;
  return std::to_string(p) + "%";
}

/// `raw` in exactly `width` columns (width >= 1): tabs as spaces to the next multiple of 4,
/// control characters as the reports show them (shownText), cut to width - 1 columns and a '~'
/// when longer, padded with spaces when shorter. A character of UTF-8 counts as one column.
std::string fit(std::string_view raw, size_t width) {
  std::string text = shownText(raw, TextShape::Block);
  std::vector<std::string> pieces;  // one column each
  for (size_t i = 0; i < text.size();) {
    unsigned char c = static_cast<unsigned char>(text[i]);
    if (c == '\t') {
      for (size_t n = 4 - pieces.size() % 4; n > 0; --n) pieces.emplace_back(" ");
      ++i;
    } else if (c < 0x20 || c == 0x7f) {
      pieces.emplace_back("?");
      ++i;
    } else {
      size_t len = std::min<size_t>(c < 0x80 ? 1 : c < 0xE0 ? 2 : c < 0xF0 ? 3 : 4, text.size() - i);
      pieces.push_back(text.substr(i, len));
      i += len;
    }
    if (pieces.size() > width) break;  // enough to know it is cut
  }
  std::string out;
  if (pieces.size() <= width) {
    for (const std::string& p : pieces) out += p;
    out.append(width - pieces.size(), ' ');
    return out;
  }
  for (size_t n = 0; n + 1 < width; ++n) out += pieces[n];
  return out + "~";
}

std::string trimRight(std::string s) {
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

std::string lineRange(LineRange r) {
  return r.first == r.last ? "line " + std::to_string(r.first)
                           : "lines " + std::to_string(r.first) + "-" + std::to_string(r.last);
}

constexpr size_t kColumn = 50;
constexpr size_t kBlocksShown = 3;
constexpr size_t kRowsShown = 24;

}  // namespace

std::string similarityText(const SimilarityReport& r) {
  std::string out;
  std::string of = std::to_string(r.programs) + (r.programs == 1 ? " program" : " programs");
  if (r.skipped > 0) of += " (" + std::to_string(r.skipped) + " skipped)";
  std::string rule = percent(r.minScore) + " or more of one program's code is found in the other";
  if (r.pairs.empty()) {
    out += "Similar code: no pair of the " + of + " where " + rule + ".\n";
  } else {
    out += "Similar code: " + std::to_string(r.pairs.size()) + (r.pairs.size() == 1 ? " pair" : " pairs");
    if (r.matching > r.pairs.size()) out += " (the best of " + std::to_string(r.matching) + ")";
    out += " of the " + of + " where " + rule + ".\n";
    out += "An aid for the teacher, never a verdict: read the lines side by side.\n";
  }
  size_t rank = 0;
  for (const SimilarPair& p : r.pairs) {
    std::string a = shownText(p.a, TextShape::Line), b = shownText(p.b, TextShape::Line);
    out += "\n" + std::to_string(++rank) + ". " + percent(p.score) + "  " + a + "  and  " + b + "\n";
    out += "   " + std::to_string(p.shared) + " fingerprints in common: " + percent(p.shareA) + " of " + a +
           "'s " + std::to_string(p.fingerprintsA) + ", " + percent(p.shareB) + " of " + b + "'s " +
           std::to_string(p.fingerprintsB) + "\n";
    size_t shown = 0;
    for (const SharedBlock& block : p.blocks) {
      if (shown++ == kBlocksShown) break;
      out += "\n   " + lineRange(block.a) + " of " + a + " and " + lineRange(block.b) + " of " + b + " (" +
             std::to_string(block.tokens) + " tokens):\n";
      out += "   " + fit(a, kColumn) + " | " + trimRight(fit(b, kColumn)) + "\n";
      uint32_t widest = std::max(block.a.last, block.b.last);
      size_t digits = std::to_string(widest).size();
      auto cell = [&](const std::vector<std::string>& lines, LineRange range, uint32_t line) {
        if (line == 0) return std::string(kColumn, ' ');
        std::string number = std::to_string(line);
        size_t at = line - range.first;
        std::string text = at < lines.size() ? lines[at] : "";
        return std::string(digits - std::min(digits, number.size()), ' ') + number + " " +
               fit(text, kColumn - digits - 1);
      };
      uint32_t shownA = 0, shownB = 0;
      for (size_t row = 0; row < block.rows.size() && row < kRowsShown; ++row) {
        const SharedBlock::Row& rw = block.rows[row];
        out += "   " + cell(block.linesA, block.a, rw.a) + " | " +
               trimRight(cell(block.linesB, block.b, rw.b)) + "\n";
        shownA = std::max(shownA, rw.a);
        shownB = std::max(shownB, rw.b);
      }
      if (shownA < block.a.last || shownB < block.b.last)
        out += "   ... on to line " + std::to_string(block.a.last) + " of " + a + " and line " +
               std::to_string(block.b.last) + " of " + b + "\n";
    }
    if (p.blocks.size() > kBlocksShown) {
      size_t more = p.blocks.size() - kBlocksShown;
      out +=
          "\n   and " + std::to_string(more) + " shorter shared " + (more == 1 ? "block" : "blocks") + "\n";
    }
  }
  if (!r.notes.empty()) out += "\n";
  for (const std::string& note : r.notes) out += "note: " + shownText(note, TextShape::Line) + "\n";
  return out;
}

std::string similarityJson(const SimilarityReport& r) {
  using nlohmann::ordered_json;
  auto round4 = [](double x) { return std::round(x * 10000) / 10000; };
  ordered_json doc = ordered_json::array();
  for (const SimilarPair& p : r.pairs) {
    ordered_json blocks = ordered_json::array();
    for (const SharedBlock& b : p.blocks) {
      ordered_json linesA = ordered_json::array(), linesB = ordered_json::array();
      for (const std::string& l : b.linesA) linesA.push_back(shownText(l, TextShape::Block));
      for (const std::string& l : b.linesB) linesB.push_back(shownText(l, TextShape::Block));
      ordered_json rows = ordered_json::array();
      auto line = [](uint32_t l) { return l ? ordered_json(l) : ordered_json(nullptr); };
      for (const SharedBlock::Row& row : b.rows) rows.push_back({line(row.a), line(row.b)});
      blocks.push_back({{"a", {b.a.first, b.a.last}},
                        {"b", {b.b.first, b.b.last}},
                        {"tokens", b.tokens},
                        {"lines_a", std::move(linesA)},
                        {"lines_b", std::move(linesB)},
                        {"rows", std::move(rows)}});
    }
    doc.push_back({{"a", shownText(p.a, TextShape::Line)},
                   {"b", shownText(p.b, TextShape::Line)},
                   {"score", round4(p.score)},
                   {"share_a", round4(p.shareA)},
                   {"share_b", round4(p.shareB)},
                   {"shared", p.shared},
                   {"fingerprints_a", p.fingerprintsA},
                   {"fingerprints_b", p.fingerprintsB},
                   {"blocks", std::move(blocks)}});
  }
  return doc.dump(2, ' ', false, ordered_json::error_handler_t::replace) + "\n";
}

}  // namespace rb::grade
