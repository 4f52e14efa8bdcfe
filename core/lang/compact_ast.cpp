#include "lang/compact_ast.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "base/large_memory.h"

namespace rb::ast {

// The encoding of one statement, field by field (every field, so that reading back gives the
// same statement): numbers are LEB128 varints (signed ones zigzagged); a position is its line
// as a difference from the previous position of the statement, with a bit that says whether
// its file follows (when it is not the previous position's), then its column; a name or
// string is 0 (none), 1 (in the file of the previous one) or 2 + its file, then its offset as
// a difference from the end of the previous text of the statement, and its length.

namespace {

// Chunks grow from 4 KiB to 512 KiB on the heap, so that a small program takes little; then
// they are 2 MiB of large memory each: one huge page where the system gives them, mapped at
// once, instead of 512 page faults (on some virtual machines a fault costs about 10 us, and a
// 100,000-line program made 840 of them here).
constexpr size_t kFirstChunk = 1 << 12;
constexpr size_t kLastHeapChunk = 1 << 19;
constexpr size_t kChunk = 2 * kLargeBlock;
static_assert(kLastHeapChunk < kLargeBlock);

constexpr uint8_t kHasEnd = 0x80;      // Expr: `end` is set
constexpr uint8_t kParen = 1;          // Stmt flags
constexpr uint8_t kBroken = 2;
constexpr uint8_t kHasTarget = 4;
constexpr uint8_t kHasValue = 8;
constexpr uint8_t kHasNameLoc = 16;

class Encoder {
 public:
  /// Writes into `out` (grown as needed); size() is the length written.
  Encoder(std::vector<uint8_t>& out, const SourceSet& sources) : out_(out), sources_(sources) {
    if (out_.size() < 256) out_.resize(256);
    p_ = out_.data();
    end_ = p_ + out_.size();
  }
  size_t size() const { return static_cast<size_t>(p_ - out_.data()); }

  void stmt(const Stmt& s) {
    room(3 + 3 * kLoc + kText + 5 * 4);
    uint8_t flags = static_cast<uint8_t>((s.paren ? kParen : 0) | (s.broken ? kBroken : 0) |
                                         (s.target ? kHasTarget : 0) | (s.value ? kHasValue : 0) |
                                         (s.nameLoc == SourceLoc{} ? 0 : kHasNameLoc));
    byte(static_cast<uint8_t>(s.kind));
    byte(static_cast<uint8_t>(s.op));
    byte(flags);
    loc(s.loc);
    text(s.name, s.loc.file);
    if (flags & kHasNameLoc) loc(s.nameLoc);
    if (s.target) expr(*s.target);
    if (s.value) expr(*s.value);
    room(5);
    number(s.exprs.size());
    for (const Expr* e : s.exprs) expr(*e);
    room(5 + s.seps.size());
    number(s.seps.size());
    for (Tok t : s.seps) byte(static_cast<uint8_t>(t));
    room(5);
    number(s.params.size());
    for (const Param& p : s.params) {
      room(kText + kLoc + 1);
      text(p.name, p.loc.file);
      loc(p.loc);
      byte(p.byRef ? 1 : 0);
    }
    room(5);
    number(s.body.size());
    for (const Stmt* b : s.body) stmt(*b);
  }

 private:
  static constexpr size_t kLoc = 3 * 10;   // the most a position takes
  static constexpr size_t kText = 3 * 10;  // the most a text reference takes

  void expr(const Expr& e) {
    room(2 + 2 * kLoc + kText + 10 + 5);
    bool hasEnd = !(e.end == SourceLoc{});
    byte(static_cast<uint8_t>(static_cast<uint8_t>(e.kind) | (hasEnd ? kHasEnd : 0)));
    byte(static_cast<uint8_t>(e.op));
    loc(e.loc);
    if (hasEnd) loc(e.end);
    text(e.text, e.loc.file);
    if (e.kind == ExprKind::Float) {
      std::memcpy(p_, &e.dval, sizeof(double));
      p_ += sizeof(double);
    } else {
      signedNumber(e.ival);
    }
    number(e.args.size());
    for (const Expr* a : e.args) expr(*a);
  }

