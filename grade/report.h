#pragma once
// The reports of a graded class: the summary table for the terminal, JSON, JUnit XML (which
// GitHub, GitLab and Jenkins show) and a CSV grade book. Every text that comes from a student's
// program (names, output, errors, the messages quoting them) goes through shownText (text.h):
// no report carries a control character, a workflow command or a spreadsheet formula of theirs.

#include <string>
#include <string_view>

#include "grader.h"

namespace rb::grade {

/// The summary table (program, result, steps, time, reason) and a total line; `details` adds
/// every failed check of each failed program below the table.
std::string textReport(const ClassResult& result, bool details);

/// One JSON document with every program, every check and the totals.
std::string jsonReport(const ClassResult& result);

/// One program's feedback for its student (rb test --feedback DIR): every check with its points,
/// hints and the teacher's feedback, the output with input marked; hidden checks only say that
/// they failed.
std::string studentFeedback(const ProgramResult& program, const ClassResult& result);

/// JUnit XML: one <testsuite> for the class, one <testcase> per program with a <failure> (a
/// failed check), <error> (rb could not grade it) or <skipped>, and its output.
std::string junitReport(const ClassResult& result);

/// A CSV grade book: one row per program with its result, points and reason.
std::string csvReport(const ClassResult& result);

/// The program as a student's report shows it: no message names an option or a setting that
/// would have granted what was refused ("(rb run --allow-files DIR allows another folder)",
/// "(rb test --trust-comments)", "(ports = true)"): that is for the teacher, not a cheater's
/// guide. rb test --student's reports and every feedback file show programs this way.
ProgramResult forStudents(ProgramResult program);
/// The same for one message.
std::string withoutGrants(const std::string& text);

/// A check as a report shows it: in a report for students (--student) a hidden check is only
/// "hidden check" with its verdict.
CheckResult shownCheck(const CheckResult& check, bool student);
/// The first reason a program failed, as the report shows it.
std::string shownReason(const ProgramResult& program, bool student);
/// The program's output with what input showed marked: each line an input touched starts with
/// "> " and the text it read is in [brackets]; other lines start with two blanks.
std::string outputTranscript(const ProgramResult& program);

/// Text for XML or HTML: shown as every report shows untrusted text (shownText in text.h, as
/// lines: control characters in caret notation, tab and line feed kept), then & < > " escaped,
/// and ' as `apostrophe` (XML's "&apos;", or HTML's "&#39;").
std::string markupEscape(const std::string& text, std::string_view apostrophe);
/// markupEscape for XML (character data and attribute values).
std::string xmlEscape(const std::string& text);

}  // namespace rb::grade
