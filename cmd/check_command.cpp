#include "check_command.h"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <string>
#include <vector>

#include "base/rules.h"
#include "machine/builtins.h"
#include "lang/checker.h"
#include "lang/code_dump.h"
#include "lang/portable_check.h"
#include "diagnostic_output.h"
#include "exit_codes.h"
#include "files.h"
#include "program_loader.h"

namespace rb::cli {

namespace {

struct CheckOptions {
  std::vector<std::string> files;
  std::string format = "text";
  std::string color = "auto";
  size_t maxErrors = 20;
  bool werror = false;
  bool listBuiltins = false;
  bool listRules = false;
  bool dumpCode = false;  ///< also print each program's compiled code
  std::string target;  ///< "rb9": also warn about what the RB-9 robot cannot do
  bool portable = false;  ///< also warn about what no public RobotBASIC source shows
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
  nlohmann::json rows = nlohmann::json::array();
  for (const Builtin& b : standardBuiltins().rows()) {
    std::string usage = b.usage();
    if (json) {
      rows.push_back({{"name", b.name}, {"kind", kindName(b.kind)}, {"group", b.group},
                      {"usage", usage}, {"help", b.help}, {"source", b.evidence.source},
                      {"recalled", b.evidence.recalled}, {"own", b.evidence.own() ? b.evidence.reason : ""},
                      {"why", b.evidence.reason}, {"instead", b.evidence.instead}});
    } else if (b.kind == BuiltinKind::Constant) {
      std::printf("%-9s %-9s %-40s = %lld\n", std::string(b.group).c_str(), kindName(b.kind),
                  usage.c_str(), static_cast<long long>(b.constant));
    } else {
      std::printf("%-9s %-9s %-40s %s\n", std::string(b.group).c_str(), kindName(b.kind),
                  usage.c_str(), std::string(b.help).c_str());
    }
  }
  if (json) std::printf("%s\n", rows.dump(2).c_str());
}

/// Every diagnostic rule: a line each, or (JSON) id, severity, summary, description (Markdown)
/// and the URL of its documentation; scripts/gen_rules_doc.py writes docs/diagnostics.md's table
/// from it.
void listRules(bool json) {
  nlohmann::json rows = nlohmann::json::array();
  for (const Rule& r : allRules()) {
    if (json) {
      rows.push_back({{"id", r.id}, {"severity", severityName(r.severity)}, {"summary", r.summary},
                      {"description", r.description}, {"url", ruleUrl(r.id)}});
    } else {
      std::printf("%-24s %-8s %s\n", std::string(r.id).c_str(), severityName(r.severity),
                  std::string(r.summary).c_str());
    }
  }
  if (json) std::printf("%s\n", rows.dump(2).c_str());
}

int executeCheck(const CheckOptions& opts) {
  diagnostics::DiagFormat format = diagnostics::parseDiagFormat(opts.format);
  if (opts.listBuiltins) {
    listBuiltins(format == diagnostics::DiagFormat::Json);
    return run::exitcode::kOk;
  }
  if (opts.listRules) {
    listRules(format == diagnostics::DiagFormat::Json);
    return run::exitcode::kOk;
  }
  if (opts.files.empty()) {
    std::fprintf(stderr, "rb check: no files given (see rb check --help)\n");
    return run::exitcode::kUsage;
  }
  if (opts.dumpCode && format != diagnostics::DiagFormat::Text) {
    std::fprintf(stderr, "rb check: --dump-code prints text; leave out --format %s\n", opts.format.c_str());
    return run::exitcode::kUsage;
  }
  std::vector<std::string> files = run::expandProgramPaths(opts.files);
  if (files.empty()) {
    std::fprintf(stderr, "rb check: error: no .bas files in %s\n", opts.files.front().c_str());
    return run::exitcode::kNoInput;
  }
  diagnostics::DiagOutputOptions out;
  out.format = format;
  out.color = format == diagnostics::DiagFormat::Text && diagnostics::useColor(opts.color, stdout);
  out.maxErrors = opts.maxErrors;
  diagnostics::DiagnosticReport report(stdout, out);
  size_t unreadable = 0;
  for (const std::string& file : files) {
    CompileOptions compile;
    compile.keepCode = opts.dumpCode;  // only the diagnostics are wanted otherwise
    LintOptions lint;
    lint.realRobot = opts.target == "rb9";  // a real robot needs no rLocate
    run::LoadedFile loaded = run::loadFile(file, compile, true, true, {}, lint);
    if (opts.target == "rb9" && loaded.program) checkRb9Target(*loaded.program, loaded.diags);
    if (opts.portable && loaded.program) checkPortable(*loaded.program, loaded.diags);
    if ((opts.target == "rb9" || opts.portable) && loaded.program) loaded.diags.sort();
    if (loaded.exitCode == run::exitcode::kNoInput) {
      ++unreadable;
      report.addUnreadable(file, loaded.readError);
      continue;
    }
    report.add(loaded.program->sources, loaded.diags);
    if (opts.dumpCode && loaded.compiled) {
      std::string code = dumpCode(*loaded.compiled, loaded.program->sources);
      std::fwrite(code.data(), 1, code.size(), stdout);
    }
  }
  report.finish();
  std::fflush(stdout);
  if (unreadable && report.errors() == 1) return run::exitcode::kNoInput;
  if (report.errors() > 0 || (opts.werror && report.warnings() > 0)) return run::exitcode::kRejected;
  return run::exitcode::kOk;
}

}  // namespace

void addCheckCommand(CLI::App& app, int& exitCode, bool withOptions) {
  auto opts = std::make_shared<CheckOptions>();
  CLI::App* check = app.add_subcommand(
      "check", "Find errors in programs without running them (compiler-style diagnostics)");
  if (!withOptions) return;
  check->add_option("files", opts->files, "Program files, or folders whose *.bas files (and below) are checked");
  check->add_option("--format", opts->format,
                    "Output format: text (gcc-style, for people), json (gcc's JSON shape), sarif "
                    "(SARIF 2.1.0, for code scanning) or github (GitHub Actions annotations)")
      ->check(CLI::IsMember({"text", "json", "sarif", "github"}));
  check->add_option("--color", opts->color,
                    "Colour the text: auto (on a terminal, unless NO_COLOR is set), always or never")
      ->check(CLI::IsMember({"auto", "always", "never"}));
  check->add_option("--max-errors", opts->maxErrors,
                    "Stop after showing this many errors, in every format (0: no limit; default 20)");
  check->add_flag("--werror", opts->werror, "Treat warnings as errors (exit 65 when there are any)");
  check->add_option("--target", opts->target,
                    "Also warn about what this robot cannot do: rb9 (forward moves above 250, "
                    "rLook, rGPSX/rGPSY, rChargeLevel)")
      ->check(CLI::IsMember({"rb9"}));
  check->add_flag("--portable", opts->portable,
                  "Also warn wherever the program uses what no public RobotBASIC source shows: "
                  "rb's own built-ins (trimL, contains, ...) and statement forms (else if, end if, "
                  "step, ' comments, ...), with what RobotBASIC is known to have instead");
  check->add_flag("--list-builtins", opts->listBuiltins,
                  "List every built-in command, function and constant, then exit");
  check->add_flag("--list-rules", opts->listRules,
                  "List every diagnostic rule (its code, severity and summary; with --format json "
                  "also its full description and documentation link), then exit");
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
