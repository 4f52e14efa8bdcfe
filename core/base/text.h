#pragma once
// Text shown inside messages and traces.

#include <cstddef>
#include <string>
#include <string_view>

namespace rb {

/// `s` in double quotes with C escapes (\" \\ \n \r \t \xNN for other control bytes and DEL);
/// after `maxChars` characters the rest is cut and "..." stands for it. With `quote` '\'' it is
/// in single quotes (\' escaped instead of \"), as messages quote names.
std::string cQuoted(std::string_view s, size_t maxChars = std::string_view::npos, char quote = '"');

}  // namespace rb
