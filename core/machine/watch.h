#pragma once
// A debugger's watch: an expression typed while a program runs (`x * 2`, `a[3] + 1`,
// `left(s, 2)`), evaluated with the program's variables whenever the live view stops. It is
// parsed by the language's own parser (parseExpression) and computed with the interpreter's
// rules for values: integers while they fit, else doubles; `+` joins strings with the printed
// form of a number; `/` of integers stays an integer when it divides; comparisons give 0 or 1;
// `and`/`or` look at their right side only when needed. A watch reads variables and calls only
// the pure built-ins, the math and string functions (not random or rRandom) and the constants,
// so looking never changes the run: no sub runs, no random number is drawn, no command is sent.
//
// The names are the program's: in a sub its locals and parameters, else (and with a leading
// '_', as in the program) the globals. Errors come back as text in place of the value
// ("x is not assigned yet", "index 5 is out of range for 'a' (valid: 0 to 3)").

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "lang/ast.h"
#include "lang/value.h"
#include "machine/interpreter.h"

namespace rb {

class Machine;

/// A watch's value at one look, or why there is none.
struct WatchResult {
  std::optional<Value> value;
  std::string error;  ///< when there is no value
};

class Watch {
 public:
  /// Parses `text`; a syntax error is kept and given at every evaluation.
  explicit Watch(std::string text);
  ~Watch();
  Watch(Watch&&) noexcept;
  Watch& operator=(Watch&&) noexcept;

  const std::string& text() const { return text_; }
  /// The syntax error ("" when `text` is one expression).
  const std::string& syntaxError() const { return syntaxError_; }

  /// The value with these variables (Interpreter::variables(): the globals, then the running
  /// sub's locals, which a name finds first). `machine` is the program's: the built-ins'
  /// handlers take one, and the pure ones read nothing of it.
  WatchResult evaluate(const std::vector<VariableView>& variables, Machine& machine) const;

 private:
  struct Parsed;
  std::string text_;
  std::string syntaxError_;
  std::unique_ptr<Parsed> parsed_;  ///< the tree and the text it points into
};

/// True for the built-ins a watch may call: the math and string functions that only compute
/// (random and rRandom draw numbers, which would change the run).
bool isPureBuiltin(std::string_view name);

}  // namespace rb
