#include "trace_writer.h"

#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>

#include "base/text.h"
#include "record.h"
#include "text.h"

namespace rb::record {

namespace {

using Json = nlohmann::ordered_json;

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

}  // namespace

/// What one record of the stream says; the formats render it.
struct TraceRecord {
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
  std::vector<DiagRecord> errors;  ///< end of a rejected program: its load errors
};

TraceWriter::TraceWriter(TraceSettings settings, std::FILE* out, std::string program, bool csvHeader,
                       std::function<const SourceSet*()> sources, std::function<const Machine*()> machine)
  : opts_(std::move(settings)), out_(out), program_(std::move(program)), sources_(std::move(sources)),
    machine_(std::move(machine)) {
  if (opts_.format == "csv" && csvHeader)
  std::fprintf(out_, "%sseq,file,line,event,command,args,x,y,heading,pen,value,col,text,status,steps\n",
               program_.empty() ? "" : "program,");
}

void TraceWriter::robotEvent(const RobotEvent& e) {
  if (e.kind == RobotEvent::Sensor && !opts_.sensors) return;
  TraceRecord r;
  r.event = eventName(e.kind);
  r.command = std::string(e.command);
  r.args = e.args;
  r.loc = e.loc;
  r.pose = e.pose;
  r.pen = e.pen;
  r.value = e.value;
  write(r);
}

void TraceWriter::line(SourceLoc loc) {
  last_ = loc;
  ++statements_;
  if (!opts_.lines) return;
  TraceRecord r;
  r.event = "line";
  r.loc = loc;
  const Machine* m = machine_();
  if (m) {
    r.pose = m->robot().pose();
    r.pen = m->robot().penDown();
  }
  write(r);
}

void TraceWriter::output(std::string_view text) {
  TraceRecord r;
  r.event = "output";
  r.loc = last_;
  r.text = std::string(text);
  const Machine* m = machine_();
  if (m) {
    r.pose = m->robot().pose();
    r.pen = m->robot().penDown();
  }
  write(r);
}

void TraceWriter::end(const TraceEnd& e) {
  TraceRecord r;
  r.event = "end";
  r.exit = e.exit;
  r.hasPose = false;
  const SourceSet* sources = sources_();
  if (e.result) {
    const RunResult& result = *e.result;
    r.status = statusName(result.status);
    r.limit = limitName(result.status);
    if (result.status == RunStatus::StepLimit && !e.stepLimitIsError) r.status = "limit";
    r.steps = e.steps;
    if (result.error) {
      r.loc = result.error->loc;
      r.text = result.error->message;
    }
    const Machine* m = machine_();
    if (m) {
      r.hasPose = true;
      r.pose = m->robot().pose();
      r.pen = m->robot().penDown();
      r.located = m->robot().located();
    }
  } else if (e.loadErrors) {
    r.status = "rejected";
    r.steps = 0;
    for (const Diagnostic& d : e.loadErrors->all()) {
      if (d.severity != Severity::Error) continue;
      DiagRecord rec;
      if (sources && d.loc.valid() && d.loc.file < sources->size()) rec.file = sources->file(d.loc.file).name();
      rec.line = d.loc.line;
      rec.col = d.loc.col;
      rec.message = d.message;
      r.errors.push_back(rec);
    }
    if (!r.errors.empty()) r.text = r.errors[0].message;
    for (const Diagnostic& d : e.loadErrors->all())
      if (d.severity == Severity::Error) {
        r.loc = d.loc;
        break;
      }
  } else {
    r.status = "not-run";
    r.text = e.notRun;
  }
  write(r);
}

std::string TraceWriter::fileName(SourceLoc loc) const {
  const SourceSet* sources = sources_();
  return sources && loc.valid() && loc.file < sources->size() ? sources->file(loc.file).name() : "";
  }

void TraceWriter::write(const TraceRecord& r) {
  ++seq_;
  if (opts_.format == "jsonl") writeJson(r);
  else if (opts_.format == "csv") writeCsv(r);
  else writeText(r);
  }

/// JSON strings are UTF-8; a Windows program's Latin-1 text is converted (record/text.h).
void TraceWriter::writeJson(const TraceRecord& r) {
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
      for (const DiagRecord& e : r.errors)
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

void TraceWriter::writeCsv(const TraceRecord& r) {
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

void TraceWriter::writeText(const TraceRecord& r) {
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


}  // namespace rb::record
