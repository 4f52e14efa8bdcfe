#pragma once
// Source files and positions. Every token, AST node, instruction and diagnostic carries a
// SourceLoc; a SourceSet owns the text of every file a program is made of (the main file and
// its includes) so that diagnostics can quote the offending line.

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace rb {

/// A position in a source file: file index in its SourceSet, 1-based line and column.
struct SourceLoc {
  uint32_t file = 0;
  uint32_t line = 0;  ///< 0 means "no position"
  uint32_t col = 0;

  bool valid() const { return line != 0; }
  friend bool operator==(const SourceLoc&, const SourceLoc&) = default;
};

/// One file's name and text, with an index of line starts.
class SourceFile {
 public:
  SourceFile(std::string name, std::string text);

  const std::string& name() const { return name_; }
  const std::string& text() const { return text_; }
  /// The text of a 1-based line, without its line ending ("" when out of range).
  std::string_view lineText(uint32_t line) const;
  /// How many lines the file has (a last line without a line ending counts).
  uint32_t lineCount() const { return static_cast<uint32_t>(lineStarts_.size()); }

 private:
  std::string name_;
  std::string text_;
  std::vector<uint32_t> lineStarts_;
};

/// The files of one program. Files are never removed, so indices and string_views stay valid.
class SourceSet {
 public:
  /// Adds a file and returns its index.
  uint32_t add(std::string name, std::string text);
  const SourceFile& file(uint32_t index) const { return *files_[index]; }
  size_t size() const { return files_.size(); }

 private:
  std::vector<std::unique_ptr<SourceFile>> files_;
};

}  // namespace rb
