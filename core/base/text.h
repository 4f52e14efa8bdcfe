#pragma once
// Text shown inside messages and traces.

#include <cstddef>
#include <string>
#include <string_view>

namespace rb {

/// `s` in double quotes with C escapes (\" \\ \n \r \t \xNN for other control bytes); after
/// `maxChars` characters the rest is cut and "..." stands for it.
std::string cQuoted(std::string_view s, size_t maxChars = std::string_view::npos);

}  // namespace rb
