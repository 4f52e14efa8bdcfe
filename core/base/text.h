#pragma once
// Text shown inside messages and traces.

#include <cstddef>
#include <string>
#include <string_view>

namespace rb {

/// `s` in double quotes with C escapes (\" \\ \n \r \t \xNN for other control bytes); after
/// `maxChars` characters the rest is cut and "..." stands for it.
std::string cQuoted(std::string_view s, size_t maxChars = std::string_view::npos);

/// `s` on one line with nothing a terminal would obey: newline, return and tab as `\n`, `\r`,
/// `\t`, other control characters in caret notation (`^[` for ESC, `^@` for NUL, `^?` for DEL),
/// C1 controls (U+0080..U+009F) and bytes that are not UTF-8 as `\xNN`. For names a program
/// chose (file names in messages).
std::string visibleText(std::string_view s);

}  // namespace rb
