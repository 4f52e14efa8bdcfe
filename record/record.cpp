#include "record.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "text.h"

namespace rb::record {

using nlohmann::json;

std::string statusName(RunStatus status) {
  switch (status) {
    case RunStatus::Finished: return "finished";
    case RunStatus::RuntimeError: return "error";
    case RunStatus::StepLimit:
    case RunStatus::Timeout: return "limit";
    case RunStatus::Stopped: return "stopped";
  }
  return "error";
}

std::string limitName(RunStatus status) {
  if (status == RunStatus::StepLimit) return "max-steps";
  if (status == RunStatus::Timeout) return "timeout";
  return "";
}

std::string printedOutput(const std::string& output, const std::vector<RunRecord::InputMark>& marks) {
  std::string text;
  size_t at = 0;
  for (const RunRecord::InputMark& m : marks) {
    if (m.start < at || m.start > output.size()) break;
    text.append(output, at, m.start - at);
    if (!text.empty() && text.back() != '\n') text += '\n';
    at = static_cast<size_t>(std::min<uint64_t>(m.end, output.size()));
  }
  if (at < output.size()) text.append(output, at, std::string::npos);
  return text;
}

bool PathRecorder::add(Polylines& lines, size_t& count, bool newLine, P2 p) {
  if (count >= kMaxPoints) {
    truncated = true;
    return false;
  }
  if (newLine || lines.empty()) lines.push_back({});
  lines.back().push_back(p);
  ++count;
  return true;
}

void PathRecorder::addPath(bool newLine, P2 p, uint32_t line) {
  if (!add(path, pathPoints_, newLine, p)) return;
  if (newLine || pathLines.size() < path.size()) pathLines.push_back({});
  pathLines.back().push_back(line);
}

void PathRecorder::robotEvent(const RobotEvent& e) {
  P2 p{e.pose.pos.x(), e.pose.pos.y()};
  uint32_t line = e.loc.file == 0 ? e.loc.line : 0;
  switch (e.kind) {
    case RobotEvent::Locate:
      ++moves;
      addPath(true, p, line);
      stroke_ = false;
      break;
    case RobotEvent::Move:
    case RobotEvent::Crash: {
      ++moves;
      if (e.kind == RobotEvent::Crash) crashed = true;
      if (path.empty()) {
        addPath(true, p, line);
        if (path.empty()) break;
      }
      P2 from = path.back().back();
      if (e.pen) {
        if (!stroke_) stroke_ = add(trail, trailPoints_, true, from);
        if (stroke_ && !(trail.back().back() == p)) add(trail, trailPoints_, false, p);
      }
      if (!(from == p)) addPath(false, p, line);
      break;
    }
    case RobotEvent::Turn:
      ++moves;
      break;
    case RobotEvent::Pen:
      if (!e.pen) stroke_ = false;
      break;
    default:
      break;
  }
}

namespace {

/// Messages can quote a Windows program's Latin-1 text: JSON carries it as UTF-8.
json diagJson(const DiagRecord& d) {
  return {{"file", toUtf8(d.file)}, {"line", d.line}, {"col", d.col}, {"severity", d.severity},
          {"message", toUtf8(d.message)}};
}

DiagRecord diagFrom(const json& j) {
  DiagRecord d;
  d.file = j.at("file").get<std::string>();
  d.line = j.at("line").get<uint32_t>();
  d.col = j.at("col").get<uint32_t>();
  d.severity = j.at("severity").get<std::string>();
  d.message = j.at("message").get<std::string>();
  return d;
}

json linesJson(const Polylines& lines) {
  json out = json::array();
  for (const Polyline& l : lines) {
    json pts = json::array();
    for (const P2& p : l) pts.push_back({p.x, p.y});
    out.push_back(std::move(pts));
  }
  return out;
}

Polylines linesFrom(const json& j) {
  Polylines out;
  for (const json& l : j) {
    Polyline pl;
    for (const json& p : l) pl.push_back({p.at(0).get<double>(), p.at(1).get<double>()});
    out.push_back(std::move(pl));
  }
  return out;
}

}  // namespace

std::string screenFileBytes(const std::vector<render::ColourRun>& runs, int width, int height) {
  std::string bytes = "RBRUNS1 " + std::to_string(width) + " " + std::to_string(height) + " " +
                      std::to_string(runs.size()) + "\n";
  size_t head = bytes.size();
  bytes.resize(head + runs.size() * 8);
  for (size_t i = 0; i < runs.size(); ++i)
    for (int k = 0; k < 4; ++k) {
      bytes[head + i * 8 + static_cast<size_t>(k)] = static_cast<char>(runs[i].count >> (8 * k));
      bytes[head + i * 8 + 4 + static_cast<size_t>(k)] = static_cast<char>(runs[i].rgb >> (8 * k));
    }
  return bytes;
}

bool writeScreenFile(const std::string& path, const std::vector<render::ColourRun>& runs, int width, int height,
                     std::string& error) {
  std::string bytes = screenFileBytes(runs, width, height);
  return render::writeFileBytes(path, bytes.data(), bytes.size(), error);
}

Screen screenOf(const render::RgbImage& image) {
  Screen s;
  s.width = image.width;
  s.height = image.height;
  size_t n = static_cast<size_t>(image.width) * static_cast<size_t>(image.height);
  for (size_t i = 0; i < n;) {
    uint32_t rgb = image.pixel(static_cast<int>(i % static_cast<size_t>(image.width)),
                               static_cast<int>(i / static_cast<size_t>(image.width)));
    const uint8_t* p = image.rgb.data() + i * 3;
    size_t j = i + 1;
    while (j < n && p[(j - i) * 3] == p[0] && p[(j - i) * 3 + 1] == p[1] && p[(j - i) * 3 + 2] == p[2]) ++j;
    s.runs.push_back({static_cast<uint32_t>(j - i), rgb});
    i = j;
  }
  return s;
}

render::RgbImage imageOf(const Screen& screen) { return render::imageFromRuns(screen.runs, screen.width, screen.height); }

std::optional<Screen> readScreenFile(const std::string& path, std::string& error) {
  std::ifstream in(path, std::ios::binary);
  std::string magic;
  long width = 0, height = 0, count = 0;
  if (!(in >> magic >> width >> height >> count) || magic != "RBRUNS1" || width <= 0 || height <= 0 ||
      width > 10000 || height > 10000 || count < 0 || count > width * height) {
    error = "cannot read the screen file " + path;
    return std::nullopt;
  }
  in.get();  // the line end after the header
  std::string bytes(static_cast<size_t>(count) * 8, '\0');
  if (!in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()))) {
    error = "the screen file " + path + " is cut short";
    return std::nullopt;
  }
  Screen screen;
  screen.width = static_cast<int>(width);
  screen.height = static_cast<int>(height);
  screen.runs.resize(static_cast<size_t>(count));
  auto word = [&](size_t at) {
    uint32_t v = 0;
    for (int k = 0; k < 4; ++k) v |= static_cast<uint32_t>(static_cast<uint8_t>(bytes[at + static_cast<size_t>(k)])) << (8 * k);
    return v;
  };
  uint64_t total = 0;
  for (size_t i = 0; i < screen.runs.size(); ++i) {
    screen.runs[i] = {word(i * 8), word(i * 8 + 4)};
    total += screen.runs[i].count;
  }
  if (total != static_cast<uint64_t>(width) * static_cast<uint64_t>(height)) {
    error = "the screen file " + path + " does not cover the screen";
    return std::nullopt;
  }
  return screen;
}

