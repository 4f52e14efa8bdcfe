#pragma once
// Text positions as LSP counts them and as rb does. rb's SourceLoc has 1-based lines and
// 1-based byte columns; LSP has 0-based lines and characters counted in UTF-16 code units (or
// UTF-8 bytes when the client accepts that encoding). Also: document URIs and file paths, and
// the name (word) at a position.

#include <cstdint>
#include <string>
#include <string_view>

namespace rb::lsp {

enum class Encoding { Utf16, Utf8 };

/// The LSP character offset of byte `byteCol` (0-based) in `line`.
uint32_t toLspCharacter(std::string_view line, size_t byteCol, Encoding enc);
/// The byte offset (0-based, at most line.size()) of the LSP character `character` in `line`.
size_t toByteColumn(std::string_view line, uint32_t character, Encoding enc);

/// Line `line` (0-based) of `text` without its line end; "" past the end.
std::string_view lineOf(std::string_view text, uint32_t line);

/// A `file:` URI's path, percent-decoded ("file:///a%20b/x.bas" -> "/a b/x.bas"); any other URI
/// is returned as it is (an unsaved editor buffer: "untitled:Untitled-1").
std::string uriToPath(std::string_view uri);
/// The `file:` URI of an absolute path (made absolute from the working folder if it is not).
std::string pathToUri(std::string_view path);

bool isNameChar(char c);
/// The name (identifier characters: letters, digits, '_' and '$') around byte column `col` of
/// `line` (the name the cursor is in or just after): [begin, end) in bytes, empty when none.
struct Span {
  size_t begin = 0;
  size_t end = 0;
  bool empty() const { return begin == end; }
};
Span nameAt(std::string_view line, size_t col);

}  // namespace rb::lsp
