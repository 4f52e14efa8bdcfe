#pragma once
// The built-in table's mechanism: what a built-in command, function or constant is (`Builtin`),
// how its signature is read, the table a program is compiled against (`BuiltinTable`) and the
// arguments a handler receives (`Args`). The rows of the standard table, with their handlers,
// live in machine/builtins.cpp: the language knows how to use a table, not what is in it.
//
// The front end (loader, parser, compiler, checker) is given the table it compiles against;
// the compiled Program keeps it, so the interpreter dispatches through the same rows.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "lang/value.h"

namespace rb {

class Machine;  // what a handler works on; defined in machine/, opaque to the language
class Args;

enum class BuiltinKind : uint8_t { Command, Function, Constant };

using BuiltinFn = Value (*)(Machine& m, Args& args);

/// One parameter as the signature spells it.
struct ParamSpec {
  std::string_view name;
  bool out = false;  ///< written `&name`: the argument must be a variable that receives a result
};

/// What the checks of `rb check` may assume about a built-in (Builtin::traits, or-ed). A row
/// without traits is assumed to read and change anything: the checks stay quiet about it.
namespace trait {
/// A function whose value depends on its arguments alone and that changes nothing (abs, left):
/// a loop condition made of such calls changes only when its variables do.
constexpr uint8_t kPure = 1;
/// Stops the simulator with "the robot has not been placed" before the first rLocate.
constexpr uint8_t kNeedsRobot = 2;
/// Places the simulated robot (rLocate).
constexpr uint8_t kPlacesRobot = 4;
/// May hand the robot statements to a real robot, which is never placed (rCommPort).
constexpr uint8_t kRealRobot = 8;
}  // namespace trait

/// Where a built-in comes from: the public RobotBASIC source that names it, or, for a name no
/// source shows, why rb has it and what RobotBASIC is known to have instead. The standard
/// table's evidence is one table keyed by name (machine/builtins_evidence.cpp); docs/builtins.md
/// shows it, docs/compatibility.md counts it and `rb check --portable` warns from it.
struct Evidence {
  /// The sources that name it, in the style docs/compatibility.md cites them ("seed, Figure
  /// 1.5; course cheat sheet"); empty: rb's own.
  std::string_view source;
  /// rb's own: why rb has it.
  std::string_view reason;
  /// rb's own: what RobotBASIC is known to have instead ("x * 180 / pi()"); empty when nothing.
  std::string_view instead;
  /// Not confirmed, but named by the project's research notes as recalled from RobotBASIC's
  /// documentation (tag [R], "language.md 5.2 ([R] low)"); empty otherwise.
  std::string_view recalled;

  bool confirmed() const { return !source.empty(); }
  /// Neither named by a source nor recalled: rb's own (rb check --portable warns about it).
  bool own() const { return source.empty() && recalled.empty(); }
};

/// One row of a built-in table.
struct Builtin {
  Builtin(std::string_view name_, BuiltinKind kind_, std::string_view group_,
          std::string_view signature_, BuiltinFn fn_, int64_t constant_, std::string_view help_,
          uint8_t traits_ = 0)
      : name(name_), kind(kind_), group(group_), signature(signature_), fn(fn_),
        constant(constant_), help(help_), traits(traits_) {}

  std::string_view name;       ///< canonical spelling, e.g. "rForward"
  BuiltinKind kind;
  std::string_view group;      ///< "math", "string", "time", "robot", "graphics", "input", ...
  /// `[...]` is optional, `&name` receives a result (the argument must be a variable),
  /// `name...` repeats, and a final `items...` takes a print-style list (items separated by
  /// ',' or ';'). E.g. "x, y [, heading [, radius [, colour]]]", "[prompt,] &key".
  std::string_view signature;
  BuiltinFn fn;                ///< commands and functions
  int64_t constant;            ///< constants
  std::string_view help;       ///< one line
  uint8_t traits = 0;          ///< trait:: flags
  Evidence evidence;           ///< set by the table's owner (the standard table: its evidence table)

  // Derived from the signature when the table is built:
  int minArgs = 0;
  int maxArgs = 0;             ///< -1: no upper bound
  bool printList = false;      ///< arguments are a print-style list (items separated by , or ;)
  /// forms[n] lists the parameters used when n arguments are given (empty for impossible n).
  std::vector<std::vector<ParamSpec>> forms;

