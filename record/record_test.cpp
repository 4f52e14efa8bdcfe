#include "record.h"

#include <catch2/catch.hpp>

using namespace rb;
using namespace rb::record;

namespace {

RobotEvent event(RobotEvent::Kind kind, double x, double y, bool pen) {
  RobotEvent e{kind, "rForward", {}, "", Pose{}, pen, std::nullopt};
  e.pose.pos = {x, y};
  return e;
}

}  // namespace

TEST_CASE("the path recorder splits the path at rLocate and the trail at pen changes", "[grade][record]") {
  PathRecorder r;
  r.robotEvent(event(RobotEvent::Locate, 400, 300, false));
  r.robotEvent(event(RobotEvent::Move, 400, 200, false));   // pen up: path only
  r.robotEvent(event(RobotEvent::Pen, 400, 200, true));
  r.robotEvent(event(RobotEvent::Turn, 400, 200, true));
  r.robotEvent(event(RobotEvent::Move, 500, 200, true));
  r.robotEvent(event(RobotEvent::Move, 500, 300, true));
  r.robotEvent(event(RobotEvent::Pen, 500, 300, false));
  r.robotEvent(event(RobotEvent::Move, 500, 350, false));
  r.robotEvent(event(RobotEvent::Locate, 100, 100, false));
  r.robotEvent(event(RobotEvent::Pen, 100, 100, true));
  r.robotEvent(event(RobotEvent::Crash, 100, 30, true));
  CHECK(r.path == Polylines{{{400, 300}, {400, 200}, {500, 200}, {500, 300}, {500, 350}}, {{100, 100}, {100, 30}}});
  CHECK(r.trail == Polylines{{{400, 200}, {500, 200}, {500, 300}}, {{100, 100}, {100, 30}}});
  CHECK(r.crashed);
  CHECK_FALSE(r.truncated);
}

TEST_CASE("the path recorder stops growing at its limit", "[grade][record]") {
  PathRecorder r;
  r.robotEvent(event(RobotEvent::Locate, 0, 0, true));
  for (size_t i = 1; i < PathRecorder::kMaxPoints + 10; ++i)
    r.robotEvent(event(RobotEvent::Move, static_cast<double>(i % 2), static_cast<double>(i), true));
  CHECK(r.truncated);
  CHECK(r.path[0].size() == PathRecorder::kMaxPoints);
}

TEST_CASE("a record survives its JSON", "[grade][record]") {
  RunRecord r;
  r.checkExit = 65;
  r.checkDiags = {{"a.bas", 3, 9, "error", "undefined label 'X'"}};
  r.targetDiags = {{"a.bas", 4, 1, "warning", "rLook is not on the RB-9"}};
  r.exitCode = 70;
  r.status = "error";
  r.error = DiagRecord{"a.bas", 6, 1, "error", "robot crashed into an obstacle"};
  r.crashed = true;
  r.steps = 418;
  r.seed = 7;
  r.located = true;
  r.pos = {400.5, 20};
  r.heading = 90;
  r.penDown = true;
  r.path = {{{400, 300}, {400.5, 20}}};
  r.trail = r.path;
  std::string error;
  std::optional<RunRecord> back = recordFromJson(recordToJson(r), error);
  REQUIRE(back);
  CHECK(back->checkDiags == r.checkDiags);
  CHECK(back->targetDiags == r.targetDiags);
  CHECK(back->error == r.error);
  CHECK(back->steps == 418);
  CHECK(back->pos == r.pos);
  CHECK(back->trail == r.trail);
  CHECK(back->crashed);
  CHECK_FALSE(recordFromJson("{\"check\": 1}", error));
  CHECK_FALSE(error.empty());
  CHECK_FALSE(recordFromJson("not json", error));
}

TEST_CASE("run statuses have names", "[grade][record]") {
  CHECK(statusName(RunStatus::Finished) == "finished");
  CHECK(statusName(RunStatus::RuntimeError) == "error");
  CHECK(statusName(RunStatus::StepLimit) == "limit");
  CHECK(limitName(RunStatus::StepLimit) == "max-steps");
  CHECK(limitName(RunStatus::Timeout) == "timeout");
  CHECK(limitName(RunStatus::Finished).empty());
}
