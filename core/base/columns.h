#pragma once
// Columns in the units other tools count. rb's SourceLoc columns are 1-based UTF-8 byte
// columns; SARIF (run.columnKind "utf16CodeUnits"), GitHub annotations and LSP count UTF-16
// code units, and gcc's JSON "column"/"display-column" count what a terminal shows (a tab to
// the next multiple of 8, a wide character two, a combining mark none).

#include <cstdint>
#include <string_view>

namespace rb {

/// The column, in UTF-16 code units (1-based), of the character at byte column `byteCol`
/// (1-based) of `line`; a byte column inside a character counts that character as before it,
/// so an exclusive end (the byte after a range) maps to the unit after the range. Past the end
/// of the line each byte counts one.
uint32_t utf16Column(std::string_view line, uint32_t byteCol);

/// gcc's display column (1-based) of byte column `byteCol` (1-based) of `line`, with tabs
/// stopping every `tabStop` columns (gcc's -ftabstop, 8 by default).
uint32_t displayColumn(std::string_view line, uint32_t byteCol, uint32_t tabStop = 8);

/// How many terminal columns a code point takes: 2 for East Asian wide and fullwidth
/// characters and emoji, 0 for combining marks and zero-width formatting characters, else 1.
int codePointWidth(char32_t c);

/// How many terminal columns the character starting at byte `i` of `s` takes (a tab counts 1:
/// where it stops depends on the column), and its length in bytes in `len`.
int displayWidthAt(std::string_view s, size_t i, size_t& len);

}  // namespace rb
