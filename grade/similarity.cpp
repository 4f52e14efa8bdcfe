#include "similarity.h"

#include <algorithm>
#include <array>
#include <bit>
#include <atomic>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#ifdef __GLIBC__
#include <malloc.h>
#endif
#include <stdexcept>
#include <thread>
#include <unordered_map>
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

/// Which bytes continue a word (the lexer's isIdentChar: ASCII letters, digits, '_', '$').
constexpr std::array<bool, 256> kWordByte = [] {
  std::array<bool, 256> t{};
  for (int c = 0; c < 256; ++c)
    t[static_cast<size_t>(c)] = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '$';
  return t;
}();

/// A word's spelling hashed (FNV-1a), to find it in Words.
inline uint64_t spellingHash(std::string_view word) {
  uint64_t h = 0xcbf29ce484222325ull;
  for (char c : word) h = (h ^ static_cast<unsigned char>(c)) * 0x100000001b3ull;
  return h;
}

/// What the lexer and the built-in table say of a word, remembered by its spelling: a class's
/// programs use the same few hundred words, and looking one up without regard to case costs
/// more than reading it.
class Words {
 public:
  static constexpr uint32_t kNone = UINT32_MAX;
  struct Info {
    Tok kind = Tok::Ident;  ///< the keyword it is (as the lexer reads it), or Ident
    bool rem = false;       ///< REM: a remark to the end of the line
    bool constant = false;  ///< a built-in constant
    uint32_t command = kNone, function = kNone;  ///< its rows in the table
  };
  explicit Words(const BuiltinTable& builtins) : builtins_(builtins) { slots_.resize(1024); }
  const Info& of(std::string_view word) { return of(word, spellingHash(word)); }
  /// `hash`: spellingHash(word).
  const Info& of(std::string_view word, uint64_t hash) {
    const size_t mask = slots_.size() - 1;
    for (size_t i = slotOf(hash);; i = (i + 1) & mask) {
      Slot& s = slots_[i];
      if (s.used && s.hash == hash && s.length == word.size() && same(spellings_.data() + s.offset, word))
        return s.info;
      if (s.used) continue;
      if ((used_ + 1) * 2 > slots_.size()) {
        if (slots_.size() < kMostSlots) {
          grow();
        } else {  // a file of a hundred thousand different names: start afresh
          slots_.assign(1024, Slot{});
          spellings_.clear();
          used_ = 0;
        }
        return of(word, hash);
      }
      if (spellings_.size() + word.size() > kMostBytes) {
        slots_.assign(1024, Slot{});
        spellings_.clear();
        used_ = 0;
        return of(word, hash);
      }
      s.used = true;
      s.hash = hash;
      s.offset = static_cast<uint32_t>(spellings_.size());
      s.length = static_cast<uint32_t>(word.size());
      spellings_.append(word);
      ++used_;
      s.info = lookUp(word);
      return s.info;
    }
  }

 private:
  static constexpr size_t kMostSlots = 1 << 17;
  static constexpr size_t kMostBytes = size_t{4} << 20;
  struct Slot {
    bool used = false;
    uint64_t hash = 0;
    uint32_t offset = 0, length = 0;
    Info info;
  };
  /// The slot a spelling's hash starts at: its top bits, multiplied in (FNV's low bits vary
  /// little between names that differ only in their last letters).
  size_t slotOf(uint64_t hash) const {
    return static_cast<size_t>((hash * 0x9E3779B97F4A7C15ull) >> (64 - std::countr_zero(slots_.size())));
  }
  static bool same(const char* kept, std::string_view word) {
    size_t i = 0;
    for (; i + 8 <= word.size(); i += 8) {
      uint64_t a, b;
      std::memcpy(&a, kept + i, 8);
      std::memcpy(&b, word.data() + i, 8);
      if (a != b) return false;
    }
    for (; i < word.size(); ++i)
      if (kept[i] != word[i]) return false;
    return true;
  }
  void grow() {
    std::vector<Slot> old = std::move(slots_);
    slots_.assign(old.size() * 2, Slot{});
    const size_t mask = slots_.size() - 1;
    for (const Slot& o : old)
      if (o.used) {
        size_t i = slotOf(o.hash);
        while (slots_[i].used) i = (i + 1) & mask;
        slots_[i] = o;
      }
  }
  Info lookUp(std::string_view word) const {
    Info info;
    if (word.size() < 16) {  // as the lexer: a longer word is a name
      char lower[16];
      for (size_t i = 0; i < word.size(); ++i)
        lower[i] = word[i] >= 'A' && word[i] <= 'Z' ? static_cast<char>(word[i] - 'A' + 'a') : word[i];
      const std::string_view lw(lower, word.size());
      info.rem = lw == "rem";
      info.kind = keywordKind(lw);
    }
    if (const Builtin* b = builtins_.find(word, BuiltinKind::Command)) info.command = builtins_.indexOf(*b);
    if (const Builtin* b = builtins_.find(word, BuiltinKind::Function)) info.function = builtins_.indexOf(*b);
    info.constant = builtins_.find(word, BuiltinKind::Constant) != nullptr;
    return info;
  }
  const BuiltinTable& builtins_;
  std::vector<Slot> slots_;
  std::string spellings_;
  size_t used_ = 0;
};

/// The code of a word (line[i], an Ident token; infoOf(i): what Words says of it): a built-in
/// where the language lets a built-in of that kind stand (a constant is a number), else a name.
/// Built-ins are looked up without regard to case. As rb reads a line: a statement starts the
/// line, or follows a label, `then` or `else`; a command is the first word of a statement, a
/// function is called with '(' and a constant is a value. So a label, the word after gosub,
/// goto, sub and call, a word assigned to (`length = 90`) or used as an array, and a function's
/// name without '(' are names, whatever they are spelled like.
template <class Line, class InfoOf>
uint32_t wordCode(const Line& line, size_t i, InfoOf&& infoOf) {
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
  const Words::Info& info = infoOf(i);
  if (statement && info.command != Words::kNone) return kBuiltinBase + info.command;
  if (after == Tok::LParen && info.function != Words::kNone) return kBuiltinBase + info.function;
  // A constant is a number with a name (GREEN is 2): changing it is changing a number.
  return info.constant ? kNumber : kName;
}

/// The normalised tokens of one line (its tokens up to its Newline): emit(code, token index).
template <class Line, class InfoOf, class Emit>
void normaliseLine(const Line& line, InfoOf&& infoOf, Emit&& emit) {
  for (size_t i = 0; i < line.size(); ++i) {
    uint32_t code = 0;
    switch (line[i].kind) {
      case Tok::Eof:
      case Tok::Newline: continue;
      case Tok::Int:
      case Tok::Float: code = kNumber; break;
      case Tok::String: code = kString; break;
      case Tok::Ident: code = wordCode(line, i, infoOf); break;
      default: code = 1 + static_cast<uint32_t>(line[i].kind); break;
    }
    emit(code, i);
  }
}