  /// Makes room for `n` more bytes; the writers below assume it.
  void room(size_t n) {
    if (static_cast<size_t>(end_ - p_) >= n) return;
    size_t at = size();
    out_.resize(std::max(out_.size() * 2, at + n));
    p_ = out_.data() + at;
    end_ = out_.data() + out_.size();
  }
  void byte(uint8_t b) { *p_++ = b; }
  void number(uint64_t v) {
    while (v >= 0x80) {
      *p_++ = static_cast<uint8_t>(v | 0x80);
      v >>= 7;
    }
    *p_++ = static_cast<uint8_t>(v);
  }
  void signedNumber(int64_t v) {
    number((static_cast<uint64_t>(v) << 1) ^ static_cast<uint64_t>(v >> 63));
  }
  void loc(SourceLoc l) {
    int64_t delta = static_cast<int64_t>(l.line) - static_cast<int64_t>(prevLine_);
    uint64_t zz = (static_cast<uint64_t>(delta) << 1) ^ static_cast<uint64_t>(delta >> 63);
    bool newFile = l.file != prevFile_;
    number(zz << 1 | (newFile ? 1 : 0));
    if (newFile) number(l.file);
    number(l.col);
    prevLine_ = l.line;
    prevFile_ = l.file;
  }
  void text(std::string_view t, uint32_t hint) {
    if (t.data() == nullptr) {
      number(0);
      return;
    }
    uint32_t file = hint;
    if (!holds(file, t)) {
      for (file = 0; file < sources_.size() && !holds(file, t); ++file) {
      }
    }
    // Every name and string the parser keeps is a piece of a file's text.
    if (file == sources_.size()) throw std::logic_error("compact statements: a name outside the source text");
    auto off = static_cast<int64_t>(t.data() - sources_.file(file).text().data());
    number(file == prevTextFile_ ? 1 : uint64_t(file) + 2);
    prevTextFile_ = file;
    signedNumber(off - prevEnd_);
    number(t.size());
    prevEnd_ = off + static_cast<int64_t>(t.size());
  }
  bool holds(uint32_t file, std::string_view t) const {
    if (file >= sources_.size()) return false;
    const std::string& all = sources_.file(file).text();
    return t.data() >= all.data() && t.data() + t.size() <= all.data() + all.size();
  }

  std::vector<uint8_t>& out_;
  uint8_t* p_;
  uint8_t* end_;
  const SourceSet& sources_;
  uint32_t prevLine_ = 0;
  uint32_t prevFile_ = 0;
  uint32_t prevTextFile_ = 0;
  int64_t prevEnd_ = 0;
};

class Decoder {
 public:
  Decoder(const uint8_t* in, const SourceSet& sources, Arena& arena)
      : in_(in), sources_(sources), arena_(arena) {}

  Stmt* stmt() {
    Stmt* s = arena_.stmtToOverwrite();  // every field is set below
    s->kind = static_cast<StmtKind>(byte());
    s->op = static_cast<Tok>(byte());
    uint8_t flags = byte();
    s->paren = flags & kParen;
    s->broken = flags & kBroken;
    s->loc = loc();
    s->name = text();
    s->nameLoc = flags & kHasNameLoc ? loc() : SourceLoc{};
    s->target = flags & kHasTarget ? expr() : nullptr;
    s->value = flags & kHasValue ? expr() : nullptr;
    // The lists are empty (a node from the arena); most statements have few or none.
    s->exprs.clear();
    for (uint64_t n = number(); n > 0; --n) s->exprs.push_back(expr());
    s->seps.clear();
    for (uint64_t n = number(); n > 0; --n) s->seps.push_back(static_cast<Tok>(byte()));
    s->params.clear();
    for (uint64_t n = number(); n > 0; --n) {
      Param p;
      p.name = text();
      p.loc = loc();
      p.byRef = byte() != 0;
      s->params.push_back(p);
    }
    s->body.clear();
    for (uint64_t n = number(); n > 0; --n) s->body.push_back(stmt());
    return s;
  }

  const uint8_t* position() const { return in_; }

