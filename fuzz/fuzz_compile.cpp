// libFuzzer target: the input bytes are a RobotBASIC program "fuzz.bas". It is loaded (lexer,
// parser, #include splicing), compiled twice (without and with line tracing), linted, and the
// first diagnostics are formatted; rb check's compact path (statements kept compact, no code
// kept) must find exactly the same diagnostics as the tree path, or the fuzzer stops. The program is never run: the interpreter may
// legitimately loop forever. Any crash, sanitizer report or hang is a bug in rb_core.

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>

#include "lang/checker.h"
#include "lang/code_dump.h"
#include "lang/compiler.h"
#include "base/diagnostic.h"
#include "lang/loader.h"
#include "machine/builtins.h"

namespace {

// A small fixed library, so that seeds including "lib/helpers.bas" (testdata/lang/include)
// resolve to something with subs and labels in it.
constexpr const char* kHelpers =
    "// fixed library served to the fuzzer\n"
    "Greet:\n"
    "  print \"hello from the library\"\n"
    "return\n"
    "sub Twice(x)\n"
    "  return x * 2\n"
    "endsub\n"
    "dim table[3]\n"
    "data table; 1, 2, 3\n";

/// Files in memory. Like the real file reader on a case-insensitive file system, a name is
/// found whatever its case and its canonical form is lower case.
class FuzzReader : public rb::SourceReader {
 public:
  std::map<std::string, std::string> files;  // keyed by lower-case name

  static std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
  }
  std::optional<std::string> find(const std::string& path) override {
    std::string key = lower(path);
    if (files.count(key)) return key;
    return std::nullopt;
  }
  std::optional<std::string> read(const std::string& canonical) override {
    auto it = files.find(canonical);
    if (it == files.end()) return std::nullopt;
    return it->second;
  }
};

size_t sink = 0;  // keeps the formatted text observable

/// Every diagnostic's severity, place, rule and message, in order.
std::string summary(const rb::DiagnosticList& diags) {
  std::string out;
  for (const rb::Diagnostic& d : diags.all()) {
    out += std::to_string(static_cast<int>(d.severity)) + ' ' + std::to_string(d.loc.file) + ':' +
           std::to_string(d.loc.line) + ':' + std::to_string(d.loc.col) + ' ' + d.code + ' ' +
           d.message + '\n';
  }
  return out;
}

/// Formats the first diagnostics, before and after sorting. Only the first 64 each time: rb
/// check prints 20 errors unless told otherwise, every diagnostic goes through the same code,
/// and formatting thousands of them on one 4 KiB line took most of each execution's time.
void formatAll(const rb::SourceSet& sources, rb::DiagnosticList& diags) {
  constexpr size_t kFormatted = 64;
  auto formatSome = [&] {
    size_t n = 0;
    for (const rb::Diagnostic& d : diags.all()) {
      if (n++ == kFormatted) break;
      sink += rb::formatDiagnostic(sources, d).size();
    }
  };
  formatSome();
  diags.sort();
  formatSome();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string text(reinterpret_cast<const char*>(data), size);

  FuzzReader reader;
  reader.files["fuzz.bas"] = text;
  reader.files["inc.bas"] = text;  // `#include "inc.bas"` splices the same bytes in once more
  reader.files["lib/helpers.bas"] = kHelpers;

  rb::DiagnosticList loadDiags;
  rb::LoadOptions options;
  options.libraryDirs.push_back("lib");  // so `#include "helpers.bas"` resolves through a lib dir
  std::unique_ptr<rb::LoadedProgram> loaded =
      rb::loadProgram("fuzz.bas", text, reader, rb::standardBuiltins(), options, loadDiags);
  if (!loaded) __builtin_trap();  // loadProgram promises a usable result

  // rb check's path: statements kept compact, no code kept, the unassigned-variable check fed
  // by the compiler's walk. It must find exactly what the tree path below finds.
  std::string compactFound;
  {
    rb::DiagnosticList diags;
    rb::LoadOptions compactOptions = options;
    compactOptions.compact = true;
    std::unique_ptr<rb::LoadedProgram> compact =
        rb::loadProgram("fuzz.bas", text, reader, rb::standardBuiltins(), compactOptions, diags);
    if (!compact) __builtin_trap();
    rb::Linter linter(*compact);
    rb::CompileOptions checkOptions;
    checkOptions.keepCode = false;
    checkOptions.onStatement = [&linter](const rb::ast::Stmt& st, size_t i) { linter.statement(st, i); };
    std::unique_ptr<rb::Program> program = rb::compileProgram(*compact, checkOptions, diags);
    linter.finish(diags);
    diags.sort();
    compactFound = summary(diags);
  }

  for (bool lineTracing : {false, true}) {
    rb::DiagnosticList diags = loadDiags;
    rb::CompileOptions compileOptions;
    compileOptions.lineTracing = lineTracing;
    std::unique_ptr<rb::Program> program = rb::compileProgram(*loaded, compileOptions, diags);
    // The contract of compileProgram: a program exactly when there are no errors.
    if ((program != nullptr) == diags.hasErrors()) __builtin_trap();
    if (program) sink += rb::dumpCode(*program, loaded->sources).size();  // the dump reads every operand
    if (!lineTracing) {
      rb::lintProgram(*loaded, diags);
      rb::DiagnosticList sorted = diags;
      sorted.sort();
      if (summary(sorted) != compactFound) __builtin_trap();
    }
    formatAll(loaded->sources, diags);
  }
  return 0;
}