/// A program's text as it is compared: read (or as given), decoded as rb reads programs, lines
/// longer than 16 KiB cut. False, with `skip` saying why, when it cannot be compared.
bool programText(const std::string& path, const SimilarityOptions& options, std::string& text,
                 std::vector<std::string>& cuts, std::string& skip) {
  std::string raw;
  bool cut = false;
  std::optional<std::string> given = options.source ? options.source(path) : std::nullopt;
  if (given) {
    raw = std::move(*given);
    cut = raw.size() > kMaxFileBytes;
    if (cut) raw.resize(kMaxFileBytes);
  } else if (!readCapped(path, raw, cut, skip)) {
    return false;
  }
  if (cut) cuts.push_back("only its first 4 MiB are compared");
  DecodedText decoded = decodeSourceText(std::move(raw));
  if (decoded.kind == DecodedText::Binary) {
    skip = "a binary file, not a program (it holds " + decoded.why + ")";
    return false;
  }
  if (cutLongLines(decoded.text)) cuts.push_back("lines longer than 16 KiB are cut");
  text = std::move(decoded.text);
  return true;
}

constexpr const char* kTokensCut = "only its first 500,000 tokens are compared";

/// `text` lexed by rb's lexer into normalised tokens (with their lines); r.skip when it is not
/// RobotBASIC; its text kept in r.sources when `keepText`.
void lexText(const std::string& path, std::string text, bool keepText, Words& words, Lexed& r) {
  auto sources = std::make_unique<SourceSet>();
  uint32_t file = sources->add(path, std::move(text));
  DiagnosticList diags;
  LineLexer lexer(*sources, file, diags);
  std::vector<Token> line;
  auto infoOf = [&](size_t i) -> const Words::Info& { return words.of(line[i].text); };
  for (;;) {
    lexer.next(line);
    if (diags.errorCount() > kMaxLexErrors) {
      r.tokens = {};
      r.skip = "not RobotBASIC: more than " + std::to_string(kMaxLexErrors) + " characters rb cannot read";
      return;
    }
    if (line.empty() || line.front().kind == Tok::Eof) break;
    normaliseLine(line, infoOf, [&](uint32_t code, size_t i) { r.tokens.push_back({code, line[i].loc.line}); });
    if (r.tokens.size() >= kMaxTokens) {
      r.tokens.resize(kMaxTokens);
      r.cuts.push_back(kTokensCut);
      break;
    }
  }
  r.tokens.shrink_to_fit();
  if (keepText) r.sources = std::move(sources);
}

/// The codes rb's lexer and normaliseLine give `text` (lexText's, without the lines), found by
/// a quick scan of what programs are mostly made of. False when the text holds anything the
/// quick scan leaves to the lexer: a character the lexer reports (any byte outside strings and
/// comments that starts no token, a byte of UTF-8 among them), a string not closed on its line,
/// a block comment, a hexadecimal or binary number, a number with an exponent or of more than
/// 300 characters (which could be too large). `cut`: the codes were cut at kMaxTokens.
class QuickScan {
 public:
  explicit QuickScan(Words& words) : words_(words) {}
  /// `lines`, when given: each code's line (1-based), as the lexer numbers them.
  bool codes(std::string_view text, std::vector<uint32_t>& out, bool& cut, std::vector<uint32_t>* lines = nullptr) {
    out.clear();
    if (lines) lines->clear();
    cut = false;
    const char* p = text.data();
    const char* const end = p + text.size();
    uint32_t lineNo = 1;
    // A line at a time: its codes depend on its own characters alone (nothing the quick scan
    // reads goes past a line's end), so a line seen before, in this program or another (a
    // class shares most of its lines), gives the codes it gave then.
    while (p < end) {
      const void* nl = std::memchr(p, '\n', static_cast<size_t>(end - p));
      const char* lineEnd = nl ? static_cast<const char*>(nl) : end;
      const std::string_view text1(p, static_cast<size_t>(lineEnd - p));
      const size_t before = out.size();
      if (!memo_.find(text1, out)) {
        if (!line(p, lineEnd, out)) return false;
        memo_.add(text1, out.data() + before, out.size() - before);
      }
      if (lines) lines->resize(out.size(), lineNo);
      if (out.size() >= kMaxTokens) {  // as the lexer's reading stops: after the line
        out.resize(kMaxTokens);
        if (lines) lines->resize(kMaxTokens);
        cut = true;
        return true;
      }
      p = lineEnd + (nl ? 1 : 0);
      ++lineNo;
    }
    return true;
  }

