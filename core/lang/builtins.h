#pragma once
// The one table of built-in commands, functions and constants. The parser asks it which names
// are commands, the compiler resolves calls and checks argument counts against it, the
// interpreter dispatches through its handlers, and `rb check --list-builtins` and the docs print
// it. To add a built-in: one row in builtins.cpp and one handler in the builtins_*.cpp of its
// family.

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "lang/value.h"

namespace rb {

class Machine;
class Args;

enum class BuiltinKind : uint8_t { Command, Function, Constant };

using BuiltinFn = Value (*)(Machine& m, Args& args);

/// One parameter as the signature spells it.
struct ParamSpec {
  std::string_view name;
  bool out = false;  ///< written `&name`: the argument must be a variable that receives a result
};

struct Builtin {
  Builtin(std::string_view name_, BuiltinKind kind_, std::string_view group_,
          std::string_view signature_, BuiltinFn fn_, int64_t constant_, std::string_view help_)
      : name(name_), kind(kind_), group(group_), signature(signature_), fn(fn_),
        constant(constant_), help(help_) {}

  std::string_view name;       ///< canonical spelling, e.g. "rForward"
  BuiltinKind kind;
  std::string_view group;      ///< "math", "string", "time", "robot", "graphics", "input", ...
  std::string_view signature;  ///< e.g. "x, y [, heading [, radius [, colour]]]", "[prompt,] &key"
  BuiltinFn fn;                ///< commands and functions
  int64_t constant;            ///< constants
  std::string_view help;       ///< one line

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
};

/// Every built-in, in table order.
const std::vector<Builtin>& builtinTable();
/// Case-insensitive lookup of a name of the given kind; nullptr when there is none.
const Builtin* findBuiltin(std::string_view name, BuiltinKind kind);
/// Any kind.
const Builtin* findAnyBuiltin(std::string_view name);
/// Index of a builtin in builtinTable().
inline uint32_t builtinIndex(const Builtin* b) {
  return static_cast<uint32_t>(b - builtinTable().data());
}

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
