#pragma once
// Text that goes into JSON and XML must be UTF-8; RobotBASIC programs often come from Windows
// in Latin-1 (Windows-1252). Bytes that are not UTF-8 are read as Latin-1, so nothing is lost
// and the same input always gives the same text.

#include <string>
#include <string_view>

namespace rb::grade {

/// `text` as valid UTF-8: well-formed UTF-8 stays, every other byte is read as Latin-1.
/// `xmlSafe` also replaces the control characters XML 1.0 cannot carry with U+FFFD.
std::string toUtf8(std::string_view text, bool xmlSafe = false);

/// A CSV field, quoted when needed (RFC 4180): rb test's grade book, rb trace's CSV.
std::string csvField(const std::string& text);

}  // namespace rb::grade