 private:
  /// The codes of the line [p, lineEnd) appended to `out`; false when it holds anything the
  /// quick scan leaves to the lexer.
  bool line(const char* p, const char* const lineEnd, std::vector<uint32_t>& out) {
    line_.count = 0;
    auto token = [this](Tok kind, const Words::Info& info = Words::Info{}) {
      if (line_.count == line_.items.size()) line_.items.resize(std::max<size_t>(64, line_.count * 2));
      line_.items[line_.count++] = {kind, info};
    };
    auto digit = [](char c) { return c >= '0' && c <= '9'; };
    // The character `ahead` of p, or '\n' at the line's end (as the lexer sees it there) and
    // NUL past it.
    auto next = [&](ptrdiff_t ahead) { return lineEnd - p > ahead ? p[ahead] : lineEnd - p == ahead ? '\n' : '\0'; };
    auto one = [&](Tok kind) {
      token(kind);
      ++p;
    };
    auto two = [&](Tok kind) {
      token(kind);
      p += 2;
    };
    while (p < lineEnd) {
      const char c = *p;
      switch (c) {
        case ' ': case '\t': case '\r': case '\f': case '\v': ++p; continue;
        case '\'': p = lineEnd; continue;
        case '/':
          if (next(1) == '/') {
            p = lineEnd;
            continue;
          }
          if (next(1) == '*') return false;
          if (next(1) == '=') two(Tok::SlashAssign);
          else one(Tok::Slash);
          continue;
        case '"': {
          const char* q = p + 1;
          while (q < lineEnd && *q != '"') ++q;
          if (q == lineEnd) return false;  // not closed on its line
          token(Tok::String);
          p = q + 1;
          continue;
        }
        default:
          if (const OperatorToken t = operatorAt(c, next(1)); t.length != 0) {
            if (t.length == 2) two(t.kind);
            else one(t.kind);
            continue;
          }
          break;
      }
      if (digit(c) || (c == '.' && digit(next(1)))) {
        if (c == '0') {
          const char n = next(1), n2 = next(2);
          if ((n == 'x' || n == 'X') && std::isxdigit(static_cast<unsigned char>(n2))) return false;
          if (n == '%' && (n2 == '0' || n2 == '1')) return false;
        }
        const char* q = p;
        while (q < lineEnd && digit(*q)) ++q;
        if (q < lineEnd && *q == '.') {
          ++q;
          while (q < lineEnd && digit(*q)) ++q;
        }
        if (q < lineEnd && (*q == 'e' || *q == 'E')) {
          const char* r = q + 1;
          if (r < lineEnd && (*r == '+' || *r == '-')) ++r;
          if (r < lineEnd && digit(*r)) return false;  // an exponent: "2e" alone is 2 and the name e
        }
        if (q - p > 300) return false;
        token(Tok::Int);  // Int or Float: the same code
        p = q;
        continue;
      }
      if ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_') {
        uint64_t h = 0xcbf29ce484222325ull;  // spellingHash, as the word is read
        const char* q = p;
        do h = (h ^ static_cast<unsigned char>(*q)) * 0x100000001b3ull;
        while (++q < lineEnd && kWordByte[static_cast<unsigned char>(*q)]);
        const Words::Info& info = words_.of(std::string_view(p, static_cast<size_t>(q - p)), h);
        p = q;
        if (info.rem) {  // a remark runs to the end of the line
          p = lineEnd;
          continue;
        }
        token(info.kind, info);
        continue;
      }
      return false;  // a character the lexer reports
    }
    token(Tok::Newline);
    auto infoOf = [this](size_t i) -> const Words::Info& { return line_.items[i].info; };
    normaliseLine(line_, infoOf, [&out](uint32_t code, size_t) { out.push_back(code); });
    return true;
  }

  struct Quick {
    Tok kind = Tok::Eof;
    Words::Info info;  ///< of a word (a copy: the table may start afresh within a line)
  };
  /// The line's tokens so far (its items are kept from line to line).
  struct Line {
    std::vector<Quick> items;
    size_t count = 0;
    size_t size() const { return count; }
    const Quick& operator[](size_t i) const { return items[i]; }
  };

  /// Lines seen and their codes, up to a few megabytes (then it starts afresh).
  class Memo {
   public:
    Memo() : slots_(1024) {}
    bool find(std::string_view line, std::vector<uint32_t>& out) const {
      const uint64_t h = hashOf(line);
      const size_t mask = slots_.size() - 1;
      for (size_t i = slotOf(h);; i = (i + 1) & mask) {
        const Slot& s = slots_[i];
        if (!s.used) return false;
        if (s.hash == h && s.length == line.size() && std::memcmp(text_.data() + s.text, line.data(), line.size()) == 0) {
          out.insert(out.end(), codes_.begin() + s.codes, codes_.begin() + s.codes + s.count);
          return true;
        }
      }
    }
    void add(std::string_view line, const uint32_t* codes, size_t count) {
      if (line.size() > kLongest || count > kLongest) return;
      if (text_.size() + line.size() > kMostText || codes_.size() + count > kMostCodes) clear();
      if ((used_ + 1) * 2 > slots_.size()) grow();
      const uint64_t h = hashOf(line);
      const size_t mask = slots_.size() - 1;
      size_t i = slotOf(h);
      while (slots_[i].used) i = (i + 1) & mask;
      slots_[i] = {true, h, static_cast<uint32_t>(text_.size()), static_cast<uint32_t>(line.size()),
                   static_cast<uint32_t>(codes_.size()), static_cast<uint32_t>(count)};
      text_.append(line);
      codes_.insert(codes_.end(), codes, codes + count);
      ++used_;
    }

   private:
    static constexpr size_t kLongest = 4096, kMostText = size_t{1} << 20, kMostCodes = size_t{1} << 18;
    struct Slot {
      bool used = false;
      uint64_t hash = 0;
      uint32_t text = 0, length = 0, codes = 0, count = 0;
    };
    static uint64_t hashOf(std::string_view s) {
      uint64_t h = s.size() * 0x9E3779B97F4A7C15ull;
      size_t i = 0;
      for (; i + 8 <= s.size(); i += 8) {
        uint64_t w;
        std::memcpy(&w, s.data() + i, 8);
        h = (h ^ w) * 0xbf58476d1ce4e5b9ull;
        h ^= h >> 29;
      }
      for (; i < s.size(); ++i) h = (h ^ static_cast<unsigned char>(s[i])) * 0x100000001b3ull;
      return h ^ (h >> 32);
    }
    size_t slotOf(uint64_t h) const {
      return static_cast<size_t>((h * 0x9E3779B97F4A7C15ull) >> (64 - std::countr_zero(slots_.size())));
    }
    void grow() {
      std::vector<Slot> old = std::move(slots_);
      slots_.assign(old.size() * 2, Slot{});
      const size_t mask = slots_.size() - 1;
      for (const Slot& o : old)
        if (o.used) {
          size_t i = slotOf(o.hash);
          while (slots_[i].used) i = (i + 1) & mask;
          slots_[i] = o;
        }
    }
    void clear() {
      slots_.assign(1024, Slot{});
      text_.clear();
      codes_.clear();
      used_ = 0;
    }
    std::vector<Slot> slots_;
    std::string text_;
    std::vector<uint32_t> codes_;
    size_t used_ = 0;
  };

  Words& words_;
  Line line_;
  Memo memo_;
};

