#pragma once
// The robot as the pictures draw it, taken from a Machine: shared by rb render and the live
// terminal view so both show the same pose.

#include "arena_view.h"
#include "machine/machine.h"

namespace rb::render {

/// The robot's view: visible once rLocate placed it; the pose is the one a trace shows (the
/// real robot's dead-reckoned pose when one is connected, else the simulator's).
inline RobotView robotView(const Machine& machine) {
  RobotView view;
  view.visible = machine.robotLocated();
  const Pose& pose = machine.robotPose();
  view.x = pose.pos.x();
  view.y = pose.pos.y();
  view.heading = pose.heading;
  view.radius = machine.robot().radius();
  view.colour = machine.robot().colour();
  return view;
}

}  // namespace rb::render
