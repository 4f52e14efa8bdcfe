// The evidence behind every name of the standard built-in table: the public RobotBASIC source
// that names it, or, for a name no source shows, why rb has it and what RobotBASIC is known to
// have instead. One row per name (a name that is both a command and a function, MsgBox, has one
// row); applyEvidence() puts each on its built-ins and refuses a table where a built-in has no
// row or a row names no built-in. docs/compatibility.md lists the sources in full and counts
// this table (scripts/gen_builtins_doc.py); docs/builtins.md shows each row; `rb check
// --portable` warns at every use of a name that is rb's own.
//
// How sources are cited (docs/compatibility.md, "Where the names come from"):
//   seed                 "Robot Projects for RobotBASIC", Volume I, Project 1 (shared/seed)
//   course ...           the CSE435 Robotics course (GitHub Nora-Lootfy/CSE435-Robotics): its
//                        cheat sheet (labs/robotBasicCheatSheet.md), lab handouts
//                        (labs/labN...) and programs (labs/labN/code/*.BAS)
//   SERVO, March 2008    RobotBASIC's authors' article, pp. 60-61, with the protocol table
//   SERVO listing, published path planner, published menu, published programs: as
//                        docs/compatibility.md has cited them since they were read (2026-11-23)
//   SR15 RROS firmware   a robot firmware written for RobotBASIC's protocol
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "machine/builtins_impl.h"

