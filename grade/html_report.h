#pragma once
// The class report page (rb test --html DIR): DIR/index.html with a card per program (the
// student's name, the points, the final screen, each check's verdict), sortable and filterable
// in the page, and DIR/programs/NAME.html per program (its source with the lines where the run
// went wrong marked, every check, the output, the feedback its student gets, the feedback
// picture and the replay). Static pages with no network: they open from file:// and the folder
// can be zipped and opened anywhere (pictures are linked by relative paths). Everything that
// comes from a student (names, file names, source, output) is escaped, and the pages' Content
// Security Policy runs only the page's own script (a nonce), so a program cannot put a script
// into the teacher's page.

#include <string>
#include <vector>

#include "grader.h"

namespace rb::grade {

/// Text for HTML character data and attribute values: shown as every report shows untrusted
/// text (shownText in text.h: control characters in caret notation, tab and line feed kept),
/// then & < > " ' as character references.
std::string htmlEscape(const std::string& text);

/// The URL, relative to the folder `fromDir`, of the file `to` (both as paths on this machine,
/// relative to the working folder or absolute), percent-encoded but for letters, digits, '/',
/// '-', '.', '_' and '~'.
std::string relativeUrl(const std::string& to, const std::string& fromDir);

/// The pages' own parts, for tests: the class page (cards link to `pages[i]`, relative to DIR,
/// "" for none) and one program's page (`source`: its text, or nullopt when it cannot be read).
/// `dir` is the report's folder; `nonce` the Content Security Policy's nonce for the script.
std::string classPage(const ClassResult& result, const std::vector<std::string>& pages, const std::string& dir,
                      const std::string& nonce);
std::string programPage(const ClassResult& result, size_t index, const std::string* source,
                        const std::string& dir, const std::string& nonce);

/// Writes DIR/index.html and DIR/programs/NAME.html (NAME as reportName() gives it for `paths`,
/// made unique). On failure returns false with a message naming the file in `error`.
bool writeHtmlReport(const ClassResult& result, const std::vector<std::string>& paths, const std::string& dir,
                     std::string& error);

}  // namespace rb::grade
