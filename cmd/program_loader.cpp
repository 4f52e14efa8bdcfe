#include "program_loader.h"

#include "lang/checker.h"
#include "machine/builtins.h"
#include "exit_codes.h"
#include "files.h"

namespace rb::cli {

LoadedFile loadFile(const std::string& file, const CompileOptions& options, bool lint) {
  LoadedFile out;
  std::string text;
  std::string name = file;
  std::string why;
  std::optional<std::string> t = file == "-" ? readStdin(&why) : readFile(file, &why);
  if (file == "-") name = "<stdin>";
  if (!t) {
    out.readError = why;
    out.exitCode = exitcode::kNoInput;
    return out;
  }
  text = std::move(*t);
  FileSourceReader reader;
  LoadOptions loadOptions;
  loadOptions.libraryDirs = libraryDirs();
  out.program = loadProgram(name, std::move(text), reader, standardBuiltins(), loadOptions, out.diags);
  out.compiled = compileProgram(*out.program, options, out.diags);
  if (lint) lintProgram(*out.program, out.diags);
  out.diags.sort();
  return out;
}

void printDiagnostic(std::FILE* out, const SourceSet& sources, const Diagnostic& d) {
  std::string text = formatDiagnostic(sources, d);
  std::fwrite(text.data(), 1, text.size(), out);
}

void printDiagnostics(std::FILE* out, const SourceSet& sources, const DiagnosticList& diags,
                      bool errorsOnly) {
  bool lastShown = false;
  for (const Diagnostic& d : diags.all()) {
    bool show = !errorsOnly || d.severity == Severity::Error ||
                (d.severity == Severity::Note && lastShown);
    if (d.severity != Severity::Note) lastShown = show;
    if (show) printDiagnostic(out, sources, d);
  }
}

}  // namespace rb::cli