/// Reads, decodes and lexes one file into normalised tokens (by the quick scan where it can,
/// else by rb's lexer: the same tokens); keeps its text when `keepText`.
Lexed lexProgram(const std::string& path, bool keepText, const SimilarityOptions& options, Words& words) {
  Lexed r;
  std::string text;
  if (!programText(path, options, text, r.cuts, r.skip)) return r;
  QuickScan quick(words);
  std::vector<uint32_t> codes, lines;
  bool cut = false;
  if (!quick.codes(text, codes, cut, &lines)) {
    lexText(path, std::move(text), keepText, words, r);
    return r;
  }
  if (cut) r.cuts.push_back(kTokensCut);
  r.tokens.resize(codes.size());
  for (size_t i = 0; i < codes.size(); ++i) r.tokens[i] = {codes[i], lines[i]};
  if (keepText) {
    r.sources = std::make_unique<SourceSet>();
    r.sources->add(path, std::move(text));
  }
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
/// next), finished so that the hashes look random to winnowing's minimum. `code(i)` is token i's.
template <class Code>
void kgramHashesInto(size_t tokens, Code code, size_t k, std::vector<uint64_t>& out) {
  out.clear();
  if (tokens < k) return;
  constexpr uint64_t kBase = 0x100000001b3ull;  // odd
  uint64_t top = 1;                             // kBase^(k-1)
  for (size_t j = 1; j < k; ++j) top *= kBase;
  out.resize(tokens - k + 1);
  uint64_t h = 0;
  for (size_t j = 0; j < k; ++j) h = h * kBase + code(j);
  out[0] = finish(h);
  for (size_t p = 1; p < out.size(); ++p) {
    h = (h - top * code(p - 1)) * kBase + code(p + k - 1);
    out[p] = finish(h);
  }
}

std::vector<uint64_t> kgramHashes(const std::vector<NormToken>& t, size_t k) {
  std::vector<uint64_t> out;
  kgramHashesInto(t.size(), [&t](size_t i) { return t[i].code; }, k, out);
  return out;
}

struct Fingerprint {
  uint64_t hash;
  uint32_t pos;  ///< the k-gram's first token
};

/// Robust winnowing: the minimum of every window of w hashes (the rightmost of equal ones),
/// each selected position once, in order: select(position). The windows' minima come from
/// blocks of w hashes (van Herk, Gil and Werman): a window is the end of one block and the
/// start of the next, so its minimum is the smaller of the block's minimum from the window's
/// start on and the next block's up to the window's end, found without a branch the random
/// hashes would make unpredictable. `from`, `upTo`: room for those, reused.
template <class Select>
void winnowInto(const std::vector<uint64_t>& h, size_t w, std::vector<uint32_t>& from, std::vector<uint32_t>& upTo,
                Select&& select) {
  const size_t n = h.size();
  if (n == 0) return;
  w = std::min(w, n);
  from.resize(n);
  upTo.resize(n);
  // Within each block: from[i], the rightmost minimum of h[i .. block end]; upTo[i], of
  // h[block start .. i].
  for (size_t start = 0; start < n; start += w) {
    const size_t last = std::min(start + w, n) - 1;
    uint32_t m = static_cast<uint32_t>(last);
    from[last] = m;
    for (size_t i = last; i-- > start;) {
      m = h[i] < h[m] ? static_cast<uint32_t>(i) : m;
      from[i] = m;
    }
    m = static_cast<uint32_t>(start);
    upTo[start] = m;
    for (size_t i = start + 1; i <= last; ++i) {
      m = h[i] <= h[m] ? static_cast<uint32_t>(i) : m;
      upTo[i] = m;
    }
  }
  size_t chosen = std::numeric_limits<size_t>::max();
  for (size_t s = 0; s + w <= n; ++s) {
    const uint32_t a = from[s], b = upTo[s + w - 1];  // b is a or right of it
    const size_t m = h[b] <= h[a] ? b : a;
    if (m != chosen) {
      chosen = m;
      select(m);
    }
  }
}

std::vector<Fingerprint> winnow(const std::vector<uint64_t>& h, size_t w) {
  std::vector<Fingerprint> out;
  std::vector<uint32_t> from, upTo;
  winnowInto(h, w, from, upTo, [&](size_t p) { out.push_back({h[p], static_cast<uint32_t>(p)}); });
  return out;
}

/// A set of hashes (a template's k-grams, a program's fingerprints while they are made
/// distinct): open addressing in a power-of-two table. A hash is its own slot's key (they look
/// random); 0 is kept aside, since it marks an empty slot.
class HashSet {
 public:
  void clear(size_t expected) {
    size_t want = 16;
    while (want < expected * 2) want *= 2;
    if (slots_.size() != want) slots_.assign(want, 0);
    else std::fill(slots_.begin(), slots_.end(), 0);
    zero_ = false;
  }
  /// True when h was not in the set yet (and is now). The set holds at most half its slots.
  bool insert(uint64_t h) {
    if (h == 0) return !std::exchange(zero_, true);
    const size_t mask = slots_.size() - 1;
    for (size_t i = static_cast<size_t>(h) & mask;; i = (i + 1) & mask) {
      if (slots_[i] == h) return false;
      if (slots_[i] == 0) {
        slots_[i] = h;
        return true;
      }
    }
  }
  bool contains(uint64_t h) const {
    if (h == 0) return zero_;
    if (slots_.empty()) return false;
    const size_t mask = slots_.size() - 1;
    for (size_t i = static_cast<size_t>(h) & mask;; i = (i + 1) & mask) {
      if (slots_[i] == h) return true;
      if (slots_[i] == 0) return false;
    }
  }

 private:
  std::vector<uint64_t> slots_;
  bool zero_ = false;
};

/// Which fingerprints more than one program has, and how many programs have each, found in one
/// reading of the class without keeping every program's fingerprints as they are (a class of
/// 2,000 programs of 10,000 lines has 27 million, most of them a program's own or the whole
/// class's).
///
/// Each program's distinct hashes are given once. A hash met for the first time goes into a
/// Bloom filter, and the program keeps the hash itself (its `first` list). A hash met again (the
/// filter holds it) gets a number in an exact table, counted from there, and the program keeps
/// only the number (its `again` list). A filter never misses a hash it holds, so only a hash's
/// first meeting ever goes to a `first` list; one that only seemed held goes to the table at
/// once (about 1% of first meetings). After the reading, the `first` hashes found in the table
/// are counted too: the counts are then exact, and a `first` hash not in the table is in one
/// program only.
///
/// The hashes are split by their top bits into shards, each with its own lock, filter and
/// table, so that threads rarely wait for one another and a table grows a little at a time.
class ClassHashes {
 public:
  static constexpr int kShardBits = 6;
  static constexpr size_t kShards = size_t{1} << kShardBits;
  static size_t shardOf(uint64_t h) { return static_cast<size_t>(h >> (64 - kShardBits)); }

  ClassHashes() : shards_(kShards) {}

  /// The hashes of shard s of one program, each once: the numbers of those met before (or
  /// seemingly) go to `again`, the others to `first`.
  void add(size_t s, const uint64_t* hashes, size_t n, std::vector<uint32_t>& again, std::vector<uint64_t>& first) {
    Shard& shard = shards_[s];
    std::lock_guard<std::mutex> lock(shard.mutex);
    // Each hash is a cache miss or two in the table and the filter: asked for a few hashes
    // ahead, they come in together.
    constexpr size_t kAhead = 8;
    for (size_t i = 0; i < std::min(n, kAhead); ++i) shard.prefetch(hashes[i]);
    for (size_t i = 0; i < n; ++i) {
      if (i + kAhead < n) shard.prefetch(hashes[i + kAhead]);
      const uint64_t h = hashes[i];
      // The filter first: a hash met for the first time (most of them) is not looked for in
      // the table at all.
      if (!shard.filterHas(h)) {
        shard.filterAdd(h);
        first.push_back(h);
        continue;
      }
      uint32_t local = shard.find(h);
      if (local != kNone) ++shard.counts[local];
      else local = shard.insert(h);
      again.push_back(static_cast<uint32_t>(local << kShardBits | s));
    }
  }

  /// After the reading: the filters go; the counts so far, by number (numbers run below
  /// numbers()).
  std::vector<uint32_t> freeze() {
    size_t most = 0;
    for (Shard& shard : shards_) {
      shard.filters = {};
      most = std::max(most, shard.counts.size());
    }
    if (most > (size_t{1} << (32 - kShardBits))) throw std::length_error("too many shared fingerprints to compare");
    std::vector<uint32_t> counts(most << kShardBits, 0);
    for (size_t s = 0; s < kShards; ++s)
      for (size_t local = 0; local < shards_[s].counts.size(); ++local) counts[local << kShardBits | s] = shards_[s].counts[local];
    return counts;
  }
  /// After freeze(), from any thread: the number of h, or kNone when no program met it again.
  uint32_t find(uint64_t h) const {
    const size_t s = shardOf(h);
    const uint32_t local = shards_[s].find(h);
    return local == kNone ? kNone : static_cast<uint32_t>(local << kShardBits | s);
  }
  /// Every hash in the table, with its number.
  template <class F>
  void forEach(F&& f) const {
    for (size_t s = 0; s < kShards; ++s)
      for (const Slot& slot : shards_[s].slots)
        if (slot.local != kNone) f(slot.hash, static_cast<uint32_t>(slot.local << kShardBits | s));
  }
  static constexpr uint32_t kNone = UINT32_MAX;

 private:
  struct Slot {
    uint64_t hash;
    uint32_t local;  ///< its number in the shard; kNone: an empty slot
  };

  /// A Bloom filter in blocks of one cache line: six bits of one block for each hash.
  struct Filter {
    std::vector<uint64_t> words;  ///< 8 a block
    size_t capacity = 0, held = 0;
    size_t block(uint64_t h) const {
      const uint64_t m = h * 0x9E3779B97F4A7C15ull;
      return static_cast<size_t>(((m >> 32) * (words.size() / 8)) >> 32) * 8;
    }
    // The block from the hash multiplied (its top bits), the six bits of the block from the
    // hash's own lowest 54 bits, nine at a time.
    bool has(uint64_t h) const {
      const uint64_t* b = words.data() + block(h);
      for (int k = 0; k < 6; ++k) {
        const unsigned bit = static_cast<unsigned>(h >> (k * 9)) & 511;
        if (!(b[bit >> 6] >> (bit & 63) & 1)) return false;
      }
      return true;
    }
    void add(uint64_t h) {
      uint64_t* b = words.data() + block(h);
      for (int k = 0; k < 6; ++k) {
        const unsigned bit = static_cast<unsigned>(h >> (k * 9)) & 511;
        b[bit >> 6] |= uint64_t{1} << (bit & 63);
      }
      ++held;
    }
  };

  struct Shard {
    std::mutex mutex;
    /// Filters of growing size (a full one stays, for what it holds): 10 bits a hash.
    std::vector<Filter> filters;
    std::vector<Slot> slots;
    std::vector<uint32_t> counts;  ///< by number

    bool filterHas(uint64_t h) const {
      for (const Filter& f : filters)
        if (f.has(h)) return true;
      return false;
    }
    void prefetch(uint64_t h) const {
      if (!slots.empty()) __builtin_prefetch(&slots[static_cast<size_t>(h) & (slots.size() - 1)]);
      for (const Filter& f : filters) __builtin_prefetch(f.words.data() + f.block(h));
    }
    void filterAdd(uint64_t h) {
      if (filters.empty() || filters.back().held >= filters.back().capacity) {
        Filter f;
        f.capacity = filters.empty() ? 16384 : filters.back().capacity * 8;
        f.words.assign((f.capacity * 10 / 512 + 1) * 8, 0);
        filters.push_back(std::move(f));
      }
      filters.back().add(h);
    }
    uint32_t find(uint64_t h) const {
      if (slots.empty()) return kNone;
      const size_t mask = slots.size() - 1;
      for (size_t i = static_cast<size_t>(h) & mask;; i = (i + 1) & mask) {
        if (slots[i].local == kNone) return kNone;
        if (slots[i].hash == h) return slots[i].local;
      }
    }
    /// A new number for h, met once now.
    uint32_t insert(uint64_t h) {
      if ((counts.size() + 1) * 4 > slots.size() * 3) grow();
      const size_t mask = slots.size() - 1;
      size_t i = static_cast<size_t>(h) & mask;
      while (slots[i].local != kNone) i = (i + 1) & mask;
      slots[i] = {h, static_cast<uint32_t>(counts.size())};
      counts.push_back(1);
      return slots[i].local;
    }
    void grow() {
      std::vector<Slot> old = std::move(slots);
      slots.assign(old.empty() ? 1024 : old.size() * 2, Slot{0, kNone});
      const size_t mask = slots.size() - 1;
      for (const Slot& o : old)
        if (o.local != kNone) {
          size_t i = static_cast<size_t>(o.hash) & mask;
          while (slots[i].local != kNone) i = (i + 1) & mask;
          slots[i] = o;
        }
    }
  };
  std::vector<Shard> shards_;
};

/// Ascending numbers, each as its difference from the one before in 7-bit groups (the low
/// first, the high bit set on all but the last): a program's table numbers in a byte or two
/// each, where 4 would be most of the class's memory.
void packAscending(const std::vector<uint32_t>& sorted, std::vector<uint8_t>& out) {
  out.clear();
  uint32_t before = 0;
  for (uint32_t v : sorted) {
    uint32_t d = v - before;
    before = v;
    while (d >= 0x80) {
      out.push_back(static_cast<uint8_t>(d | 0x80));
      d >>= 7;
    }
    out.push_back(static_cast<uint8_t>(d));
  }
}
/// Sorts `v` (LSD radix, 11 bits a pass, as many passes as its largest number needs), with
/// `tmp` for room: the lists of table numbers are long, and std::sort spent more on them than
/// on reading the programs.
void sortNumbers(std::vector<uint32_t>& v, std::vector<uint32_t>& tmp) {
  uint32_t most = 0;
  for (uint32_t x : v) most |= x;
  tmp.resize(v.size());
  for (int shift = 0; shift < 32 && (most >> shift) != 0; shift += 11) {
    uint32_t counts[2049] = {};
    for (uint32_t x : v) ++counts[((x >> shift) & 2047) + 1];
    for (size_t b = 1; b <= 2048; ++b) counts[b] += counts[b - 1];
    for (uint32_t x : v) tmp[counts[(x >> shift) & 2047]++] = x;
    v.swap(tmp);
  }
}

template <class F>
void unpackAscending(const std::vector<uint8_t>& in, F&& f) {
  uint32_t v = 0;
  for (size_t i = 0; i < in.size();) {
    uint32_t d = 0;
    int shift = 0;
    uint8_t b;
    do {
      b = in[i++];
      d |= static_cast<uint32_t>(b & 0x7F) << shift;
      shift += 7;
    } while (b & 0x80);
    v += d;
    f(v);
  }
}

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
/// `printsA`, `printsB`: the programs' fingerprints in order of position, without the ignored
/// files' hashes; `counted(hash)`: whether a hash counts (it is not boilerplate).
template <class Counted>
std::vector<SharedBlock> findBlocks(const std::vector<Fingerprint>& printsA, const std::vector<Fingerprint>& printsB,
                                    const Lexed& la, const Lexed& lb, Counted&& counted,
                                    const std::vector<uint64_t>& ignored, size_t k, size_t w) {
  std::vector<Fingerprint> inB;
  for (const Fingerprint& f : printsB)
    if (counted(f.hash)) inB.push_back(f);
  std::sort(inB.begin(), inB.end(), [](const Fingerprint& x, const Fingerprint& y) {
    return x.hash != y.hash ? x.hash < y.hash : x.pos < y.pos;
  });
  std::vector<Match> matches;
  for (const Fingerprint& f : printsA) {
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

/// The few programs' tokens, text and fingerprints that blocks are being found for, read again.
class LexedCache {
 public:
  struct Entry {
    Lexed lexed;
    std::vector<Fingerprint> prints;  ///< without the ignored files' hashes
  };
  /// The program read again, or as read for the last pairs. A reference stays valid until the
  /// cache has been asked for 8 other programs (the one asked for moves to the back; the front
  /// is forgotten first).
  LexedCache(const SimilarityOptions& options, const HashSet& ignored, size_t k, size_t w)
      : options_(options), ignored_(ignored), k_(k), w_(w), words_(standardBuiltins()) {}
  const Entry& get(uint32_t program, const std::string& path) {
    for (size_t i = 0; i < items_.size(); ++i) {
      if (items_[i].first != program) continue;
      std::rotate(items_.begin() + static_cast<ptrdiff_t>(i), items_.begin() + static_cast<ptrdiff_t>(i) + 1,
                  items_.end());
      return *items_.back().second;
    }
    if (items_.size() >= 8) items_.erase(items_.begin());
    auto e = std::make_unique<Entry>();
    e->lexed = lexProgram(path, true, options_, words_);
    if (e->lexed.skip.empty()) {
      e->prints = winnow(kgramHashes(e->lexed.tokens, k_), w_);
      std::erase_if(e->prints, [&](const Fingerprint& f) { return ignored_.contains(f.hash); });
    }
    items_.emplace_back(program, std::move(e));
    return *items_.back().second;
  }

 private:
  const SimilarityOptions& options_;
  const HashSet& ignored_;
  size_t k_, w_;
  Words words_;
  std::vector<std::pair<uint32_t, std::unique_ptr<Entry>>> items_;
};

/// Runs work(item, worker) for items 0..count-1 on `threads` threads (the calling one among
/// them), each item once, any item on any thread; the first exception is thrown again here.
template <class Work>
void inParallel(size_t count, size_t threads, Work&& work) {
  std::atomic<size_t> next{0};
  std::exception_ptr failed;
  std::mutex failure;
  auto run = [&](size_t worker) {
    try {
      for (size_t i; (i = next.fetch_add(1, std::memory_order_relaxed)) < count;) work(i, worker);
    } catch (...) {
      std::lock_guard<std::mutex> lock(failure);
      if (!failed) failed = std::current_exception();
      next.store(count, std::memory_order_relaxed);
    }
  };
  std::vector<std::thread> others;
  for (size_t t = 1; t < threads; ++t) others.emplace_back(run, t);
  run(0);
  for (std::thread& t : others) t.join();
  if (failed) std::rethrow_exception(failed);
}

/// Gives the memory freed so far back to the system: the programs' first hashes and the table
/// were many small blocks among those still in use, which the heap would otherwise keep.
void releaseFreedMemory() {
#ifdef __GLIBC__
  malloc_trim(0);
#endif
}

/// What a worker thread keeps from one program to the next.
struct Worker {
  explicit Worker(const BuiltinTable& builtins) : words(builtins), quick(words) {}
  Words words;
  QuickScan quick;
  std::string text;
  std::vector<std::string> cuts;
  std::vector<uint32_t> codes, from, upTo;
  std::vector<uint64_t> hashes, distinct, byShard;
  HashSet seen;
  Lexed lexed;
};

/// One program as the reading sees it.
struct Program {
  std::string path;
  bool compared = false;  ///< read and long enough (else `skip` says why)
  std::string skip;
  std::vector<std::string> cuts;
  uint32_t tokens = 0;
  uint32_t distinct = 0;  ///< distinct fingerprints (without the ignored files')
  std::vector<uint64_t> first;  ///< the hashes it met first (ClassHashes)
  /// The table numbers of its fingerprints that other programs have too (packAscending).
  std::vector<uint8_t> shared;
  uint32_t unique = 0;    ///< fingerprints no other program has
  size_t counted = 0;     ///< fingerprints that count (not boilerplate)
};

/// The program's distinct fingerprints (in w.distinct, grouped by shard: ClassHashes), from its
/// text read and normalised; false, with p.skip or p.cuts set, when it cannot be compared.
bool fingerprints(Program& p, const SimilarityOptions& options, const HashSet& ignored, size_t k, size_t wnd,
                  Worker& w) {
  w.cuts.clear();
  std::string skip;
  if (!programText(p.path, options, w.text, w.cuts, skip)) {
    p.skip = skip;
    return false;
  }
  bool tokensCut = false;
  size_t tokens = 0;
  if (w.quick.codes(w.text, w.codes, tokensCut)) {
    tokens = w.codes.size();
    kgramHashesInto(tokens, [&w](size_t i) { return w.codes[i]; }, k, w.hashes);
    if (tokensCut) w.cuts.push_back(kTokensCut);
  } else {  // what the quick scan leaves to the lexer
    w.lexed = Lexed{};
    lexText(p.path, std::move(w.text), false, w.words, w.lexed);
    if (!w.lexed.skip.empty()) {
      p.skip = w.lexed.skip;
      return false;
    }
    w.cuts.insert(w.cuts.end(), w.lexed.cuts.begin(), w.lexed.cuts.end());
    tokens = w.lexed.tokens.size();
    kgramHashesInto(tokens, [&w](size_t i) { return w.lexed.tokens[i].code; }, k, w.hashes);
  }
  if (tokens < k) {
    p.skip = "too short to compare (" + std::to_string(tokens) + " tokens; it takes " + std::to_string(k) + ")";
    return false;
  }
  p.tokens = static_cast<uint32_t>(tokens);
  // The winnowed hashes, each once, without the template's, grouped by shard.
  w.seen.clear(w.hashes.size() * 2 / (wnd + 1) + 16);
  w.distinct.clear();
  winnowInto(w.hashes, wnd, w.from, w.upTo, [&](size_t at) {
    const uint64_t h = w.hashes[at];
    if (!ignored.contains(h) && w.seen.insert(h)) w.distinct.push_back(h);
  });
  size_t counts[ClassHashes::kShards + 1] = {};
  for (uint64_t h : w.distinct) ++counts[ClassHashes::shardOf(h) + 1];
  for (size_t s = 1; s <= ClassHashes::kShards; ++s) counts[s] += counts[s - 1];
  w.byShard.resize(w.distinct.size());
  for (uint64_t h : w.distinct) w.byShard[counts[ClassHashes::shardOf(h)]++] = h;
  std::swap(w.distinct, w.byShard);
  return true;
}

}  // namespace

SimilarityReport findSimilar(const std::vector<std::string>& paths, const SimilarityOptions& options) {
  SimilarityReport report;
  report.minScore = options.minScore;
  const size_t k = std::max<size_t>(options.k, 1);
  const size_t w = std::max<size_t>(options.window, 1);
  const BuiltinTable& builtins = standardBuiltins();

  // The template's k-grams, every one of them.
  std::vector<uint64_t> ignored;
  std::vector<fs::path> ignoredFiles;
  {
    Words words(builtins);
    for (const std::string& path : options.ignore) {
      Lexed lexed = lexProgram(path, false, options, words);
      if (!lexed.skip.empty()) {
        report.notes.push_back(path + ": not used as a template: " + lexed.skip);
        continue;
      }
      std::vector<uint64_t> h = kgramHashes(lexed.tokens, k);
      ignored.insert(ignored.end(), h.begin(), h.end());
      ignoredFiles.emplace_back(path);
    }
  }
  std::sort(ignored.begin(), ignored.end());
  ignored.erase(std::unique(ignored.begin(), ignored.end()), ignored.end());
  HashSet ignoredSet;
  ignoredSet.clear(ignored.size());
  for (uint64_t h : ignored) ignoredSet.insert(h);

  std::vector<Program> programs(paths.size());
  for (size_t i = 0; i < paths.size(); ++i) {
    programs[i].path = paths[i];
    bool isTemplate = false;
    for (const fs::path& t : ignoredFiles) {
      std::error_code ec;
      isTemplate = isTemplate || fs::equivalent(t, paths[i], ec);
    }
    if (isTemplate) programs[i].skip = "it is one of the ignored files (the template)";
  }
  size_t threads = options.threads ? options.threads : std::max(1u, std::thread::hardware_concurrency());
  threads = std::clamp<size_t>(threads, 1, std::min<size_t>(16, std::max<size_t>(paths.size(), 1)));
  std::vector<std::unique_ptr<Worker>> workers;
  for (size_t t = 0; t < threads; ++t) workers.push_back(std::make_unique<Worker>(builtins));

  // The reading: every program's fingerprints into the class's table.
  ClassHashes table;
  struct Scratch {
    std::vector<uint32_t> again, more, tmp;
  };
  std::vector<Scratch> scratch(threads);
  inParallel(programs.size(), threads, [&](size_t i, size_t t) {
    Program& p = programs[i];
    if (!p.skip.empty()) return;
    Worker& wk = *workers[t];
    const bool ok = fingerprints(p, options, ignoredSet, k, w, wk);
    p.cuts = wk.cuts;
    if (!ok) return;
    p.compared = true;
    p.distinct = static_cast<uint32_t>(wk.distinct.size());
    std::vector<uint32_t>& again = scratch[t].again;
    again.clear();
    for (size_t at = 0; at < wk.distinct.size();) {
      const size_t s = ClassHashes::shardOf(wk.distinct[at]);
      size_t end = at;
      while (end < wk.distinct.size() && ClassHashes::shardOf(wk.distinct[end]) == s) ++end;
      table.add(s, wk.distinct.data() + at, end - at, again, p.first);
      at = end;
    }
    p.first.shrink_to_fit();
    sortNumbers(again, scratch[t].tmp);
    packAscending(again, p.shared);
    p.shared.shrink_to_fit();
  });
  size_t n = 0;
  for (const Program& p : programs) {
    if (!p.compared) {
      report.notes.push_back(p.path + ": skipped: " + p.skip);
      ++report.skipped;
      continue;
    }
    for (const std::string& cut : p.cuts) report.notes.push_back(p.path + ": " + cut);
    ++n;
  }
  report.programs = n;
  // Boilerplate: in more than commonShare of the programs compared, and in commonMinPrograms.
  const double commonAbove = options.commonShare * static_cast<double>(n);
  auto common = [&](uint64_t have) {
    return have >= options.commonMinPrograms && static_cast<double>(have) > commonAbove;
  };

  // The hashes each program met first: counted where another program met them again.
  std::vector<uint32_t> count = table.freeze();
  inParallel(programs.size(), threads, [&](size_t i, size_t t) {
    Program& p = programs[i];
    if (!p.compared) return;
    Scratch& sc = scratch[t];
    std::vector<uint32_t>& found = sc.more;
    found.clear();
    for (uint64_t h : p.first) {
      const uint32_t id = table.find(h);
      if (id == ClassHashes::kNone) {
        ++p.unique;
        continue;
      }
      std::atomic_ref<uint32_t>(count[id]).fetch_add(1, std::memory_order_relaxed);
      found.push_back(id);
    }
    std::vector<uint64_t>().swap(p.first);
    if (found.empty()) return;
    sortNumbers(found, sc.tmp);
    sc.again.clear();
    unpackAscending(p.shared, [&sc](uint32_t id) { sc.again.push_back(id); });
    sc.tmp.resize(sc.again.size() + found.size());
    std::merge(sc.again.begin(), sc.again.end(), found.begin(), found.end(), sc.tmp.begin());
    packAscending(sc.tmp, p.shared);
    p.shared.shrink_to_fit();
  });
  // What is boilerplate, for the blocks; then the table goes.
  HashSet commonHashes;
  {
    std::vector<uint64_t> found;
    table.forEach([&](uint64_t h, uint32_t id) {
      if (common(count[id])) found.push_back(h);
    });
    commonHashes.clear(found.size());
    for (uint64_t h : found) commonHashes.insert(h);
    report.common = found.size();
    table = ClassHashes();
  }
  releaseFreedMemory();
  size_t uniques = 0;
  for (const Program& p : programs) uniques += p.unique;
  if (common(1)) report.common += uniques;

  // Groups: the hashes of two programs or more that are not boilerplate, each with its
  // programs in order.
  std::vector<uint32_t> start(count.size(), 0);
  size_t postings = 0;
  for (uint32_t id = 0; id < count.size(); ++id)
    if (count[id] >= 2 && !common(count[id])) {
      start[id] = static_cast<uint32_t>(postings);
      postings += count[id];
    }
  if (postings >= UINT32_MAX) throw std::length_error("too many shared fingerprints to compare");
  std::vector<uint32_t> members(postings);
  {
    std::vector<uint32_t> next = start;
    size_t empty = 0;
    for (uint32_t i = 0; i < programs.size(); ++i) {
      Program& p = programs[i];
      if (!p.compared) continue;
      p.counted = common(1) ? 0 : p.unique;
      unpackAscending(p.shared, [&](uint32_t id) {
        const uint32_t c = count[id];
        if (common(c)) return;
        ++p.counted;
        members[next[id]++] = i;
      });
      if (p.counted == 0) ++empty;
    }
    if (empty > 0)
      report.notes.push_back(
          std::to_string(empty) + (empty == 1 ? " program has" : " programs have") +
          " no code of its own to compare: all of it is in the template or common to most programs");
  }
  std::vector<uint32_t> compared;  // the programs' numbers, in order
  for (uint32_t i = 0; i < programs.size(); ++i)
    if (programs[i].compared) compared.push_back(i);

  // Each program against the later ones that share a counted hash with it.
  auto better = [&](const Candidate& x, const Candidate& y) {
    if (x.score != y.score) return x.score > y.score;
    if (x.shared != y.shared) return x.shared > y.shared;
    const std::string& xa = programs[x.a].path;
    const std::string& ya = programs[y.a].path;
    if (xa != ya) return xa < ya;
    return programs[x.b].path < programs[y.b].path;
  };
  const size_t limit = options.maxPairs;
  struct Tally {
    std::vector<uint32_t> count, touched;
    std::vector<Candidate> kept;
    size_t matching = 0;
  };
  std::vector<Tally> tallies(threads);
  for (Tally& t : tallies) t.count.assign(programs.size(), 0);
  inParallel(compared.size(), threads, [&](size_t c, size_t t) {
    const uint32_t i = compared[c];
    Tally& tally = tallies[t];
    unpackAscending(programs[i].shared, [&](uint32_t id) {
      const uint32_t have = count[id];
      if (have < 2 || common(have)) return;
      const uint32_t* group = members.data() + start[id];
      // The later programs of the group (it lists them in order).
      for (const uint32_t* q = std::upper_bound(group, group + have, i); q != group + have; ++q)
        if (tally.count[*q]++ == 0) tally.touched.push_back(*q);
    });
    for (uint32_t j : tally.touched) {
      uint32_t shared = tally.count[j];
      tally.count[j] = 0;
      double si = double(shared) / double(programs[i].counted);
      double sj = double(shared) / double(programs[j].counted);
      double score = std::max(si, sj);
      if (score < options.minScore || shared < options.minShared) continue;
      ++tally.matching;
      tally.kept.push_back({i, j, shared, score});
      if (limit > 0 && tally.kept.size() >= 2 * limit + 1024) {
        std::nth_element(tally.kept.begin(), tally.kept.begin() + static_cast<ptrdiff_t>(limit), tally.kept.end(),
                         better);
        tally.kept.resize(limit);
      }
    }
    tally.touched.clear();
  });
  std::vector<Candidate> kept;
  for (Tally& t : tallies) {
    report.matching += t.matching;
    kept.insert(kept.end(), t.kept.begin(), t.kept.end());
  }
  tallies.clear();
  std::vector<uint32_t>().swap(members);
  std::vector<uint32_t>().swap(start);
  std::vector<uint32_t>().swap(count);
  std::sort(kept.begin(), kept.end(), better);
  if (limit > 0 && kept.size() > limit) kept.resize(limit);

  // The kept pairs, with their blocks.
  auto counted = [&](uint64_t h) { return !common(1) && !commonHashes.contains(h); };
  LexedCache cache(options, ignoredSet, k, w);
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
    const LexedCache::Entry& la = cache.get(c.a, pa.path);
    const LexedCache::Entry& lb = cache.get(c.b, pb.path);
    bool sameA = la.lexed.skip.empty() && la.lexed.tokens.size() == pa.tokens;
    bool sameB = lb.lexed.skip.empty() && lb.lexed.tokens.size() == pb.tokens;
    if (sameA && sameB) {
      pair.blocks = findBlocks(la.prints, lb.prints, la.lexed, lb.lexed, counted, ignored, k, w);
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

namespace detail {

std::optional<std::vector<uint32_t>> normalisedCodes(const std::string& text, bool quick) {
  Words words(standardBuiltins());
  std::vector<uint32_t> codes;
  if (quick) {
    bool cut = false;
    QuickScan scan(words);
    if (!scan.codes(text, codes, cut)) return std::nullopt;
    return codes;
  }
  Lexed lexed;
  lexText("test.bas", text, false, words, lexed);
  if (!lexed.skip.empty()) return std::nullopt;
  for (const NormToken& t : lexed.tokens) codes.push_back(t.code);
  return codes;
}

std::vector<uint32_t> winnowed(const std::vector<uint64_t>& hashes, size_t w) {
  std::vector<uint32_t> out;
  for (const Fingerprint& f : winnow(hashes, std::max<size_t>(w, 1))) out.push_back(f.pos);
  return out;
}

std::vector<uint64_t> fingerprintsOf(const std::string& text, size_t k, size_t w) {
  Program p;
  p.path = "test.bas";
  SimilarityOptions options;
  options.source = [&text](const std::string&) { return std::optional<std::string>(text); };
  HashSet none;
  none.clear(0);
  Worker worker(standardBuiltins());
  if (!fingerprints(p, options, none, std::max<size_t>(k, 1), std::max<size_t>(w, 1), worker)) return {};
  std::vector<uint64_t> out = worker.distinct;
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace detail

}  // namespace rb::grade
