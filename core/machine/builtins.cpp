#include "machine/builtins.h"

#include "machine/builtins_impl.h"

namespace rb {

namespace {

using K = BuiltinKind;

// The rows. Signatures name the parameters: `[...]` is optional, `&name` receives a result
// (the argument must be a variable), `name...` repeats, and a final `items...` takes a
// print-style list (items separated by ',' or ';').
std::vector<Builtin> makeTable() {
  using namespace builtins;
  std::vector<Builtin> t = {
      // ---- constants
      {"True", K::Constant, "constant", "", nullptr, 1, "1"},
      {"False", K::Constant, "constant", "", nullptr, 0, "0"},
      {"Up", K::Constant, "constant", "", nullptr, 0, "pen up (0)"},
      {"Down", K::Constant, "constant", "", nullptr, 1, "pen down (1)"},
      {"On", K::Constant, "constant", "", nullptr, 1, "1"},
      {"Off", K::Constant, "constant", "", nullptr, 0, "0"},
      {"Black", K::Constant, "colour", "", nullptr, 0, "colour 0"},
      {"Blue", K::Constant, "colour", "", nullptr, 1, "colour 1"},
      {"Green", K::Constant, "colour", "", nullptr, 2, "colour 2"},
      {"Cyan", K::Constant, "colour", "", nullptr, 3, "colour 3"},
      {"Red", K::Constant, "colour", "", nullptr, 4, "colour 4"},
      {"Magenta", K::Constant, "colour", "", nullptr, 5, "colour 5"},
      {"Brown", K::Constant, "colour", "", nullptr, 6, "colour 6"},
      {"Gray", K::Constant, "colour", "", nullptr, 7, "colour 7"},
      {"DarkGray", K::Constant, "colour", "", nullptr, 8, "colour 8"},
      {"LightBlue", K::Constant, "colour", "", nullptr, 9, "colour 9"},
      {"LightGreen", K::Constant, "colour", "", nullptr, 10, "colour 10"},
      {"LightCyan", K::Constant, "colour", "", nullptr, 11, "colour 11"},
      {"LightRed", K::Constant, "colour", "", nullptr, 12, "colour 12"},
      {"LightMagenta", K::Constant, "colour", "", nullptr, 13, "colour 13"},
      {"Yellow", K::Constant, "colour", "", nullptr, 14, "colour 14"},
      {"White", K::Constant, "colour", "", nullptr, 15, "colour 15"},
      {"fs_Bold", K::Constant, "constant", "", nullptr, kFsBold, "xyText style: bold (1); add the fs_ constants to combine them"},
      {"fs_Italic", K::Constant, "constant", "", nullptr, kFsItalic, "xyText style: italic (2)"},
      {"fs_Underline", K::Constant, "constant", "", nullptr, kFsUnderline, "xyText style: underlined (4)"},
      {"fs_StrikeOut", K::Constant, "constant", "", nullptr, kFsStrikeOut, "xyText style: struck out (8)"},

      // ---- math
      {"abs", K::Function, "math", "x", mathAbs, 0, "absolute value"},
      {"sqrt", K::Function, "math", "x", mathSqrt, 0, "square root (x >= 0)"},
      {"sin", K::Function, "math", "radians", mathSin, 0, "sine of an angle in radians"},
      {"cos", K::Function, "math", "radians", mathCos, 0, "cosine of an angle in radians"},
      {"tan", K::Function, "math", "radians", mathTan, 0, "tangent of an angle in radians"},
      {"asin", K::Function, "math", "x", mathAsin, 0, "arc sine in radians (-1 <= x <= 1)"},
      {"acos", K::Function, "math", "x", mathAcos, 0, "arc cosine in radians (-1 <= x <= 1)"},
      {"atan", K::Function, "math", "x", mathAtan, 0, "arc tangent in radians"},
      {"atan2", K::Function, "math", "y, x", mathAtan2, 0, "angle of the vector (x, y) in radians"},
      {"exp", K::Function, "math", "x", mathExp, 0, "e to the power x"},
      {"ln", K::Function, "math", "x", mathLn, 0, "natural logarithm (x > 0)"},
      {"log", K::Function, "math", "x", mathLog, 0, "base-10 logarithm (x > 0)"},
      {"pow", K::Function, "math", "x, y", mathPow, 0, "x to the power y (same as x ^ y)"},
      {"int", K::Function, "math", "x", mathInt, 0, "x truncated toward zero"},
      {"floor", K::Function, "math", "x", mathFloor, 0, "largest integer <= x"},
      {"ceil", K::Function, "math", "x", mathCeil, 0, "smallest integer >= x"},
      {"frac", K::Function, "math", "x", mathFrac, 0, "fractional part: x - int(x)"},
      {"round", K::Function, "math", "x", mathRound, 0, "nearest integer (halves away from zero)"},
      {"sign", K::Function, "math", "x", mathSign, 0, "-1, 0 or 1"},
      {"min", K::Function, "math", "a, b...", mathMin, 0, "the smallest argument"},
      {"max", K::Function, "math", "a, b...", mathMax, 0, "the largest argument"},
      {"limit", K::Function, "math", "x, low, high", mathLimit, 0, "x clamped to low..high"},
      {"within", K::Function, "math", "x, low, high", mathWithin, 0, "1 if low <= x <= high, else 0"},
      {"pi", K::Function, "math", "[factor]", mathPi, 0, "3.14159... times factor (default 1)"},
      {"rtod", K::Function, "math", "radians", mathRtoD, 0, "radians to degrees"},
      {"dtor", K::Function, "math", "degrees", mathDtoR, 0, "degrees to radians"},
      {"polarA", K::Function, "math", "x, y", mathPolarA, 0,
       "angle of (x, y) in radians, atan2(y, x); screen y grows downward"},
      {"polarR", K::Function, "math", "x, y", mathPolarR, 0, "length of (x, y): sqrt(x*x + y*y)"},
      {"cartX", K::Function, "math", "r, radians", mathCartX, 0, "x of the polar point: r*cos(a)"},
      {"cartY", K::Function, "math", "r, radians", mathCartY, 0, "y of the polar point: r*sin(a)"},
      {"random", K::Function, "math", "n", mathRandom, 0, "random integer 0 .. n-1 (seeded by --seed)"},
      {"rRandom", K::Function, "math", "n", mathRRandom, 0, "random real in [0, n)"},
      {"randomize", K::Command, "math", "seed", mathRandomize, 0, "restarts the random numbers from seed"},

      // ---- strings and conversion
      {"length", K::Function, "string", "s", strLength, 0, "number of characters"},
      {"left", K::Function, "string", "s, n", strLeft, 0, "the first n characters"},
      {"right", K::Function, "string", "s, n", strRight, 0, "the last n characters"},
      {"mid", K::Function, "string", "s, start [, count]", strMid, 0,
       "count characters (default: all) from position start (1 = first)"},
      {"upper", K::Function, "string", "s", strUpper, 0, "upper case"},
      {"lower", K::Function, "string", "s", strLower, 0, "lower case"},
      {"trim", K::Function, "string", "s", strTrim, 0, "s without leading and trailing spaces"},
      {"trimL", K::Function, "string", "s", strTrimL, 0, "s without leading spaces"},
      {"trimR", K::Function, "string", "s", strTrimR, 0, "s without trailing spaces"},
      {"spaces", K::Function, "string", "n", strSpaces, 0, "n spaces"},
      {"reverse", K::Function, "string", "s", strReverse, 0, "s backwards"},
      {"instr", K::Function, "string", "s, find [, start]", strInstr, 0,
       "position (1 = first) of find in s at or after start, 0 if absent"},
      {"contains", K::Function, "string", "s, find", strContains, 0, "1 if find occurs in s, else 0"},
      {"replace", K::Function, "string", "s, find, with", strReplace, 0, "s with every find replaced"},
      {"extract", K::Function, "string", "s, delimiter, n", strExtract, 0,
       "the n-th field (1 = first) of s split at delimiter"},
      {"char", K::Function, "string", "code", strChar, 0, "one-character string with that code"},
      {"ascii", K::Function, "string", "s", strAscii, 0, "code of the first character of s"},
      {"toString", K::Function, "string", "x [, decimals]", strToString, 0,
       "x as text (with a fixed number of decimals if given)"},
      {"toNumber", K::Function, "string", "s [, default]", strToNumber, 0,
       "the number s spells; default (or an error) if it is not a number"},
      {"isNumber", K::Function, "string", "value", strIsNumber, 0, "1 if value is a number"},
      {"isString", K::Function, "string", "value", strIsString, 0, "1 if value is a string"},

      // ---- time
      {"timer", K::Function, "time", "", timeTimer, 0, "milliseconds since the program started"},
      {"delay", K::Command, "time", "ms", timeDelay, 0, "waits ms milliseconds"},
  };
  appendRobotBuiltins(t);
  appendGraphicsBuiltins(t);
  appendInputBuiltins(t);
  appendSystemBuiltins(t);
  // Every math and string function is pure but the random numbers, which are the run's: a
  // watch may evaluate pure functions, and rb check knows a loop condition of them changes
  // only with its variables.
  for (Builtin& b : t) {
    bool family = b.group == "math" || b.group == "string";
    if (b.kind == K::Function && family && b.name != "random" && b.name != "rRandom")
      b.traits |= trait::kPure;
  }
  applyEvidence(t);
  return t;
}

}  // namespace

const BuiltinTable& standardBuiltins() {
  static const BuiltinTable table(makeTable());
  return table;
}

}  // namespace rb
