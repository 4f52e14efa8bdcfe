#pragma once
// Handlers of the built-in table, one family per builtins_*.cpp file. Each handler is named
// after its BASIC name with its family as prefix (mathAbs is abs(), strLeft is left()).

#include <string>
#include <string_view>
#include <vector>

#include "lang/builtins.h"
#include "machine/machine.h"

namespace rb::builtins {

// math (builtins_math.cpp)
Value mathAbs(Machine&, Args&);
Value mathSqrt(Machine&, Args&);
Value mathSin(Machine&, Args&);
Value mathCos(Machine&, Args&);
Value mathTan(Machine&, Args&);
Value mathAsin(Machine&, Args&);
Value mathAcos(Machine&, Args&);
Value mathAtan(Machine&, Args&);
Value mathAtan2(Machine&, Args&);
Value mathExp(Machine&, Args&);
Value mathLn(Machine&, Args&);
Value mathLog(Machine&, Args&);
Value mathPow(Machine&, Args&);
Value mathInt(Machine&, Args&);
Value mathFloor(Machine&, Args&);
Value mathCeil(Machine&, Args&);
Value mathFrac(Machine&, Args&);
Value mathRound(Machine&, Args&);
Value mathSign(Machine&, Args&);
Value mathMin(Machine&, Args&);
Value mathMax(Machine&, Args&);
Value mathLimit(Machine&, Args&);
Value mathWithin(Machine&, Args&);
Value mathPi(Machine&, Args&);
Value mathRtoD(Machine&, Args&);
Value mathDtoR(Machine&, Args&);
Value mathPolarA(Machine&, Args&);
Value mathPolarR(Machine&, Args&);
Value mathCartX(Machine&, Args&);
Value mathCartY(Machine&, Args&);
Value mathRandom(Machine&, Args&);
Value mathRRandom(Machine&, Args&);
Value mathRandomize(Machine&, Args&);

// strings (builtins_string.cpp)
Value strLength(Machine&, Args&);
Value strLeft(Machine&, Args&);
Value strRight(Machine&, Args&);
Value strMid(Machine&, Args&);
Value strUpper(Machine&, Args&);
Value strLower(Machine&, Args&);
Value strTrim(Machine&, Args&);
Value strTrimL(Machine&, Args&);
Value strTrimR(Machine&, Args&);
Value strSpaces(Machine&, Args&);
Value strReverse(Machine&, Args&);
Value strInstr(Machine&, Args&);
Value strContains(Machine&, Args&);
Value strReplace(Machine&, Args&);
Value strExtract(Machine&, Args&);
Value strChar(Machine&, Args&);
Value strAscii(Machine&, Args&);
Value strToString(Machine&, Args&);
Value strToNumber(Machine&, Args&);
Value strIsNumber(Machine&, Args&);
Value strIsString(Machine&, Args&);

// time (builtins_time.cpp)
Value timeTimer(Machine&, Args&);
Value timeDelay(Machine&, Args&);

// Families that add their own rows to the table.
void appendRobotBuiltins(std::vector<Builtin>& table);
void appendGraphicsBuiltins(std::vector<Builtin>& table);
void appendInputBuiltins(std::vector<Builtin>& table);
void appendSystemBuiltins(std::vector<Builtin>& table);

/// Gives every row of the standard table its evidence (builtins_evidence.cpp): the public
/// source that names it, or why it is rb's own. A built-in without an evidence row, or an
/// evidence row that names no built-in, is a programming error: std::logic_error.
void applyEvidence(std::vector<Builtin>& table);

/// The longest string a built-in makes.
constexpr int64_t kMaxString = 64 << 20;

/// The first place at or after `from` where `needle` occurs in `hay`, or npos: linear in both
/// lengths, however the strings repeat (builtins_string.cpp). The memory a long needle's search
/// takes is counted against the machine's --max-memory first.
size_t findText(Machine& m, const std::string& hay, const std::string& needle, size_t from);

/// Calls `field(text)` for each field of `s` split at `delimiter` (not empty), in order, until
/// it returns false. Linear in the length of s whatever the delimiter (findText: fields are at
/// least as long apart as the delimiter, so searching from each costs s's length in all), and
/// the run's limits are looked at every 65,536 fields.
template <typename Field>
void forEachField(Machine& m, const std::string& s, const std::string& delimiter, Field&& field) {
  size_t pos = 0;
  for (uint32_t count = 1;; ++count) {
    if (count % 65536 == 0) m.checkAlarms();
    size_t at = findText(m, s, delimiter, pos);
    size_t end = at == std::string::npos ? s.size() : at;
    if (!field(std::string_view(s).substr(pos, end - pos)) || at == std::string::npos) return;
    pos = at + delimiter.size();
  }
}

/// P_NOWAIT, Spawn's mode that returns at once (the value C's process.h gives it).
constexpr int64_t kSpawnNoWait = 1;

/// A double result, as an integer when it is integral and small enough (so that print shows
/// "3", not "3.0", and later integer arithmetic stays exact).
Value numberResult(double d);

}  // namespace rb::builtins
