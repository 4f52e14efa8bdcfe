// The functions web/rb.js calls: check a program (the diagnostics `rb check` gives) and run
// one (as `rb run` does, or live on the page). Results are JSON text the caller frees.

#include <emscripten.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "base/diagnostic.h"
#include "input/input_script.h"
#include "lang/checker.h"
#include "lang/compiler.h"
#include "lang/loader.h"
#include "machine/builtins.h"
#include "machine/interpreter.h"
#include "machine/machine.h"
#include "json_text.h"
#include "web_host.h"

namespace rb::web {
namespace {

using render::appendJsonString;

/// A program on the page is one file: an #include finds nothing.
class NoFiles : public SourceReader {
 public:
  std::optional<std::string> find(const std::string&) override { return std::nullopt; }
  std::optional<std::string> read(const std::string&) override { return std::nullopt; }
};

const char* kProgramName = "program.bas";

void jsonDiagnostic(std::string& out, const SourceSet& sources, const Diagnostic& d) {
  out += "{\"severity\":";
  appendJsonString(out, d.severity == Severity::Error ? "error" : d.severity == Severity::Warning ? "warning" : "note");
  out += ",\"line\":" + std::to_string(d.loc.line) + ",\"col\":" + std::to_string(d.loc.col);
  if (d.end.valid()) out += ",\"endLine\":" + std::to_string(d.end.line) + ",\"endCol\":" + std::to_string(d.end.col);
  out += ",\"message\":";
  appendJsonString(out, d.message);
  out += ",\"code\":";
  appendJsonString(out, d.code);
  out += ",\"text\":";
  appendJsonString(out, formatDiagnostic(sources, d, DiagnosticStyle{}));
  out += '}';
}

char* give(const std::string& s) {
  char* p = static_cast<char*>(std::malloc(s.size() + 1));
  std::memcpy(p, s.data(), s.size() + 1);
  return p;
}

struct Loaded {
  DiagnosticList diags;
  std::unique_ptr<LoadedProgram> program;
  std::unique_ptr<Program> compiled;
};

/// Loads and compiles as rb does (with rb check's warnings when `lint`).
std::unique_ptr<Loaded> load(const char* source, bool lint, bool keepCode, bool lineTracing = false) {
  auto out = std::make_unique<Loaded>();
  NoFiles reader;
  out->program = loadProgram(kProgramName, source, reader, standardBuiltins(), LoadOptions{}, out->diags);
  CompileOptions compile;
  compile.keepCode = keepCode;
  // The page's live runs: the host hears each statement while the user steps, and the code is
  // not finished, so that the debugger shows every variable as the program wrote it (as the
  // live terminal view does).
  compile.lineTracing = lineTracing;
  out->compiled = compileChecked(*out->program, compile, lint, out->diags);
  return out;
}

std::string diagnosticsJson(const Loaded& l) {
  std::string out = "[";
  bool first = true;
  for (const Diagnostic& d : l.diags.all()) {
    if (!first) out += ',';
    first = false;
    jsonDiagnostic(out, l.program->sources, d);
  }
  return out + "]";
}


}  // namespace
}  // namespace rb::web

using namespace rb;
using namespace rb::web;

