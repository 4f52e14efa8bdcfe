#include "trace_command.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "base/diagnostic.h"
#include "exit_codes.h"
#include "headless_run.h"

namespace rb::cli {

namespace {

struct TraceOptions {
  RunOptions run;
  std::string format = "text";
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

std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

/// Writes one line per event in the chosen format.
class TraceWriter : public RobotObserver {
 public:
  TraceWriter(const TraceOptions& opts, const HeadlessRun& run) : opts_(opts), run_(run) {
    if (opts_.format == "csv") std::printf("seq,file,line,event,command,args,x,y,heading,pen,value\n");
  }

  void robotEvent(const RobotEvent& e) override {
    if (e.kind == RobotEvent::Sensor && !opts_.sensors) return;
    std::optional<std::string> value;
    if (e.value) value = formatNumber(*e.value);
    write(eventName(e.kind), std::string(e.command), e.args, e.loc, e.pose, e.pen, value);
  }

  void line(SourceLoc loc, const SimRobot& robot) {
    write("line", "", "", loc, robot.pose(), robot.penDown(), std::nullopt);
  }

 private:
  void write(const char* event, const std::string& command, const std::string& args, SourceLoc loc,
             const Pose& pose, bool pen, const std::optional<std::string>& value) {
    ++seq_;
    const SourceSet* sources = run_.loaded.program ? &run_.loaded.program->sources : nullptr;
    std::string file = sources && loc.file < sources->size() ? sources->file(loc.file).name() : "";
    std::string where = loc.file == 0 ? std::to_string(loc.line) : file + ":" + std::to_string(loc.line);
    std::string x = fixed(pose.pos.x()), y = fixed(pose.pos.y()), h = fixed(pose.heading);
    const char* penText = pen ? "down" : "up";
    if (opts_.format == "jsonl") {
      std::string out = "{\"seq\":" + std::to_string(seq_) + ",\"file\":\"" + jsonEscape(file) +
                        "\",\"line\":" + std::to_string(loc.line) + ",\"event\":\"" + event +
                        "\",\"command\":\"" + jsonEscape(command) + "\",\"args\":\"" + jsonEscape(args) +
                        "\",\"x\":" + x + ",\"y\":" + y + ",\"heading\":" + h + ",\"pen\":\"" + penText + "\"";
      if (value) out += ",\"value\":" + *value;
      std::printf("%s}\n", out.c_str());
    } else if (opts_.format == "csv") {
      std::printf("%llu,%s,%u,%s,%s,%s,%s,%s,%s,%s,%s\n", static_cast<unsigned long long>(seq_),
                  csvField(file).c_str(), loc.line, event, command.c_str(), csvField(args).c_str(),
                  x.c_str(), y.c_str(), h.c_str(), penText, value ? value->c_str() : "");
    } else {
      std::string call = command.empty() ? std::string(event) : command + (args.empty() ? "" : " " + args);
      std::string out = std::to_string(seq_) + " line " + where + ": " + call + " -> x=" + x +
                        " y=" + y + " heading=" + h + " pen=" + penText;
      if (value) out += " value=" + *value;
      if (std::string(event) == "crash") out += " CRASH";
      std::printf("%s\n", out.c_str());
    }
  }

  const TraceOptions& opts_;
  const HeadlessRun& run_;  ///< for the names of included files
  uint64_t seq_ = 0;
};

int executeTrace(const TraceOptions& opts) {
  HeadlessRun run;
  TraceWriter writer(opts, run);
  CompileOptions compile;
  compile.lineTracing = opts.lines;
  std::function<void(SourceLoc)> onLine;
  if (opts.lines) onLine = [&](SourceLoc loc) { writer.line(loc, run.machine->robot()); };
  int code = runHeadless("rb trace", opts.run, compile, nullptr, &writer, run, onLine);
  std::fflush(stdout);
  return code;
}

}  // namespace

void addTraceCommand(CLI::App& app, int& exitCode) {
  auto opts = std::make_shared<TraceOptions>();
  CLI::App* trace = app.add_subcommand(
      "trace", "Run a program headless and print what the robot did, one line per event");
  trace->add_option("file", opts->run.file, "Program file (- reads standard input)")->required();
  addRunLimitOptions(*trace, opts->run);
  trace->add_option("--format", opts->format, "text, jsonl (one JSON object per line) or csv")
      ->check(CLI::IsMember({"text", "jsonl", "csv"}));
  trace->add_flag("--sensors", opts->sensors, "Also list every sensor reading with its value");
  trace->add_flag("--lines", opts->lines, "Also list every statement executed (like TRON)");
  trace->footer(
      "Each line: sequence number, source line, command and arguments, then the robot's pose "
      "after it (x, y, heading in degrees) and its pen. The program's own printed output is not "
      "shown. Exit status as for rb run.");
  trace->callback([opts, &exitCode] { exitCode = executeTrace(*opts); });
}

}  // namespace rb::cli
