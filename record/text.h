#pragma once
// Text that goes into JSON and XML must be UTF-8; RobotBASIC programs often come from Windows
// in Latin-1 (Windows-1252). Bytes that are not UTF-8 are read as Latin-1, so nothing is lost
// and the same input always gives the same text.
//
// Text from a student's program (its output and errors, its file name, a roster's name, a
// message quoting them) is untrusted: every report shows it through shownText(), so that no
// byte of it moves a terminal's cursor, sets its clipboard, starts a CI runner's workflow
// command or a spreadsheet's formula.

#include <string>
#include <string_view>
#include <vector>

namespace rb::record {

/// `text` as valid UTF-8: well-formed UTF-8 stays, every other byte is read as Latin-1.
/// `xmlSafe` also replaces the control characters XML 1.0 cannot carry with U+FFFD.
std::string toUtf8(std::string_view text, bool xmlSafe = false);

/// What shownText() does with line ends and tabs.
enum class TextShape {
  Line,   ///< a name or a message, one line: LF shown as `\n`, CR as `\r`, tab as `\t`
  Block,  ///< lines (a program's output): LF a line break, tab kept, CR shown as `^M`
};

/// Untrusted text as every report shows it: valid UTF-8 that a terminal, a browser, a CI
/// runner or a spreadsheet only displays.
/// - other C0 control characters in caret notation (`^[` ESC, `^@` NUL, `^G` BEL), DEL as `^?`;
/// - C1 control characters (U+0080..U+009F, as UTF-8 or as a lone byte) as `\x80`..`\x9f`;
/// - bytes that are not UTF-8 read as Latin-1 (as toUtf8), those of the C1 range as above;
/// - the bidirectional formatting characters (U+061C, U+200E, U+200F, U+202A..U+202E,
///   U+2066..U+2069) and the line and paragraph separators (U+2028, U+2029) as `\u202e`;
/// - GitHub Actions workflow commands: a line that would begin with `::` after blanks (the
///   runner trims them) shows its first colon as `\x3a`, and `##[` (the runner's older
///   form, looked for anywhere in a line) shows as `\x23#[`.
/// A second pass changes nothing: shownText(shownText(t, s), s) == shownText(t, s).
/// `offsets`, when given, are byte offsets into `text`: each becomes the offset of the same
/// place in the text shown (an offset inside a character: where that character is shown).
std::string shownText(std::string_view text, TextShape shape, std::vector<size_t>* offsets = nullptr);

/// A CSV field, quoted when needed (RFC 4180): rb test's grade book, rb trace's CSV.
std::string csvField(const std::string& text);

/// A CSV field of untrusted text (a name, a reason) for a spreadsheet: shownText() as one line,
/// behind a single quote when it begins with `=`, `+`, `-`, `@`, a tab or a CR (OWASP's rule
/// against formula injection), quoted as csvField() quotes.
std::string csvTextField(std::string_view text);

}  // namespace rb::record