std::string recordToJson(const RunRecord& r) {
  json j;
  j["check"] = {{"exit", r.checkExit}, {"diagnostics", json::array()}};
  for (const DiagRecord& d : r.checkDiags) j["check"]["diagnostics"].push_back(diagJson(d));
  j["check"]["target"] = json::array();
  for (const DiagRecord& d : r.targetDiags) j["check"]["target"].push_back(diagJson(d));
  j["exit"] = r.exitCode;
  j["status"] = r.status;
  if (!r.limit.empty()) j["limit"] = r.limit;
  j["load_errors"] = json::array();
  for (const DiagRecord& d : r.loadErrors) j["load_errors"].push_back(diagJson(d));
  if (r.error) j["error"] = diagJson(*r.error);
  j["crashed"] = r.crashed;
  j["steps"] = r.steps;
  j["seed"] = r.seed;
  j["located"] = r.located;
  j["x"] = r.pos.x;
  j["y"] = r.pos.y;
  j["heading"] = r.heading;
  j["pen"] = r.penDown;
  j["path"] = linesJson(r.path);
  j["trail"] = linesJson(r.trail);
  j["truncated"] = r.truncated;
  j["screen"] = r.screen;
  j["complete"] = r.complete;
  j["statements"] = r.statements;
  j["moves"] = r.moves;
  j["radius"] = r.radius;
  j["path_lines"] = r.pathLines;
  j["inputs"] = json::array();
  for (const RunRecord::InputMark& m : r.inputs) j["inputs"].push_back({m.start, m.promptEnd, m.end});
  if (r.loopFirst) j["loop"] = {r.loopFirst, r.loopLast};
  j["touches"] = json::array();
  for (const RunRecord::Touch& t : r.touches)
    j["touches"].push_back({{"rgb", t.rgb}, {"touched", t.touched}, {"x", t.at.x}, {"y", t.at.y}, {"line", t.line}});
  if (!r.worldError.empty()) j["world_error"] = toUtf8(r.worldError);
  if (!r.confinement.empty()) j["confinement"] = toUtf8(r.confinement);
  j["posts"] = json::array();
  for (const RunRecord::Post& p : r.posts) {
    json pj = {{"file", toUtf8(p.file)}, {"output", toUtf8(p.output)}, {"ran", p.ran}};
    if (p.error) pj["error"] = diagJson(*p.error);
    j["posts"].push_back(std::move(pj));
  }
  return j.dump(-1, ' ', false, json::error_handler_t::replace);
}

