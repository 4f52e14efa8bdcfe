#include "trace_command.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "run_command.h"
#include "base/diagnostic.h"
#include "base/text.h"
#include "exit_codes.h"
#include "png_writer.h"
#include "headless_run.h"
#include "record.h"
#include "text.h"

namespace rb::cli {

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

struct TraceOptions {
  std::vector<std::string> files;
  RunOptions run;
  std::string format = "text";
  std::string outDir;
  bool sensors = false;
  bool lines = false;
};

const char* eventName(RobotEvent::Kind k) {
  switch (k) {
    case RobotEvent::Locate: return "locate";
    case RobotEvent::Move: return "move";
    case RobotEvent::Turn: return "turn";
    case RobotEvent::Pen: return "pen";
    case RobotEvent::Crash: return "crash";
    case RobotEvent::Sensor: return "sensor";
    case RobotEvent::Setting: return "setting";
  }
  return "event";
}

/// A fixed two-decimal number without "-0.00", so traces diff cleanly.
std::string fixed(double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  std::string s = buf;
  return s == "-0.00" ? "0.00" : s;
}

/// The same number for JSON: rounded to two decimals, never -0.
Json rounded(double v) {
  double r = std::round(v * 100) / 100;
  if (r == 0) r = 0;
  if (!std::isfinite(r)) return nullptr;
  if (r == std::trunc(r) && std::fabs(r) < 9e15) return static_cast<int64_t>(r);
  return r;
}

/// A number as JSON: whole numbers as integers.
Json number(double v) {
  if (!std::isfinite(v)) return nullptr;
  if (v == std::trunc(v) && std::fabs(v) < 9e15) return static_cast<int64_t>(v);
  return v;
}

/// A built-in's arguments ("400,300", as the trace's text shows them) as a JSON array of
/// numbers; robot built-ins take only numbers, but anything else stays a string.
Json argList(const std::string& args) {
  Json out = Json::array();
  if (args.empty()) return out;
  size_t start = 0;
  while (true) {
    size_t comma = args.find(',', start);
    std::string item = args.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    char* end = nullptr;
    double v = std::strtod(item.c_str(), &end);
    if (!item.empty() && end == item.c_str() + item.size()) out.push_back(number(v));
    else out.push_back(item);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

/// What one record of the stream says; the formats render it.
struct Record {
  std::string event;           ///< locate, move, ..., line, output, end
  std::string command;
  std::string args;
  SourceLoc loc;
  bool hasPose = true;
  Pose pose;
  bool pen = false;
  std::optional<double> value;
  // output and end
  std::string text;            ///< output: the printed text; end: the message
  // end
  std::string status, limit;
  std::optional<uint64_t> steps;
  std::optional<int> exit;
  bool located = false;
  std::vector<grade::DiagRecord> errors;  ///< end of a rejected program: its load errors
};

/// Writes one stream of records in the chosen format.
class TraceWriter : public RobotObserver {
 public:
  /// `program` is set when several programs share standard output: each record names it.
  TraceWriter(const TraceOptions& opts, std::FILE* out, const HeadlessRun& run, std::string program)
      : opts_(opts), out_(out), run_(run), program_(std::move(program)) {
    if (opts_.format == "csv" && firstCsv_)
      std::fprintf(out_, "%sseq,file,line,event,command,args,x,y,heading,pen,value,col,text,status,steps\n",
                   program_.empty() ? "" : "program,");
  }

  /// Several programs on one stream: only the first writes the CSV header.
  static inline bool firstCsv_ = true;

  void robotEvent(const RobotEvent& e) override {
    if (e.kind == RobotEvent::Sensor && !opts_.sensors) return;
    Record r;
    r.event = eventName(e.kind);
    r.command = std::string(e.command);
    r.args = e.args;
    r.loc = e.loc;
    r.pose = e.pose;
    r.pen = e.pen;
    r.value = e.value;
    write(r);
  }

  /// Before each statement: remembers where the program is (for output) and lists it with
  /// --lines.
  void line(SourceLoc loc) {
    last_ = loc;
    ++statements_;
    if (!opts_.lines) return;
    Record r;
    r.event = "line";
    r.loc = loc;
    r.pose = run_.machine->robot().pose();
    r.pen = run_.machine->robot().penDown();
    write(r);
  }

  void output(std::string_view text) {
    Record r;
    r.event = "output";
    r.loc = last_;
    r.text = std::string(text);
    r.pose = run_.machine->robot().pose();
    r.pen = run_.machine->robot().penDown();
    write(r);
  }

  /// The end record: how the run ended, after how many steps, where the robot is.
  void end(int exitCode) {
    Record r;
    r.event = "end";
    r.exit = exitCode;
    r.hasPose = false;
    const SourceSet* sources = run_.loaded.program ? &run_.loaded.program->sources : nullptr;
    if (run_.ran) {
      r.status = grade::statusName(run_.result.status);
      r.limit = grade::limitName(run_.result.status);
      if (run_.result.status == RunStatus::StepLimit && !run_.stepLimitIsError) r.status = "limit";
      r.steps = countedSteps(run_.result, statements_);
      if (run_.result.error) {
        r.loc = run_.result.error->loc;
        r.text = run_.result.error->message;
      }
      r.hasPose = true;
      r.pose = run_.machine->robot().pose();
      r.pen = run_.machine->robot().penDown();
      r.located = run_.machine->robot().located();
    } else if (run_.loaded.program && !run_.loaded.compiled) {
      r.status = "rejected";
      r.steps = 0;
      for (const Diagnostic& d : run_.loaded.diags.all()) {
        if (d.severity != Severity::Error) continue;
        grade::DiagRecord e;
        if (sources && d.loc.valid() && d.loc.file < sources->size()) e.file = sources->file(d.loc.file).name();
        e.line = d.loc.line;
        e.col = d.loc.col;
        e.message = d.message;
        r.errors.push_back(e);
      }
      if (!r.errors.empty()) r.text = r.errors[0].message;
      for (const Diagnostic& d : run_.loaded.diags.all())
        if (d.severity == Severity::Error) {
          r.loc = d.loc;
          break;
        }
    } else {
      r.status = "not-run";
      r.text = exitCode == exitcode::kNoInput ? "cannot read '" + opts_.run.file + "': no such file"
                                              : "the program did not run (see standard error)";
    }
    write(r);
  }

 private:
  std::string fileName(SourceLoc loc) const {
    const SourceSet* sources = run_.loaded.program ? &run_.loaded.program->sources : nullptr;
    return sources && loc.valid() && loc.file < sources->size() ? sources->file(loc.file).name() : "";
  }

  void write(const Record& r) {
    ++seq_;
    if (opts_.format == "jsonl") writeJson(r);
    else if (opts_.format == "csv") writeCsv(r);
    else writeText(r);
  }

  /// JSON strings are UTF-8; a Windows program's Latin-1 text is converted (grade/text.h).
  void writeJson(const Record& r) {
    using grade::toUtf8;
    Json j;
    if (!program_.empty()) j["program"] = toUtf8(program_);
    j["seq"] = seq_;
    if (r.event != "end" || r.loc.valid()) {
      j["file"] = toUtf8(fileName(r.loc));
      j["line"] = r.loc.line;
      if (r.event == "end" || r.event == "output") j["col"] = r.loc.col;
    }
    j["event"] = r.event;
    if (r.event == "end") {
      j["status"] = r.status;
      if (!r.limit.empty()) j["limit"] = r.limit;
      if (!r.text.empty()) j["message"] = toUtf8(r.text);
      if (!r.errors.empty()) {
        Json errors = Json::array();
        for (const grade::DiagRecord& e : r.errors)
          errors.push_back({{"file", toUtf8(e.file)}, {"line", e.line}, {"col", e.col}, {"message", toUtf8(e.message)}});
        j["errors"] = errors;
      }
      if (r.steps) j["steps"] = *r.steps;
      if (r.exit) j["exit"] = *r.exit;
    } else if (r.event == "output") {
      j["text"] = toUtf8(r.text);
    } else {
      j["command"] = r.command;
      j["args"] = argList(toUtf8(r.args));
    }
    if (r.hasPose) {
      j["x"] = rounded(r.pose.pos.x());
      j["y"] = rounded(r.pose.pos.y());
      j["heading"] = rounded(r.pose.heading);
      j["pen"] = r.pen ? "down" : "up";
      if (r.event == "end") j["located"] = r.located;
    }
    if (r.value) j["value"] = number(*r.value);
    std::string line = j.dump(-1, ' ', false, Json::error_handler_t::replace);
    std::fprintf(out_, "%s\n", line.c_str());
  }

  void writeCsv(const Record& r) {
    std::string x, y, h, pen;
    if (r.hasPose) {
      x = fixed(r.pose.pos.x());
      y = fixed(r.pose.pos.y());
      h = fixed(r.pose.heading);
      pen = r.pen ? "down" : "up";
    }
    bool end = r.event == "end";
    std::string command = end ? r.limit : r.command;
    std::string col = end || r.event == "output" ? std::to_string(r.loc.col) : "";
    std::string text = r.text;
    std::string row = (program_.empty() ? "" : csvField(program_) + ",") + std::to_string(seq_) + "," +
                      csvField(fileName(r.loc)) + "," + std::to_string(r.loc.line) + "," + r.event + "," +
                      csvField(command) + "," + csvField(r.args) + "," + x + "," + y + "," + h + "," + pen + "," +
                      (r.value ? formatNumber(*r.value) : "") + "," + col + "," + csvField(text) + "," +
                      r.status + "," + (r.steps ? std::to_string(*r.steps) : "");
    std::fprintf(out_, "%s\n", row.c_str());
  }

  void writeText(const Record& r) {
    std::string file = fileName(r.loc);
    std::string where = r.loc.file == 0 ? std::to_string(r.loc.line) : file + ":" + std::to_string(r.loc.line);
    std::string pose;
    if (r.hasPose) {
      pose = " -> x=" + fixed(r.pose.pos.x()) + " y=" + fixed(r.pose.pos.y()) + " heading=" + fixed(r.pose.heading) +
             " pen=" + (r.pen ? "down" : "up");
    }
    std::string out;
    if (r.event == "output") {
      out = std::to_string(seq_) + " line " + where + ": output " + cQuoted(r.text);
    } else if (r.event == "end") {
      out = std::to_string(seq_) + " end: " + r.status;
      if (!r.limit.empty()) out += " (" + r.limit + ")";
      if (r.loc.valid()) out += " at " + file + ":" + std::to_string(r.loc.line) + ":" + std::to_string(r.loc.col);
      if (r.steps) out += " after " + std::to_string(*r.steps) + " steps";
      if (!r.text.empty()) out += ": " + r.text;
      out += pose;
    } else {
      std::string call = r.command.empty() ? r.event : r.command + (r.args.empty() ? "" : " " + r.args);
      out = std::to_string(seq_) + " line " + where + ": " + call + pose;
      if (r.value) out += " value=" + formatNumber(*r.value);
      if (r.event == "crash") out += " CRASH";
    }
    std::fprintf(out_, "%s\n", out.c_str());
  }

  const TraceOptions& opts_;
  std::FILE* out_;
  const HeadlessRun& run_;  ///< for the names of included files, the machine, the result
  std::string program_;
  uint64_t seq_ = 0;
  SourceLoc last_;          ///< the statement running now
  uint64_t statements_ = 0; ///< statements started so far
};

std::string extensionFor(const std::string& format) {
  return format == "jsonl" ? ".jsonl" : format == "csv" ? ".csv" : ".trace";
}

/// Traces one program into `out`; returns rb run's exit code for it.
int traceOne(const TraceOptions& opts, const std::string& file, std::FILE* out, const std::string& program) {
  TraceOptions one = opts;
  one.run.file = file;
  HeadlessRun run;
  TraceWriter writer(one, out, run, program);
  CompileOptions compile;
  compile.lineTracing = true;  // to know the line of each output (and for --lines)
  int code = runHeadless("rb trace", one.run, compile, nullptr, &writer, run,
                         [&](SourceLoc loc) { writer.line(loc); },
                         [&](std::string_view text) { writer.output(text); });
  writer.end(code);
  std::fflush(out);
  return code;
}

int executeTrace(const TraceOptions& opts) {
  bool several = opts.files.size() > 1;
  if (!opts.outDir.empty()) {
    std::map<std::string, std::string> names;
    for (const std::string& f : opts.files) {
      std::string name = fs::path(f).stem().string() + extensionFor(opts.format);
      if (auto [it, fresh] = names.emplace(name, f); !fresh) {
        std::fprintf(stderr, "rb trace: '%s' and '%s' would both be traced to %s; trace them separately\n",
                     it->second.c_str(), f.c_str(), name.c_str());
        return exitcode::kUsage;
      }
    }
    std::string error;
    if (!render::makeFolder(opts.outDir, error)) {
      std::fprintf(stderr, "rb trace: %s\n", error.c_str());
      return exitcode::kIoError;
    }
  }
  int result = exitcode::kOk;
  for (size_t i = 0; i < opts.files.size(); ++i) {
    const std::string& file = opts.files[i];
    int code;
    if (!opts.outDir.empty()) {
      fs::path path = fs::path(opts.outDir) / (fs::path(file).stem().string() + extensionFor(opts.format));
      std::FILE* out = std::fopen(path.c_str(), "wb");
      if (!out) {
        std::fprintf(stderr, "rb trace: cannot write '%s'\n", path.c_str());
        return exitcode::kIoError;
      }
      TraceWriter::firstCsv_ = true;
      code = traceOne(opts, file, out, "");
      bool failed = std::ferror(out) != 0;
      if (std::fclose(out) != 0 || failed) {
        std::fprintf(stderr, "rb trace: cannot write '%s'\n", path.c_str());
        return exitcode::kIoError;
      }
    } else {
      if (several && opts.format == "text") std::printf("%s==> %s <==\n", i ? "\n" : "", file.c_str());
      TraceWriter::firstCsv_ = i == 0;
      code = traceOne(opts, file, stdout, several && opts.format != "text" ? file : "");
    }
    if (result == exitcode::kOk) result = code;
  }
  if (std::ferror(stdout)) {
    std::fprintf(stderr, "rb trace: cannot write to standard output\n");
    return exitcode::kIoError;
  }
  return result;
}

}  // namespace

void addTraceCommand(CLI::App& app, int& exitCode, bool withOptions) {
  auto opts = std::make_shared<TraceOptions>();
  CLI::App* trace = app.add_subcommand(
      "trace", "Run programs headless and print what the robot did, one line per event");
  if (!withOptions) return;
  trace->add_option("files", opts->files, "Program files (- reads standard input)")->required();
  addRunLimitOptions(*trace, opts->run);
  trace->add_option("--format", opts->format, "text, jsonl (one JSON object per line) or csv")
      ->check(CLI::IsMember({"text", "jsonl", "csv"}));
  trace->add_option("--out", opts->outDir,
                    "Write each program's trace to DIR/NAME.trace (.jsonl, .csv) instead of "
                    "standard output")
      ->type_name("DIR");
  trace->add_flag("--sensors", opts->sensors, "Also list every sensor reading with its value");
  trace->add_flag("--lines", opts->lines, "Also list every statement executed (like TRON)");
  trace->footer(
      "Each line: sequence number, source line, command and arguments, then the robot's pose "
      "after it (x, y, heading in degrees) and its pen. What the program prints is an output "
      "event with its line; the last record (end) says how the run ended: finished, error "
      "(file:line:col and message), limit, rejected or not-run, with the steps and the final "
      "pose. Several files: one stream after another (each record names its program), or one "
      "file each with --out. Exit status as for rb run (of the first program that failed). "
      "Manual: man rb-trace.");
  trace->callback([opts, &exitCode] { exitCode = executeTrace(*opts); });
}

}  // namespace rb::cli
