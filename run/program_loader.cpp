#include "program_loader.h"

#include "lang/checker.h"
#include "machine/builtins.h"
#include "exit_codes.h"
#include "files.h"

namespace rb::run {

LoadedFile loadFile(const std::string& file, const CompileOptions& options, bool lint, bool compact,
                    const std::vector<std::string>& allowed, const LintOptions& lintOptions) {
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
  FileSourceReader reader(file, allowed);
  LoadOptions loadOptions;
  loadOptions.libraryDirs = libraryDirs();
  loadOptions.compact = compact;
  out.program = loadProgram(name, std::move(text), reader, standardBuiltins(), loadOptions, out.diags);
  out.compiled = compileChecked(*out.program, options, lint, out.diags, lintOptions);
  return out;
}

void printDiagnostic(std::FILE* out, const SourceSet& sources, const Diagnostic& d, bool color) {
  std::string text = formatDiagnostic(sources, d, DiagnosticStyle{color});
  std::fwrite(text.data(), 1, text.size(), out);
}

void printWarningLines(const char* command, const std::string& file, const SourceSet& sources,
                       const DiagnosticList& diags, bool color) {
  constexpr size_t kShown = 5;
  size_t shown = 0;
  for (const Diagnostic& d : diags.all()) {
    if (d.severity != Severity::Warning) continue;
    if (shown++ == kShown) break;
    std::string line = formatDiagnostic(sources, d, DiagnosticStyle{color, true});
    std::fwrite(line.data(), 1, line.size(), stderr);
  }
  size_t total = diags.warningCount();
  if (total > kShown)
    std::fprintf(stderr, "%s: %zu more warnings (rb check %s shows them all; --quiet hides them)\n",
                 command, total - kShown, file.c_str());
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

}  // namespace rb::run
