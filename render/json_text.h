#pragma once
// Strings as JSON text, for the documents rb writes (the HTML player's data) and the browser
// host's answers to the page.

#include <string>
#include <string_view>

namespace rb::render {

/// Appends `s` as a JSON string (with its quotes) that is safe inside <script>: '<' is escaped
/// (no "</script>" can appear), and bytes that are not UTF-8 become U+FFFD.
void appendJsonString(std::string& out, std::string_view s);

}  // namespace rb::render
