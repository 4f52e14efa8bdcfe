#pragma once
// The robot as the pictures draw it, taken from a Machine: shared by rb render and the live
// terminal view so both show the same pose.

#include "arena_view.h"
#include "machine/machine.h"

namespace rb::render {

/// The robot's view: the active robot (the real robot's dead-reckoned pose when one is
/// connected, else the simulator), visible once rLocate placed it.
inline RobotView robotView(const Machine& machine) {
  const Robot& robot = machine.robot();
  RobotView view;
  view.visible = robot.located();
  view.x = robot.pose().pos.x();
  view.y = robot.pose().pos.y();
  view.heading = robot.pose().heading;
  view.radius = robot.radius();
  view.colour = robot.colour();
  return view;
}

}  // namespace rb::render