std::optional<RunRecord> recordFromJson(std::string_view text, std::string& error) {
  try {
    json j = json::parse(text);
    RunRecord r;
    r.checkExit = j.at("check").at("exit").get<int>();
    for (const json& d : j.at("check").at("diagnostics")) r.checkDiags.push_back(diagFrom(d));
    for (const json& d : j.at("check").at("target")) r.targetDiags.push_back(diagFrom(d));
    r.exitCode = j.at("exit").get<int>();
    r.status = j.at("status").get<std::string>();
    if (j.contains("limit")) r.limit = j["limit"].get<std::string>();
    for (const json& d : j.at("load_errors")) r.loadErrors.push_back(diagFrom(d));
    if (j.contains("error")) r.error = diagFrom(j["error"]);
    r.crashed = j.at("crashed").get<bool>();
    r.steps = j.at("steps").get<uint64_t>();
    r.seed = j.at("seed").get<uint64_t>();
    r.located = j.at("located").get<bool>();
    r.pos = {j.at("x").get<double>(), j.at("y").get<double>()};
    r.heading = j.at("heading").get<double>();
    r.penDown = j.at("pen").get<bool>();
    r.path = linesFrom(j.at("path"));
    r.trail = linesFrom(j.at("trail"));
    r.truncated = j.at("truncated").get<bool>();
    r.screen = j.at("screen").get<bool>();
    r.complete = j.value("complete", true);
    r.statements = j.value("statements", uint64_t{0});
    r.moves = j.value("moves", uint64_t{0});
    r.radius = j.value("radius", 20.0);
    if (j.contains("path_lines")) r.pathLines = j["path_lines"].get<std::vector<std::vector<uint32_t>>>();
    if (j.contains("inputs"))
      for (const json& m : j["inputs"])
        r.inputs.push_back({m.at(0).get<uint64_t>(), m.at(1).get<uint64_t>(), m.at(2).get<uint64_t>()});
    if (j.contains("loop")) {
      r.loopFirst = j["loop"].at(0).get<uint32_t>();
      r.loopLast = j["loop"].at(1).get<uint32_t>();
    }
    if (j.contains("touches"))
      for (const json& t : j["touches"])
        r.touches.push_back({t.at("rgb").get<uint32_t>(), t.at("touched").get<bool>(),
                             {t.at("x").get<double>(), t.at("y").get<double>()}, t.at("line").get<uint32_t>()});
    r.worldError = j.value("world_error", std::string());
    r.confinement = j.value("confinement", std::string());
    if (j.contains("posts"))
      for (const json& pj : j["posts"]) {
        RunRecord::Post p;
        p.file = pj.at("file").get<std::string>();
        p.output = pj.at("output").get<std::string>();
        p.ran = pj.at("ran").get<bool>();
        if (pj.contains("error")) p.error = diagFrom(pj["error"]);
        r.posts.push_back(std::move(p));
      }
    return r;
  } catch (const json::exception& e) {
    error = e.what();
    return std::nullopt;
  }
}

}  // namespace rb::record