 private:
  Expr* expr() {
    Expr* e = arena_.exprToOverwrite();  // every field is set below
    uint8_t kind = byte();
    e->kind = static_cast<ExprKind>(kind & ~kHasEnd);
    e->op = static_cast<Tok>(byte());
    e->loc = loc();
    e->end = kind & kHasEnd ? loc() : SourceLoc{};
    e->text = text();
    if (e->kind == ExprKind::Float) {
      std::memcpy(&e->dval, in_, sizeof(double));
      in_ += sizeof(double);
    } else {
      e->ival = signedNumber();
    }
    e->args.clear();
    for (uint64_t n = number(); n > 0; --n) e->args.push_back(expr());
    return e;
  }

  uint8_t byte() { return *in_++; }
  uint64_t number() {
    uint64_t v = 0;
    for (int shift = 0;; shift += 7) {
      uint8_t b = *in_++;
      v |= static_cast<uint64_t>(b & 0x7f) << shift;
      if (!(b & 0x80)) return v;
    }
  }
  int64_t signedNumber() {
    uint64_t v = number();
    return static_cast<int64_t>(v >> 1) ^ -static_cast<int64_t>(v & 1);
  }
  SourceLoc loc() {
    SourceLoc l;
    uint64_t head = number();
    uint64_t zz = head >> 1;
    int64_t delta = static_cast<int64_t>(zz >> 1) ^ -static_cast<int64_t>(zz & 1);
    l.file = head & 1 ? static_cast<uint32_t>(number()) : prevFile_;
    l.line = static_cast<uint32_t>(static_cast<int64_t>(prevLine_) + delta);
    l.col = static_cast<uint32_t>(number());
    prevLine_ = l.line;
    prevFile_ = l.file;
    return l;
  }
  std::string_view text() {
    uint64_t head = number();
    if (head == 0) return {};
    if (head > 1 || !fileText_) {
      if (head > 1) prevTextFile_ = static_cast<uint32_t>(head - 2);
      fileText_ = sources_.file(prevTextFile_).text().data();
    }
    int64_t off = prevEnd_ + signedNumber();
    size_t len = number();
    prevEnd_ = off + static_cast<int64_t>(len);
    return std::string_view(fileText_ + off, len);
  }

  const uint8_t* in_;
  const SourceSet& sources_;
  Arena& arena_;
  uint32_t prevLine_ = 0;
  uint32_t prevFile_ = 0;
  uint32_t prevTextFile_ = 0;
  const char* fileText_ = nullptr;  ///< the text of prevTextFile_
  int64_t prevEnd_ = 0;
};

}  // namespace

void CompactStmts::add(const Stmt& s) {
  Encoder enc(buf_, sources_);
  enc.stmt(s);
  size_t n = enc.size();
  if (chunks_.empty() || chunks_.back().cap - chunks_.back().size < n) {
    size_t cap = chunks_.empty() ? kFirstChunk : chunks_.back().cap * 2;
    if (cap > kLastHeapChunk) cap = kChunk;
    chunks_.emplace_back(std::max(n, cap));
  }
  Chunk& c = chunks_.back();
  std::memcpy(c.data + c.size, buf_.data(), n);
  c.size += n;
  ++count_;
}

// Not zeroed: only the bytes written are read. Every chunk but the smallest gets its pages at
// once (allocateLarge): the chunks double, so at least half of each but the last is written.
CompactStmts::Chunk::Chunk(size_t capacity) : data(static_cast<uint8_t*>(allocateLarge(capacity))), cap(capacity) {}

CompactStmts::Chunk::~Chunk() {
  if (data) freeLarge(data, cap);
}

size_t CompactStmts::bytes() const {
  size_t n = 0;
  for (const Chunk& c : chunks_) n += c.cap;
  return n;
}

const Stmt* StmtCursor::next() {
  if (vec_) return (*vec_)[index_++];
  while (offset_ == compact_->chunks_[chunk_].size) {
    ++chunk_;
    offset_ = 0;
  }
  const CompactStmts::Chunk& c = compact_->chunks_[chunk_];
  Decoder d(c.data + offset_, compact_->sources_, *scratch_);
  const Stmt* s = d.stmt();
  offset_ = static_cast<size_t>(d.position() - c.data);
  ++index_;
  return s;
}

}  // namespace rb::ast
