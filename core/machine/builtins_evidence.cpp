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
#include <algorithm>
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

Row seen(std::string_view name, std::string_view source) { return {name, {source, {}, {}, {}}}; }
Row own(std::string_view name, std::string_view reason, std::string_view instead = {}) {
  return {name, {{}, reason, instead, {}}};
}
/// Named by the project's research notes (../shared/reference) as recalled from RobotBASIC's
/// documentation, tag [R]: not checked against a source, so not confirmed, but not rb's own
/// invention either; `rb check --portable` does not warn about it.
Row recalled(std::string_view name, std::string_view note, std::string_view reason, std::string_view instead = {}) {
  return {name, {{}, reason, instead, note}};
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
      recalled("On", "research notes, language.md 6.2: flip on / flip off ([R] medium)", "the word flip takes (flip on)", "True (1)"),
      recalled("Off", "research notes, language.md 6.2: flip on / flip off ([R] medium)", "the word flip takes (flip off)", "False (0)"),
      seen("Black", "course lab 4 program randomRoaming.BAS"),
      seen("Blue", "course cheat sheet; course lab 3 program mouseControl.BAS"),
      seen("Green", "seed, Figure 1.7"),
      seen("Cyan", "published menu"),
      seen("Red", "course lab 1; course lab 2"),
      seen("Magenta", "course lab 3 program mouseControl.BAS"),
      recalled("Brown", "research notes, language.md 6.3: the full palette ([R] medium)", kPalette),
      recalled("Gray", "research notes, language.md 6.3: the full palette ([R] medium)", "the palette; screenshots confirm its colour, no source its name"),
      recalled("DarkGray", "research notes, language.md 6.3: the full palette ([R] medium)", kPalette),
      recalled("LightBlue", "research notes, language.md 6.3: the full palette ([R] medium)", kPalette),
      recalled("LightGreen", "research notes, language.md 6.3: the full palette ([R] medium)", kPalette),
      recalled("LightCyan", "research notes, language.md 6.3: the full palette ([R] medium)", kPalette),
      recalled("LightRed", "research notes, language.md 6.3: the full palette ([R] medium)", "the palette; screenshots confirm its colour, no source its name"),
      recalled("LightMagenta", "research notes, language.md 6.3: the full palette ([R] medium)", kPalette),
      recalled("Yellow", "research notes, language.md 6.3: the full palette ([R] medium)", kPalette),
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
      recalled("abs", "research notes, language.md 5.1: recalled as RobotBASIC's math functions ([R])", kMath),
      recalled("sqrt", "research notes, language.md 5.1: recalled as RobotBASIC's math functions ([R] medium)", kMath),
      recalled("sin", "research notes, language.md 5.1: recalled as RobotBASIC's math functions ([R])", kMath),
      recalled("cos", "research notes, language.md 5.1: recalled as RobotBASIC's math functions ([R])", kMath),
      recalled("tan", "research notes, language.md 5.1: recalled as RobotBASIC's math functions ([R])", kMath),
      recalled("asin", "research notes, language.md 5.1: recalled as RobotBASIC's math functions ([R])", kMath),
      recalled("acos", "research notes, language.md 5.1: recalled as RobotBASIC's math functions ([R])", kMath),
      recalled("atan", "research notes, language.md 5.1: recalled as RobotBASIC's math functions ([R])", kMath),
      recalled("atan2", "research notes, language.md 5.1 ([R])", kMath, "polarA(x, y) (the arguments the other way round)"),
      recalled("exp", "research notes, language.md 5.1: recalled as RobotBASIC's math functions ([R])", kMath),
      recalled("ln", "research notes, language.md 5.1: recalled as RobotBASIC's math functions ([R])", kMath),
      recalled("log", "research notes, language.md 5.1: recalled as RobotBASIC's math functions ([R])", kMath),
      recalled("pow", "research notes, language.md 5.1 ([R] low)", kMath, "x ^ y"),
      recalled("int", "research notes, language.md 5.1 ([R])", kMath),
      recalled("floor", "research notes, language.md 5.1 ([R] low)", kMath),
      recalled("ceil", "research notes, language.md 5.1 ([R] low)", kMath),
      recalled("frac", "research notes, language.md 5.1 ([R] low)", kMath),
      seen("round", "course lab 3 program mouseControl.BAS"),
      seen("sign", "course lab 5 programs randomRoaming1.BAS, randomRoaming2.BAS"),
      recalled("min", "research notes, language.md 5.1 ([R] low)", kMath),
      recalled("max", "research notes, language.md 5.1 ([R] low)", kMath),
      recalled("limit", "research notes, language.md 5.1 ([R] low)", "clamping, a common helper"),
      recalled("within", "research notes, language.md 5.1 ([R] low)", "a range test, a common helper", "x >= low and x <= high"),
      seen("pi", "course lab 3 program mouseControl.BAS"),
      recalled("rtod", "research notes, language.md 5.1 ([R] medium)", "angle conversion, a common helper", "x * 180 / pi()"),
      recalled("dtor", "research notes, language.md 5.1 ([R] medium)", "angle conversion, a common helper", "x * pi() / 180"),
      seen("polarA", "course cheat sheet; course lab 3 program mouseControl.BAS"),
      seen("polarR", "course cheat sheet; course lab 3 program mouseControl.BAS"),
      recalled("cartX", "research notes, language.md 5.1 ([R] low)", "the inverse of polarR/polarA, a common helper"),
      recalled("cartY", "research notes, language.md 5.1 ([R] low)", "the inverse of polarR/polarA, a common helper"),
      seen("random", "course lab 3; course lab 3 program generateRandomNumbers.BAS"),
      recalled("rRandom", "research notes, language.md 5.1 ([R] low)", "random reals", "random(n) (whole numbers 0 to n-1)"),
      recalled("randomize", "research notes, language.md 5.1 ([R] low)", "repeatable random numbers inside a program (rb's --seed does it outside)"),

      // ---- strings
      recalled("length", "research notes, language.md 5.2 ([R] medium)", kString),
      recalled("left", "research notes, language.md 5.2 ([R] medium)", kString),
      recalled("right", "research notes, language.md 5.2 ([R] medium)", kString),
      recalled("mid", "research notes, language.md 5.2 ([R] medium)", kString),
      recalled("upper", "research notes, language.md 5.2 ([R] medium)", kString),
      recalled("lower", "research notes, language.md 5.2 ([R] medium)", kString),
      recalled("trim", "research notes, language.md 5.2 ([R] low)", kString),
      recalled("trimL", "research notes, language.md 5.2 ([R] low)", kString),
      recalled("trimR", "research notes, language.md 5.2 ([R] low)", kString),
      recalled("spaces", "research notes, language.md 5.2 ([R] low)", kString),
      recalled("reverse", "research notes, language.md 5.2 ([R] low)", kString),
      recalled("instr", "research notes, language.md 5.2 ([R] low)", kString),
      recalled("contains", "research notes, language.md 5.2 ([R] low)", kString),
      recalled("replace", "research notes, language.md 5.2 ([R] low)", kString),
      recalled("extract", "research notes, language.md 5.2 ([R] low)", kString),
      seen("char", "course cheat sheet; course lab 3"),
      seen("ascii", "course cheat sheet; course lab 3; course lab 3 programs"),
      recalled("toString", "research notes, language.md 5.2 ([R] medium)", kString),
      recalled("toNumber", "research notes, language.md 5.2 ([R] medium)", kString),
      recalled("isNumber", "research notes, language.md 5.2 ([R] low)", "a type test for typeless values"),
      recalled("isString", "research notes, language.md 5.2 ([R] low)", "a type test for typeless values"),

      // ---- time
      recalled("timer", "research notes, language.md 5.3 ([R] medium)", "measuring time in a program"),
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
      recalled("rectangleWH", "research notes, language.md 6.2 ([R] low)", "a rectangle by its size", "rectangle x, y, x + w, y + h"),
      seen("eRectangle", "published menu"),
      seen("circle", "course cheat sheet; course lab 1; course lab 2"),
      recalled("circleWH", "research notes, language.md 6.2 ([R] low)", "an ellipse by its size", "circle x, y, x + w, y + h"),
      own("eCircle", "eRectangle's twin", "lineWidth w, then circle x1, y1, x2, y2, colour"),
      recalled("polygon", "research notes, language.md 6.2 ([R] low)", "a polygon from an array of vertices", "mPolygon with a data array"),
      seen("mPolygon", "published path planner (its data and a screenshot)"),
      recalled("setPixel", "research notes, language.md 6.2 ([R] low)", "one pixel"),
      recalled("pixelClr", "research notes, language.md 6.2 ([R] low)", "reading the screen back (rb's tests read what was drawn with it)"),
      recalled("floodFill", "research notes, language.md 6.2 ([R] low)", "filling a region"),
      seen("xyString", "course cheat sheet; course lab 2"),
      seen("xyText", "published program (xyText x,y,text,\"\",size,fs_Bold)"),
      own("saveScr", "remembering the screen"),
      own("restoreScr", "remembering the screen"),
      recalled("flip", "research notes, language.md 6.2: flip on / flip off ([R] medium)", "double buffering for the live view"),
      recalled("RGB", "research notes, language.md 6.3 ([R] medium)", "colours beyond the palette"),

      // ---- input
      seen("getKey", "course cheat sheet; course lab 3; course lab 3 program toggleControl.BAS"),
      recalled("getKeyE", "research notes, language.md 6.4 ([R] low)", "arrow and function keys", "getKey"),
      seen("waitKey", "course cheat sheet; course lab 2; course lab 3 programs"),
      recalled("keyDown", "research notes, language.md 6.4 ([R] low)", "whether one key is held", "getKey key (the key held now)"),
      seen("readMouse", "course cheat sheet; course lab 3; course lab 3 program mouseControl.BAS"),
      recalled("waitClick", "research notes, language.md 6.5 ([R] low)", "waiting for a click", "readMouse x, y, b in a loop until b is not 0"),
      seen("MsgBox", "published path planner (n = MsgBox(IM))"),
      recalled("AddButton", "research notes, language.md 5.5: GUI controls, names only ([R] low)", kButton),
      own("GetButton", kButton),
      recalled("LastButton", "research notes, language.md 5.5: GUI controls, names only ([R] low)", kButton),
      own("RemoveButton", kButton),
      recalled("AddEdit", "research notes, language.md 5.5: GUI controls, names only ([R] low)", kEdit, "input \"prompt\", var"),
      recalled("GetEdit", "research notes, language.md 5.5: GUI controls, names only ([R] low)", kEdit, "input \"prompt\", var"),
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
  // Rows sorted by name and looked up by halving (two hash maps of a node each were a tenth of
  // an empty program's start-up); the same checks.
  std::vector<const Row*> byName;
  byName.reserve(rows().size());
  for (const Row& r : rows()) {
    if (r.evidence.confirmed() == !r.evidence.reason.empty())
      throw std::logic_error("evidence: '" + std::string(r.name) + "' needs a source or a reason (not both)");
    if (r.evidence.confirmed() && !r.evidence.instead.empty())
      throw std::logic_error("evidence: '" + std::string(r.name) + "' is confirmed: nothing instead");
    byName.push_back(&r);
  }
  auto less = [](const Row* a, const Row* b) { return a->name < b->name; };
  std::sort(byName.begin(), byName.end(), less);
  for (size_t i = 1; i < byName.size(); ++i)
    if (byName[i]->name == byName[i - 1]->name)
      throw std::logic_error("evidence: '" + std::string(byName[i]->name) + "' has two rows");
  std::vector<bool> used(byName.size(), false);
  for (Builtin& b : table) {
    auto it = std::lower_bound(byName.begin(), byName.end(), b.name,
                               [](const Row* r, std::string_view name) { return r->name < name; });
    if (it == byName.end() || (*it)->name != b.name)
      throw std::logic_error("evidence: the built-in '" + std::string(b.name) + "' has no evidence row");
    b.evidence = (*it)->evidence;
    used[static_cast<size_t>(it - byName.begin())] = true;
  }
  for (size_t i = 0; i < byName.size(); ++i)
    if (!used[i]) throw std::logic_error("evidence: the row '" + std::string(byName[i]->name) + "' names no built-in");
}

}  // namespace rb::builtins
