#pragma once
// Helpers for core's unit tests: programs from strings, a Host that records output and feeds
// scripted input, and one call that loads, compiles and runs a program in-process.

#include <deque>
#include <map>
#include <string>

#include "lang/compiler.h"
#include "machine/builtins.h"
#include "machine/host.h"
#include "machine/interpreter.h"
#include "lang/loader.h"

namespace rb::test {

/// Files held in memory, by name.
class MemoryReader : public SourceReader {
 public:
  std::map<std::string, std::string> files;
  std::optional<std::string> find(const std::string& path) override {
    return files.count(path) ? std::optional<std::string>(path) : std::nullopt;
  }
  std::optional<std::string> read(const std::string& canonical) override {
    auto it = files.find(canonical);
    return it == files.end() ? std::nullopt : std::optional<std::string>(it->second);
  }
};

class TestHost : public Host {
 public:
  std::string out;
  std::deque<std::string> input;
  double clock = 0;
  void output(std::string_view text) override { out += text; }
  std::optional<std::string> inputLine(std::string_view prompt) override {
    out += prompt;
    if (input.empty()) return std::nullopt;
    std::string line = input.front();
    input.pop_front();
    return line;
  }
  double clockMs() override { return clock += 1; }
  void wait(double ms) override { clock += ms; }
  double wallSeconds() override { return 0; }
};

struct Outcome {
  std::string out;          ///< what the program printed
  std::string diagnostics;  ///< formatted load-time diagnostics and the runtime error, if any
  bool loaded = false;      ///< false when the program was rejected before running
  RunResult result;
};

/// Loads `text` as `name` (includes through `reader`), compiles and runs it; `loaded` is false
/// when the program was rejected before running.
inline Outcome runSource(const std::string& name, const std::string& text, SourceReader& reader,
                         std::deque<std::string> input = {}, RunLimits limits = {},
                         const CompileOptions& compile = {}) {
  Outcome o;
  DiagnosticList diags;
  auto loaded = loadProgram(name, text, reader, standardBuiltins(), {}, diags);
  auto program = compileProgram(*loaded, compile, diags);
  for (const Diagnostic& d : diags.all()) o.diagnostics += formatDiagnostic(loaded->sources, d);
  if (!program) return o;
  o.loaded = true;
  TestHost host;
  host.input = std::move(input);
  Machine machine(host, 1);
  Interpreter interp(*program, machine);
  o.result = interp.run(limits);
  o.out = host.out;
  if (o.result.error) o.diagnostics += formatDiagnostic(loaded->sources, *o.result.error);
  return o;
}

/// Loads `text` as "test.bas" (with `files` for includes), compiles and runs it.
inline Outcome runProgram(const std::string& text, MemoryReader reader = {},
                          std::deque<std::string> input = {}, RunLimits limits = {},
                          const CompileOptions& compile = {}) {
  reader.files["test.bas"] = text;
  return runSource("test.bas", text, reader, std::move(input), limits, compile);
}

}  // namespace rb::test
