#include "check_command.h"

#include <cstdio>
#include <string>
#include <vector>

#include "machine/builtins.h"
#include "lang/checker.h"
#include "lang/code_dump.h"
#include "exit_codes.h"
#include "files.h"
#include "program_loader.h"

namespace rb::cli {

namespace {

struct CheckOptions {
  std::vector<std::string> files;
  std::string format = "text";
  bool werror = false;
  bool listBuiltins = false;
  bool dumpCode = false;  ///< also print each program's compiled code
  std::string target;  ///< "rb9": also warn about what the RB-9 robot cannot do
};

const char* kindName(BuiltinKind k) {
  switch (k) {
    case BuiltinKind::Command: return "command";
    case BuiltinKind::Function: return "function";
    case BuiltinKind::Constant: return "constant";
  }
  return "";
}

void listBuiltins(bool json) {
  if (json) std::printf("[\n");
  bool first = true;
  for (const Builtin& b : standardBuiltins().rows()) {
    std::string usage = std::string(b.name);
    if (b.kind == BuiltinKind::Function) usage += "(" + std::string(b.signature) + ")";
    else if (b.kind == BuiltinKind::Command && !b.signature.empty()) usage += " " + std::string(b.signature);
    if (json) {
      std::printf("%s  {\"name\":\"%s\",\"kind\":\"%s\",\"group\":\"%s\",\"usage\":\"%s\",\"help\":\"%s\"}",
                  first ? "" : ",\n", jsonEscape(b.name).c_str(), kindName(b.kind),
                  jsonEscape(b.group).c_str(), jsonEscape(usage).c_str(), jsonEscape(b.help).c_str());
    } else if (b.kind == BuiltinKind::Constant) {
      std::printf("%-9s %-9s %-40s = %lld\n", std::string(b.group).c_str(), kindName(b.kind),
                  usage.c_str(), static_cast<long long>(b.constant));
    } else {
      std::printf("%-9s %-9s %-40s %s\n", std::string(b.group).c_str(), kindName(b.kind),
                  usage.c_str(), std::string(b.help).c_str());
    }
    first = false;
  }
  if (json) std::printf("\n]\n");
}

int executeCheck(const CheckOptions& opts) {
  bool json = opts.format == "json";
  if (opts.listBuiltins) {
    listBuiltins(json);
    return exitcode::kOk;
  }
  if (opts.files.empty()) {
    std::fprintf(stderr, "rb check: no files given (see rb check --help)\n");
    return exitcode::kUsage;
  }
  if (opts.dumpCode && json) {
    std::fprintf(stderr, "rb check: --dump-code prints text; leave out --format json\n");
    return exitcode::kUsage;
  }
  std::vector<std::string> files = expandProgramPaths(opts.files);
  if (files.empty()) {
    std::fprintf(stderr, "rb check: error: no .bas files in %s\n", opts.files.front().c_str());
    return exitcode::kNoInput;
  }
  size_t errors = 0, warnings = 0;
  bool missing = false;
  bool firstJson = true;
  if (json) std::printf("[");
  for (const std::string& file : files) {
    LoadedFile loaded = loadFile(file, CompileOptions{}, true);
    if (opts.target == "rb9" && loaded.program) {
      checkRb9Target(*loaded.program, loaded.diags);
      loaded.diags.sort();
    }
    if (loaded.exitCode == exitcode::kNoInput) {
      missing = true;
      ++errors;
      if (json) {
        std::printf("%s\n  {\"file\":\"%s\",\"line\":0,\"column\":0,\"severity\":\"error\",\"message\":\"%s\"}",
                    firstJson ? "" : ",", jsonEscape(file).c_str(), jsonEscape(loaded.readError).c_str());
        firstJson = false;
      } else {
        std::printf("%s: error: cannot read '%s': %s\n", file.c_str(), file.c_str(),
                    loaded.readError.c_str());
      }
      continue;
    }
    errors += loaded.diags.errorCount();
    warnings += loaded.diags.warningCount();
    if (json) {
      for (const Diagnostic& d : loaded.diags.all()) {
        std::printf("%s\n  %s", firstJson ? "" : ",", formatDiagnosticJson(loaded.program->sources, d).c_str());
        firstJson = false;
      }
    } else {
      printDiagnostics(stdout, loaded.program->sources, loaded.diags, false);
    }
    if (opts.dumpCode && loaded.compiled) {
      std::string code = dumpCode(*loaded.compiled, loaded.program->sources);
      std::fwrite(code.data(), 1, code.size(), stdout);
    }
  }
  if (json) std::printf("%s]\n", firstJson ? "" : "\n");
  std::fflush(stdout);
  if (missing && errors == 1) return exitcode::kNoInput;
  if (errors > 0 || (opts.werror && warnings > 0)) return exitcode::kRejected;
  return exitcode::kOk;
}

}  // namespace

void addCheckCommand(CLI::App& app, int& exitCode) {
  auto opts = std::make_shared<CheckOptions>();
  CLI::App* check = app.add_subcommand(
      "check", "Find errors in programs without running them (compiler-style diagnostics)");
  check->add_option("files", opts->files, "Program files, or folders whose *.bas files (and below) are checked");
  check->add_option("--format", opts->format, "Output format: text (file:line:col: ...) or json")
      ->check(CLI::IsMember({"text", "json"}));
  check->add_flag("--werror", opts->werror, "Treat warnings as errors (exit 65 when there are any)");
  check->add_option("--target", opts->target,
                    "Also warn about what this robot cannot do: rb9 (forward moves above 250, "
                    "rLook, rGPSX/rGPSY, rChargeLevel)")
      ->check(CLI::IsMember({"rb9"}));
  check->add_flag("--list-builtins", opts->listBuiltins,
                  "List every built-in command, function and constant, then exit");
  check->add_flag("--dump-code", opts->dumpCode,
                  "Also print each program's compiled code: one instruction a line, with its "
                  "operands, jump targets, labels, subs and source lines");
  check->footer(
      "Reports every error rb run would reject before running, plus warnings: variables read but "
      "never assigned, blocks left open. Exit status: 0 no errors, 65 errors (or warnings with "
      "--werror), 66 a file does not exist.");
  check->callback([opts, &exitCode] { exitCode = executeCheck(*opts); });
}

}  // namespace rb::cli