namespace rb::builtins {

namespace {

struct Row {
  std::string_view name;
  Evidence evidence;
};

Row seen(std::string_view name, std::string_view source) { return {name, {source, {}, {}}}; }
Row own(std::string_view name, std::string_view reason, std::string_view instead = {}) {
  return {name, {{}, reason, instead}};
}

constexpr std::string_view kPalette = "the rest of the 16-colour palette (docs/graphics.md)";
constexpr std::string_view kMath = "a usual math function";
constexpr std::string_view kString = "a usual string function";
constexpr std::string_view kKeyCode = "a named key code for getKeyE and keyDown";
constexpr std::string_view kButton = "a dialog button of the screen (docs/interaction.md)";
constexpr std::string_view kEdit = "an edit box of the screen (docs/interaction.md)";

const std::vector<Row>& rows() {
  static const std::vector<Row> table = {
      // ---- constants
      seen("True", "seed, Figure 1.13; course lab 3 programs"),
      seen("False", "seed, Figure 1.13; course lab 2"),
      seen("Up", "course cheat sheet; course lab 3 program mouseControl.BAS"),
      seen("Down", "seed, Figure 1.7; course cheat sheet"),
      own("On", "the word flip takes (flip on)", "True (1)"),
      own("Off", "the word flip takes (flip off)", "False (0)"),
      seen("Black", "course lab 4 program randomRoaming.BAS"),
      seen("Blue", "course cheat sheet; course lab 3 program mouseControl.BAS"),
      seen("Green", "seed, Figure 1.7"),
      seen("Cyan", "published menu"),
      seen("Red", "course lab 1; course lab 2"),
      seen("Magenta", "course lab 3 program mouseControl.BAS"),
      own("Brown", kPalette),
      own("Gray", "the palette; screenshots confirm its colour, no source its name"),
      own("DarkGray", kPalette),
      own("LightBlue", kPalette),
      own("LightGreen", kPalette),
      own("LightCyan", kPalette),
      own("LightRed", "the palette; screenshots confirm its colour, no source its name"),
      own("LightMagenta", kPalette),
      own("Yellow", kPalette),
      seen("White", "published menu"),
      seen("fs_Bold", "published program (xyText)"),
      own("fs_Italic", "the other xyText styles, by the Windows font-style bits"),
      own("fs_Underline", "the other xyText styles, by the Windows font-style bits"),
      own("fs_StrikeOut", "the other xyText styles, by the Windows font-style bits"),
      own("kc_Enter", kKeyCode, "13 (getKey gives character codes)"),
      own("kc_Esc", kKeyCode, "27 (getKey gives character codes)"),
      own("kc_Space", kKeyCode, "ascii(\" \")"),
      own("kc_Tab", kKeyCode, "9 (getKey gives character codes)"),
      own("kc_BackSpace", kKeyCode, "8 (getKey gives character codes)"),
      own("kc_Up", kKeyCode),
      own("kc_Down", kKeyCode),
      own("kc_Left", kKeyCode),
      own("kc_Right", kKeyCode),
      own("kc_PgUp", kKeyCode),
      own("kc_PgDn", kKeyCode),
      own("kc_End", kKeyCode),
      own("kc_Home", kKeyCode),
      own("kc_Insert", kKeyCode),
      own("kc_Delete", kKeyCode),
      own("kc_F1", kKeyCode),
      own("kc_F2", kKeyCode),
      own("kc_F3", kKeyCode),
      own("kc_F4", kKeyCode),
      own("kc_F5", kKeyCode),
      own("kc_F6", kKeyCode),
      own("kc_F7", kKeyCode),
      own("kc_F8", kKeyCode),
      own("kc_F9", kKeyCode),
      own("kc_F10", kKeyCode),
      own("kc_F11", kKeyCode),
      own("kc_F12", kKeyCode),
      seen("P_NOWAIT", "published programs (Spawn)"),

      // ---- math
      own("abs", kMath),
      own("sqrt", kMath),
      own("sin", kMath),
      own("cos", kMath),
      own("tan", kMath),
      own("asin", kMath),
      own("acos", kMath),
      own("atan", kMath),
      own("atan2", kMath, "polarA(x, y) (the arguments the other way round)"),
      own("exp", kMath),
      own("ln", kMath),
      own("log", kMath),
      own("pow", kMath, "x ^ y"),
      own("int", kMath),
      own("floor", kMath),
      own("ceil", kMath),
      own("frac", kMath),
      seen("round", "course lab 3 program mouseControl.BAS"),
      seen("sign", "course lab 5 programs randomRoaming1.BAS, randomRoaming2.BAS"),
      own("min", kMath),
      own("max", kMath),
      own("limit", "clamping, a common helper"),
      own("within", "a range test, a common helper", "x >= low and x <= high"),
      seen("pi", "course lab 3 program mouseControl.BAS"),
      own("rtod", "angle conversion, a common helper", "x * 180 / pi()"),
      own("dtor", "angle conversion, a common helper", "x * pi() / 180"),
      seen("polarA", "course cheat sheet; course lab 3 program mouseControl.BAS"),
      seen("polarR", "course cheat sheet; course lab 3 program mouseControl.BAS"),
      own("cartX", "the inverse of polarR/polarA, a common helper"),
      own("cartY", "the inverse of polarR/polarA, a common helper"),
      seen("random", "course lab 3; course lab 3 program generateRandomNumbers.BAS"),
      own("rRandom", "random reals", "random(n) (whole numbers 0 to n-1)"),
      own("randomize", "repeatable random numbers inside a program (rb's --seed does it outside)"),

      // ---- strings
      own("length", kString),
      own("left", kString),
      own("right", kString),
      own("mid", kString),
      own("upper", kString),
      own("lower", kString),
      own("trim", kString),
      own("trimL", kString),
      own("trimR", kString),
      own("spaces", kString),
      own("reverse", kString),
      own("instr", kString),
      own("contains", kString),
      own("replace", kString),
      own("extract", kString),
      seen("char", "course cheat sheet; course lab 3"),
      seen("ascii", "course cheat sheet; course lab 3; course lab 3 programs"),
      own("toString", kString),
      own("toNumber", kString),
      own("isNumber", "a type test for typeless values"),
      own("isString", "a type test for typeless values"),

      // ---- time
      own("timer", "measuring time in a program"),
      seen("delay", "course lab 3 program toggleControl.BAS"),

      // ---- robot
      seen("rLocate", "seed, Figures 1.4 and 1.5; course cheat sheet; course lab 1; SERVO, March 2008, protocol table"),
      seen("rForward", "seed, Figure 1.5; course cheat sheet; course lab 1; SERVO, March 2008, protocol table"),
      seen("rTurn", "seed, Figure 1.5; course cheat sheet; course lab 1; SERVO, March 2008, protocol table"),
      seen("rSpeed", "seed, before Figure 1.6; course cheat sheet; course lab 1; SERVO, March 2008, protocol table"),
      seen("rPen", "seed, Figure 1.7; course cheat sheet; SERVO, March 2008, protocol table"),
      seen("rInvisible", "seed, Figure 1.7; course cheat sheet"),
      seen("rSlip", "seed, Figure 1.10"),
      seen("rCommPort", "SERVO, March 2008, p. 61"),
      own("rCommand",
          "raw protocol commands for a real robot (SERVO, March 2008, p. 60 lets programs add "
          "their own commands; the name is rb's)"),
      seen("rBumper", "course cheat sheet; course lab 2; course lab 3 program mouseControl.BAS; SR15 RROS firmware"),
      seen("rFeel", "course cheat sheet; course lab 2; course lab 5 programs; SR15 RROS firmware"),
      seen("rSense", "SERVO, March 2008, p. 60; SR15 RROS firmware"),
      seen("rRange", "course cheat sheet; course lab 2; SERVO, March 2008, protocol table"),
      seen("rLook", "course cheat sheet; course lab 2; SERVO, March 2008, protocol table"),
      seen("rBeacon", "course cheat sheet; course lab 2; SERVO, March 2008, protocol table"),
      seen("rCompass", "course cheat sheet; course lab 2; SERVO, March 2008, protocol table"),
      seen("rGPSX", "course cheat sheet (rGpsX); course lab 2"),
      seen("rGPSY", "course cheat sheet (rGpsY); course lab 1"),
      seen("rChargeLevel", "course cheat sheet; course lab 2"),

      // ---- graphics
      seen("clearScr", "course cheat sheet; course lab 4; course lab 4 program draw.BAS"),
      seen("setColor", "course cheat sheet; course lab 4; course lab 4 program randomRoaming.BAS"),
      seen("lineWidth", "seed, Figure 1.7; course cheat sheet; course lab 4"),
      seen("gotoXY", "course cheat sheet; course lab 4 program draw.BAS"),
      seen("lineTo", "course cheat sheet; course lab 4 program draw.BAS"),
      own("line", "a segment in one statement", "gotoXY x1, y1 then lineTo x2, y2"),
      seen("rectangle", "course cheat sheet; course lab 1; published menu"),
      own("rectangleWH", "a rectangle by its size", "rectangle x, y, x + w, y + h"),
      seen("eRectangle", "published menu"),
      seen("circle", "course cheat sheet; course lab 1; course lab 2"),
      own("circleWH", "an ellipse by its size", "circle x, y, x + w, y + h"),
      own("eCircle", "eRectangle's twin", "lineWidth w, then circle x1, y1, x2, y2, colour"),
      own("polygon", "a polygon from an array of vertices", "mPolygon with a data array"),
      seen("mPolygon", "published path planner (its data and a screenshot)"),
      own("setPixel", "one pixel"),
      own("pixelClr", "reading the screen back (rb's tests read what was drawn with it)"),
      own("floodFill", "filling a region"),
      seen("xyString", "course cheat sheet; course lab 2"),
      seen("xyText", "published program (xyText x,y,text,\"\",size,fs_Bold)"),
      own("saveScr", "remembering the screen"),
      own("restoreScr", "remembering the screen"),
      own("flip", "double buffering for the live view"),
      own("RGB", "colours beyond the palette"),

      // ---- input
      seen("getKey", "course cheat sheet; course lab 3; course lab 3 program toggleControl.BAS"),
      own("getKeyE", "arrow and function keys", "getKey"),
      seen("waitKey", "course cheat sheet; course lab 2; course lab 3 programs"),
      own("keyDown", "whether one key is held", "getKey key (the key held now)"),
      seen("readMouse", "course cheat sheet; course lab 3; course lab 3 program mouseControl.BAS"),
      own("waitClick", "waiting for a click", "readMouse x, y, b in a loop until b is not 0"),
      seen("MsgBox", "published path planner (n = MsgBox(IM))"),
      own("AddButton", kButton),
      own("GetButton", kButton),
      own("LastButton", kButton),
      own("RemoveButton", kButton),
      own("AddEdit", kEdit, "input \"prompt\", var"),
      own("GetEdit", kEdit, "input \"prompt\", var"),
      own("SetEdit", kEdit),
      own("RemoveEdit", kEdit),

      // ---- arrays, files, the clipboard, other programs
      seen("MaxDim", "published program (MaxDim(a,1)-1 as a loop bound)"),
      seen("mFromString", "SERVO listing"),
      seen("GetCBtext", "published programs"),
      seen("SetCBtext", "published programs"),
      seen("FileExists", "published programs"),
      seen("FileRename", "published programs"),
      seen("DirSet", "published programs"),
      seen("Spawn", "published programs (Spawn(cmd, P_NOWAIT))"),
  };
  return table;
}

}  // namespace

void applyEvidence(std::vector<Builtin>& table) {
  std::unordered_map<std::string_view, const Row*> byName;
  for (const Row& r : rows()) {
    if (!byName.emplace(r.name, &r).second)
      throw std::logic_error("evidence: '" + std::string(r.name) + "' has two rows");
    if (r.evidence.confirmed() == !r.evidence.reason.empty())
      throw std::logic_error("evidence: '" + std::string(r.name) + "' needs a source or a reason (not both)");
    if (r.evidence.confirmed() && !r.evidence.instead.empty())
      throw std::logic_error("evidence: '" + std::string(r.name) + "' is confirmed: nothing instead");
  }
  std::unordered_map<std::string_view, bool> used;
  for (Builtin& b : table) {
    auto it = byName.find(b.name);
    if (it == byName.end())
      throw std::logic_error("evidence: the built-in '" + std::string(b.name) + "' has no evidence row");
    b.evidence = it->second->evidence;
    used[b.name] = true;
  }
  for (const Row& r : rows())
    if (!used.count(r.name))
      throw std::logic_error("evidence: the row '" + std::string(r.name) + "' names no built-in");
}

}  // namespace rb::builtins