  bool acceptsCount(int n) const { return n >= minArgs && (maxArgs < 0 || n <= maxArgs); }
  /// The parameter the i-th of n arguments binds to.
  const ParamSpec& param(int n, int i) const;
  /// "2", "1 to 3", "at least 1": for messages.
  std::string arityText() const;
  /// How a call is written: "rForward distance", "left(s, n)" (the signature after the name).
  std::string usage() const;
};

/// Where a program puts a name, for the one rule about built-in names (BuiltinTable::misuse).
enum class NamePlace : uint8_t {
  Statement,  ///< the first word of a statement: `name args`
  Value,      ///< read in an expression: `x = name`
  Call,       ///< called in an expression: `x = name(args)`
  Array,      ///< used as an array: `name[i]`, `dim name[n]`
  Store,      ///< receives a value: assignment, input, for, data, an output or by-reference argument
  Sub,        ///< a sub's name, where it is declared or called with `call`
};

/// A table of built-ins, looked up by name without regard to case. A name may be a command and
/// a function at once (MsgBox), never two of one kind.
class BuiltinTable {
 public:
  /// Derives every row's arity and parameter forms from its signature. A malformed signature
  /// or a name given twice for one kind is a programming error: std::logic_error.
  explicit BuiltinTable(std::vector<Builtin> rows);

  BuiltinTable(const BuiltinTable&) = delete;
  BuiltinTable& operator=(const BuiltinTable&) = delete;

  /// Every row, in table order.
  const std::vector<Builtin>& rows() const { return rows_; }
  /// The row at `index` (as indexOf gives it; compiled code calls built-ins by index).
  const Builtin& at(uint32_t index) const { return rows_[index]; }
  uint32_t indexOf(const Builtin& b) const { return static_cast<uint32_t>(&b - rows_.data()); }

  /// The built-in of that kind named `name` (any case), or nullptr.
  const Builtin* find(std::string_view name, BuiltinKind kind) const;
  /// A built-in of any kind named `name` (a constant, else a function, else a command).
  const Builtin* findAny(std::string_view name) const;
  /// The canonical names of one kind, for "did you mean".
  const std::vector<std::string_view>& names(BuiltinKind kind) const {
    return names_[static_cast<size_t>(kind)];
  }

  /// The one place that decides what a built-in name may be: nullopt when `name` may stand at
  /// `place` (it names no built-in, or a command as a statement, a constant as a value, a
  /// function called, a constant as a sub name), otherwise the error, always shaped
  /// "cannot <use> 'name': it is a built-in <kind>[ (<which>)][; <how to use it>]", where
  /// <which>, for a place where the program names a variable, an array or a sub of its own, is
  /// the built-in's usage and help ("length(s): number of characters").
  std::optional<std::string> misuse(std::string_view name, NamePlace place) const;

 private:
  /// The rows of each kind (by BuiltinKind) that bear one name; kNone where there is none.
  static constexpr uint32_t kNone = 0xffffffffu;
  struct Entry {
    uint32_t row[3] = {kNone, kNone, kNone};
  };
  /// One name's place in the index: an open-addressing table hashed without regard to ASCII
  /// case, so that no lower-case copy is made for a lookup.
  struct Slot {
    std::string_view name;  ///< empty: a free slot
    Entry entry;
  };
  static uint32_t foldedHash(std::string_view name);
  /// The rows named `name`, or nullptr: one lookup for every kind.
  const Entry* lookup(std::string_view name) const;
  /// The entry for `name`, added when missing.
  Entry& entryFor(std::string_view name);
  /// A bit for each (first letter, last letter, length) of a built-in's name, all folded: most
  /// names a program uses are its own and are turned away here without hashing.
  static size_t shapeBit(std::string_view name);

  std::vector<Builtin> rows_;
  std::vector<Slot> slots_;  ///< a power of two, at most half full
  std::vector<uint64_t> shapes_ = std::vector<uint64_t>(1 << 9);
  std::vector<std::string_view> names_[3];
};

/// The arguments a handler receives, with typed accessors that raise runtime errors naming the
/// built-in and the argument.
class Args {
 public:
  Args(const Builtin& b, Value* v, int n) : builtin_(b), v_(v), n_(n) {}
  int size() const { return n_; }
  bool has(int i) const { return i < n_; }
  Value& operator[](int i) { return v_[i]; }
  const Builtin& builtin() const { return builtin_; }

  double num(int i) const;           ///< a number (int or double)
  int64_t integer(int i) const;      ///< a number truncated toward zero
  /// A number between -limit and limit (a distance, an angle, a time), else an error naming
  /// the argument and the range.
  double within(int i, double limit) const;
  const std::string& str(int i) const;
  /// A colour number: 0..15 (the palette) or an RGB() value up to 0xFFFFFF.
  uint32_t colour(int i) const;
  /// A screen coordinate or size in pixels: rounded to the nearest whole pixel and kept within
  /// +-1,000,000 so that no drawing arithmetic can overflow.
  int coordinate(int i) const;
  double numOr(int i, double dflt) const { return has(i) ? num(i) : dflt; }
  int64_t intOr(int i, int64_t dflt) const { return has(i) ? integer(i) : dflt; }
  /// "argument 2 (count) of left()": for messages.
  std::string describe(int i) const;

 private:
  const Builtin& builtin_;
  Value* v_;
  int n_;
};

}  // namespace rb
