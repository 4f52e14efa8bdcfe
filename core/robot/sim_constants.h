#pragma once
// Every number that defines the simulated robot and its sensors, in one place. Where the
// public record of RobotBASIC is silent these are rb's choices (docs/robot.md states them);
// a better-sourced value is a one-line change here.

namespace rb::sim {

/// rLocate's defaults and limits: the robot is a disc; radius 20 makes it 40 pixels across,
/// as the seed document says.
constexpr double kDefaultRadius = 20;
constexpr double kMinRadius = 5;
constexpr double kMaxRadius = 50;
constexpr int kDefaultColour = 1;  // Blue

/// rForward moves in steps of at most this many pixels, checking for a crash after each.
constexpr double kMaxStep = 1.0;

/// rBumper(): an obstacle within this many pixels of the robot's edge presses a bumper.
/// Bumpers cover 90-degree quadrants around the heading: front (bit 4) within +-45 degrees,
/// right (bit 2), rear (bit 1), left (bit 8).
constexpr double kBumperReach = 2;
constexpr int kBumperRear = 1, kBumperRight = 2, kBumperFront = 4, kBumperLeft = 8;

/// rFeel(): five infrared sensors at these angles from the heading (clockwise positive) with
/// these bits; each sees obstacles within kFeelReach pixels of the edge inside a cone of
/// kFeelHalfAngle degrees either side of its direction.
constexpr double kFeelReach = 20;
constexpr double kFeelHalfAngle = 10;
constexpr double kFeelAngles[5] = {90, 45, 0, -45, -90};
constexpr int kFeelBits[5] = {1, 2, 4, 8, 16};

/// rSense(): three floor sensors kSenseAhead radii ahead of the centre, the side ones
/// kSenseSide radii to the left (bit 4) and right (bit 1) of the middle one (bit 2). A sensor
/// reads 1 over any pixel that is not the background.
constexpr double kSenseAhead = 0.5;
constexpr double kSenseSide = 1.0 / 3.0;
constexpr int kSenseLeft = 4, kSenseMiddle = 2, kSenseRight = 1;

/// rChargeLevel(): starts full and loses one percent every kChargePixelsPerPercent pixels
/// driven (turning in place costs kChargeDegreesPerPercent degrees per percent).
constexpr double kChargeFull = 100;
constexpr double kChargePixelsPerPercent = 1000;
constexpr double kChargeDegreesPerPercent = 3600;

/// rLook() at the screen edge: the colour of the wall around the screen.
constexpr int kEdgeColour = 0;  // Black

}  // namespace rb::sim
