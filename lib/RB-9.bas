// RB-9.bas: the library for RobotBASIC's RB-9 robot, shipped with rb (docs/real-robot.md).
// Include it at the top of a program, as the seed document does:
//     #include "RB-9.bas"
//     gosub InitRROScommands
// The library jumps over its own subroutines, so including it first runs nothing. Its own
// labels and variables start with RB9_ or RROS_ so that they cannot clash with a program's.
goto RB9_LibraryEnd

// Named variables for the RROS command codes (rCommand(code, parameter) sends one; the
// table is in docs/real-robot.md). The seed document spells the label both ways; labels are
// case-sensitive, so both exist.
InitRROScommands:
InitRROscommands:
  RROS_Locate = 3
  RROS_Forward = 6
  RROS_Backward = 7
  RROS_TurnRight = 12
  RROS_TurnLeft = 13
  RROS_Compass = 24
  RROS_Speed = 36
  RROS_LookRight = 48
  RROS_LookLeft = 49
  RROS_GPS = 66
  RROS_Beacon = 96
  RROS_Pen = 129
  RROS_RangeRight = 192
  RROS_RangeLeft = 193
  RROS_Status = 6      // sent with parameter 0 (a move of 0): answers with fresh sensor data
  RROS_MaxMove = 250   // the RB-9 moves at most about this far per rForward
return

// Connects to the real robot on serial port PortNum (rb run --port N|PATH overrides it) and
// sends the initialise command. If the robot does not answer, the program stops here with an
// error that names the port. The robot is then taken to stand at (400, 300) facing up, where
// the simulator's programs start.
InitializeRealRobot:
  rCommPort PortNum
  rLocate 400,300
return

// The simulator set up as the seed document's InitializeSimulator does (Figure 1.13), from
// the same start as InitializeRealRobot. For programs without an InitializeSimulator of their
// own:
//     if Real
//       gosub InitializeRealRobot
//     else
//       gosub RB9_InitializeSimulator
//     endif
RB9_InitializeSimulator:
  rLocate 400,300
  rInvisible GREEN
  LineWidth 4
  rPen DOWN
return

RB9_LibraryEnd:
