// RB-9.bas: the library for RobotBASIC's RB-9 robot, shipped with rb.
// Include it at the top of a program, as the seed document does:
//     #include "RB-9.bas"
//     gosub InitRROScommands
// The library jumps over its own subroutines, so including it first runs nothing.
goto RB9_LibraryEnd

// Named variables for the RROS command codes (rCommand(code, parameter) sends one).
// The seed document spells the label both ways; labels are case-sensitive, so both exist.
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
  RROS_MaxMove = 250
return

// Connects to the real robot on serial port PortNum (rb run --port overrides it).
InitializeRealRobot:
  rCommPort PortNum
return

RB9_LibraryEnd:
