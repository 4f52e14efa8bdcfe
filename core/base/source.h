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
  SourceFile(std::string name, std::string text, SourceLoc includedFrom = {});

  const std::string& name() const { return name_; }
  /// The #include line that brought this file in (invalid for the main file).
  SourceLoc includedFrom() const { return includedFrom_; }
  const std::string& text() const { return text_; }
  /// The text of a 1-based line, without its line ending ("" when out of range).
  std::string_view lineText(uint32_t line) const;
  /// How many lines the file has (a last line without a line ending counts).
  uint32_t lineCount() const { return static_cast<uint32_t>(lineStarts_.size()); }

 private:
  std::string name_;
  std::string text_;
  SourceLoc includedFrom_;
  std::vector<uint32_t> lineStarts_;
};

/// The files of one program. Files are never removed, so indices and string_views stay valid.
class SourceSet {
 public:
  /// Adds a file (brought in by the #include at `includedFrom`, if valid) and returns its index.
  uint32_t add(std::string name, std::string text, SourceLoc includedFrom = {});
  const SourceFile& file(uint32_t index) const { return *files_[index]; }
  size_t size() const { return files_.size(); }

 private:
  std::vector<std::unique_ptr<SourceFile>> files_;
};

/// What a program file's bytes turned out to be (decodeSourceText).
struct DecodedText {
  enum Kind { Utf8, Windows1252, Binary } kind = Utf8;
  std::string text;      ///< UTF-8 without a byte-order mark ("" for Binary)
  bool hadBom = false;   ///< a UTF-8 byte-order mark was skipped
  std::string why;       ///< Binary: what gave it away ("a NUL byte at byte 12")
};

/// Reads program text as RobotBASIC's files come: UTF-8 (a byte-order mark is skipped), or,
/// when the bytes are not valid UTF-8, Windows-1252 (what RobotBASIC saved), converted to UTF-8.
/// A file with a NUL byte, or with more than 1 in 100 bytes control characters or bytes
/// Windows-1252 leaves undefined, is Binary: not a program at all.
DecodedText decodeSourceText(std::string raw);

}  // namespace rb
