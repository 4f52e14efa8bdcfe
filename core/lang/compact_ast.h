#pragma once
// The statement list in a compact form, for checking big programs: each statement is encoded
// in a few dozen bytes as it is parsed (its tree freed at once), and read back one statement at
// a time into a scratch Arena by a StmtCursor. A statement read back equals the parsed one in
// every field; its names and strings point into the SourceSet's text, as the parser's do.

#include <cstdint>
#include <memory>
#include <vector>

#include "base/source.h"
#include "lang/ast.h"

namespace rb::ast {

class CompactStmts {
 public:
  explicit CompactStmts(const SourceSet& sources) : sources_(sources) {}
  /// Appends `s` (and the statements of its body).
  void add(const Stmt& s);
  size_t size() const { return count_; }
  /// Bytes held (for measurements).
  size_t bytes() const;

 private:
  friend class StmtCursor;
  /// A block of encoded statements; the big ones are large memory (base/large_memory.h).
  struct Chunk {
    explicit Chunk(size_t capacity);
    Chunk(Chunk&& o) noexcept : data(o.data), size(o.size), cap(o.cap) { o.data = nullptr; }
    Chunk(const Chunk&) = delete;
    Chunk& operator=(const Chunk&) = delete;
    ~Chunk();
    uint8_t* data;
    size_t size = 0;
    size_t cap;
  };
  const SourceSet& sources_;
  std::vector<Chunk> chunks_;
  size_t count_ = 0;
  std::vector<uint8_t> buf_;  ///< the statement being encoded
};

/// Reads a statement list in order: a vector of parsed statements, or a CompactStmts whose
/// statements it inflates into `scratch` (valid until the scratch arena is reset; the caller
/// resets it when it holds no node any more). Copies read on independently.
class StmtCursor {
 public:
  explicit StmtCursor(const std::vector<Stmt*>& stmts) : vec_(&stmts) {}
  StmtCursor(const CompactStmts& compact, Arena& scratch) : compact_(&compact), scratch_(&scratch) {}
  /// The same position, reading into another arena.
  StmtCursor(const StmtCursor& at, Arena& scratch) : StmtCursor(at) { scratch_ = &scratch; }

  bool done() const { return index_ == size(); }
  size_t size() const { return vec_ ? vec_->size() : compact_->size(); }
  /// The index of the statement next() returns.
  size_t index() const { return index_; }
  /// The next statement.
  const Stmt* next();

 private:
  const std::vector<Stmt*>* vec_ = nullptr;
  const CompactStmts* compact_ = nullptr;
  Arena* scratch_ = nullptr;
  size_t index_ = 0;
  size_t chunk_ = 0;
  size_t offset_ = 0;
};

}  // namespace rb::ast
