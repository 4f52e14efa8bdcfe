#pragma once
// `rb test [PATH...]`: grades programs against the expectations in their comments or an
// assignment file, several at a time, each in a child process (grade/).

#include "cli_app.h"

namespace rb::cli {

/// Without options: only the command's name and description (see main.cpp).
void addTestCommand(CLI::App& app, int& exitCode, bool withOptions = true);

/// `rb test-similarity PATH...` (hidden): rb test --similarity's comparison of the programs
/// alone, without grading them, its text (or --format json) on standard output. For
/// bench/grade/similarity.sh, which times it on classes too large to grade in a benchmark.
constexpr const char* kTestSimilarityCommand = "test-similarity";
void addTestSimilarityCommand(CLI::App& app, int& exitCode, bool withOptions = true);

}  // namespace rb::cli