extern "C" {

/// The built-in table the page's help reads (completion, hover and the command reference: the
/// rows the language server's completion and hover read, web/help.mjs): a JSON array, one object
/// a row: name, kind (command, function, constant), group, usage, help, value (constants), and
/// the evidence as docs/builtins.md gives it: tier (confirmed, recalled, own) and its text.
EMSCRIPTEN_KEEPALIVE char* rb_builtins() {
  std::string out = "[";
  for (const Builtin& b : standardBuiltins().rows()) {
    if (out.size() > 1) out += ',';
    const char* kind = b.kind == BuiltinKind::Command ? "command" : b.kind == BuiltinKind::Function ? "function" : "constant";
    out += "{\"name\":";
    appendJsonString(out, b.name);
    out += ",\"kind\":";
    appendJsonString(out, kind);
    out += ",\"group\":";
    appendJsonString(out, b.group);
    out += ",\"usage\":";
    appendJsonString(out, b.usage());
    out += ",\"help\":";
    appendJsonString(out, b.help);
    if (b.kind == BuiltinKind::Constant) out += ",\"value\":" + std::to_string(b.constant);
    const Evidence& e = b.evidence;
    out += ",\"tier\":";
    appendJsonString(out, e.confirmed() ? "confirmed" : e.own() ? "own" : "recalled");
    out += ",\"source\":";
    appendJsonString(out, e.source);
    out += ",\"recalled\":";
    appendJsonString(out, e.recalled);
    out += ",\"reason\":";
    appendJsonString(out, e.reason);
    out += ",\"instead\":";
    appendJsonString(out, e.instead);
    out += '}';
  }
  return give(out + "]");
}

/// The diagnostics `rb check` gives for the program, as a JSON array.
EMSCRIPTEN_KEEPALIVE char* rb_check(const char* source) {
  auto l = load(source, true, false);
  return give(diagnosticsJson(*l));
}

/// Runs a program to its end. `stdinLines`: the lines `input` reads, each ended by "\n";
/// `keys`: a --keys text ("" none); limits as rb run's options (0: none); `svg`: the final screen
/// as SVG too (WebHost::presentSvg). Returns JSON:
/// {status, diagnostics (load), error (runtime), steps, rngUsed, state (WebHost::stateJson at the end)}.
EMSCRIPTEN_KEEPALIVE char* rb_run(const char* source, const char* stdinLines, const char* keys,
                                  double seed, double maxSteps, double timeoutSeconds,
                                  double maxMemoryMiB, int live, int svg) {
  auto l = load(source, false, true, live != 0);
  std::string out = "{\"diagnostics\":" + diagnosticsJson(*l);
  if (!l->compiled) return give(out + ",\"status\":\"rejected\"}");

  std::vector<std::string> lines;
  for (const char* p = stdinLines; *p;) {
    const char* e = std::strchr(p, '\n');
    if (!e) e = p + std::strlen(p);
    lines.emplace_back(p, e);
    p = *e ? e + 1 : e;
  }
  InputScript script;
  if (*keys) {
    try {
      script.steps = parseKeyText(keys);
      script.given = true;
      script.origin = "the --keys text";
    } catch (const ScriptError& e) {
      out += ",\"status\":\"usage\",\"error\":{\"message\":";
      appendJsonString(out, std::string("--keys: ") + e.what());
      return give(out + "}}");
    }
  }
  WebHost host(live != 0, std::move(lines), std::move(script));
  Machine machine(host, static_cast<uint64_t>(seed));
  host.attachMachine(machine);
  machine.canvas().keepDisplayList(svg != 0);  // the SVG's shapes (as rb render -o OUT.svg)
  Interpreter interpreter(*l->compiled, machine);
  host.attachInterpreter(interpreter);
  RunLimits limits = RunLimits::of(static_cast<uint64_t>(maxSteps), timeoutSeconds, static_cast<uint64_t>(maxMemoryMiB));
  // A live run looks at the page (Stop, Pause) at least every few milliseconds, even when its
  // statements are slow ones (drawing, printing into a full screen, long strings).
  if (live) limits.checkInterval = 1024;
  RunResult result = interpreter.run(limits);
  host.flushOutput();
  host.present();
  const char* status = "finished";
  switch (result.status) {
    case RunStatus::Finished: status = "finished"; break;
    case RunStatus::RuntimeError: status = "error"; break;
    case RunStatus::StepLimit: status = "step-limit"; break;
    case RunStatus::Timeout: status = "timeout"; break;
    case RunStatus::Stopped: status = "stopped"; break;
  }
  out += ",\"status\":";
  appendJsonString(out, status);
  out += ",\"steps\":" + std::to_string(result.steps);
  out += ",\"rngUsed\":" + std::string(machine.rngUsed() ? "true" : "false");
  out += ",\"state\":" + host.stateJson();
  if (result.error && result.status != RunStatus::Stopped) {
    out += ",\"error\":";
    jsonDiagnostic(out, l->program->sources, *result.error);
  }
  out += '}';
  // The page hears how the run ended before the SVG is made (it can take a while: the shapes of
  // 40,000 SetPixels), which it then gets for its SVG button.
  host.finished(out);
  if (svg) host.presentSvg();
  return give(out);
}

}  // extern "C"
