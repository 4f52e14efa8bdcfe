#include "record.h"

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "text.h"

namespace rb::grade {

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

void PathRecorder::robotEvent(const RobotEvent& e) {
  P2 p{e.pose.pos.x(), e.pose.pos.y()};
  switch (e.kind) {
    case RobotEvent::Locate:
      add(path, pathPoints_, true, p);
      stroke_ = false;
      break;
    case RobotEvent::Move:
    case RobotEvent::Crash: {
      if (e.kind == RobotEvent::Crash) crashed = true;
      if (path.empty() && !add(path, pathPoints_, true, p)) break;
      P2 from = path.back().back();
      if (e.pen) {
        if (!stroke_) stroke_ = add(trail, trailPoints_, true, from);
        if (stroke_ && !(trail.back().back() == p)) add(trail, trailPoints_, false, p);
      }
      if (!(from == p)) add(path, pathPoints_, false, p);
      break;
    }
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

bool writeScreenFile(const std::string& path, const render::RgbImage& image, std::string& error) {
  std::string header = "P6\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n255\n";
  std::string bytes = header;
  bytes.append(reinterpret_cast<const char*>(image.rgb.data()), image.rgb.size());
  return render::writeFileBytes(path, bytes.data(), bytes.size(), error);
}

std::optional<render::RgbImage> readScreenFile(const std::string& path, std::string& error) {
  std::ifstream in(path, std::ios::binary);
  std::string magic;
  int width = 0, height = 0, depth = 0;
  if (!(in >> magic >> width >> height >> depth) || magic != "P6" || depth != 255 || width <= 0 ||
      height <= 0 || width > 10000 || height > 10000) {
    error = "cannot read the screen file " + path;
    return std::nullopt;
  }
  in.get();  // the one blank after the header
  render::RgbImage image;
  image.width = width;
  image.height = height;
  image.rgb.resize(static_cast<size_t>(width) * static_cast<size_t>(height) * 3);
  if (!in.read(reinterpret_cast<char*>(image.rgb.data()), static_cast<std::streamsize>(image.rgb.size()))) {
    error = "the screen file " + path + " is cut short";
    return std::nullopt;
  }
  return image;
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
  return j.dump();
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
    return r;
  } catch (const json::exception& e) {
    error = e.what();
    return std::nullopt;
  }
}

}  // namespace rb::grade
