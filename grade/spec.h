#pragma once
// Expectations written in a program's own comments: the syntax of the project's golden tests
// (testdata/README.md). `// expect: TEXT` is a line of output, `// expect-error: MESSAGE` a
// load-time error on that line, `// args: --seed 7` options for the run, and so on. Since they
// are comments, the program stays an ordinary RobotBASIC program that students can test.

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace rb::grade {

/// A diagnostic a comment expects: the file's base name, the line and the message.
struct Expected {
  std::string file;
  uint32_t line = 0;
  std::string message;
  friend auto operator<=>(const Expected&, const Expected&) = default;
};

struct CommentSpec {
  std::vector<std::string> output;       ///< expected lines of standard output
  std::set<Expected> errors;             ///< load-time errors
  std::set<Expected> warnings;           ///< rb check warnings
  std::optional<Expected> runtime;       ///< the runtime error the run stops with
  std::vector<std::string> stderrHas;    ///< text the run's standard error must contain
  std::vector<std::string> stdinLines;   ///< standard input, line by line
  std::vector<std::string> args;         ///< extra options for the run
  std::vector<std::string> checkArgs;    ///< extra options for rb check
  std::optional<std::string> skip;       ///< why the program is skipped
  bool nontest = false;                  ///< `// nontest` on line 1: a file others include
  double timeout = 30;                   ///< seconds the run may take
  bool timeoutSet = false;               ///< `// timeout:` gave it
  std::optional<int> exit;               ///< the exit status rb run must end with
  std::vector<std::string> problems;     ///< malformed comments (a bad number, a bad quote)
};

/// Reads the expectations of `path` and of the files it #includes (their errors, warnings,
/// runtime errors and standard error count; their output lines and options do not). nullopt
/// when `path` cannot be read.
std::optional<CommentSpec> readCommentSpec(const std::string& path);

/// Parses the expectations of one file's text into `spec`; `main` is false for included files.
/// `name` is the file's base name, as diagnostics show it.
void parseComments(const std::string& text, const std::string& name, bool main, CommentSpec& spec,
                   std::vector<std::string>* includes = nullptr);

/// Splits a command line like a POSIX shell: blanks separate words, quotes ('...' and "...")
/// and backslashes keep them together. nullopt when a quote is not closed.
std::optional<std::vector<std::string>> splitWords(const std::string& text);

}  // namespace rb::grade
