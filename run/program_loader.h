#pragma once
// Loading and compiling a program file for the subcommands, with the diagnostics kept for
// printing. This is orchestration only: the language work happens in core/.

#include <cstdio>
#include <memory>
#include <string>

#include "lang/bytecode.h"
#include "lang/checker.h"
#include "lang/compiler.h"
#include "base/diagnostic.h"
#include "lang/loader.h"

namespace rb::run {

struct LoadedFile {
  std::unique_ptr<LoadedProgram> program;  ///< null when the file could not be read
  std::unique_ptr<Program> compiled;       ///< null when there are errors
  DiagnosticList diags;
  int exitCode = 0;                        ///< kNoInput when the file cannot be read, else 0
  std::string readError;                   ///< why it cannot be read ("no such file", ...)
};

/// Reads FILE ("-": standard input), loads its includes and compiles it; `compact` keeps the
/// statements in their compact form (LoadOptions::compact: for rb check, which needs only the
/// diagnostics).
/// `allowed`: folders the person running rb lets the program include from besides its own folder
/// tree and the library folders (--allow-files). `lintOptions` go to the checks `lint` adds.
LoadedFile loadFile(const std::string& file, const CompileOptions& options, bool lint,
                    bool compact = false, const std::vector<std::string>& allowed = {},
                    const LintOptions& lintOptions = {});

/// Prints diagnostics gcc-style; warnings and notes too unless `errorsOnly`.
void printDiagnostics(std::FILE* out, const SourceSet& sources, const DiagnosticList& diags,
                      bool errorsOnly);

/// Prints one diagnostic (used for runtime errors).
void printDiagnostic(std::FILE* out, const SourceSet& sources, const Diagnostic& d, bool color = false);

/// Before a run: the warnings rb check would give, one line each (file:line:col: warning:
/// message), at most 5; beyond that a count and where to see them all.
void printWarningLines(const char* command, const std::string& file, const SourceSet& sources,
                       const DiagnosticList& diags, bool color);

}  // namespace rb::run
