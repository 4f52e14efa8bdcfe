#pragma once
// The reports of a graded class: the summary table for the terminal, JSON, JUnit XML (which
// GitHub, GitLab and Jenkins show) and a CSV grade book.

#include <string>

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

/// Text escaped for XML character data and attribute values. Bytes that are not UTF-8 are
/// read as Latin-1; control characters XML 1.0 cannot carry become U+FFFD.
std::string xmlEscape(const std::string& text);

}  // namespace rb::grade
