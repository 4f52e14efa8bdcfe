#pragma once
// The one exception type for errors while a program runs. It is thrown anywhere in the
// interpreter or a built-in and caught once, at the run boundary, which adds the position of
// the instruction that failed.

#include <stdexcept>
#include <string>

namespace rb {

class RuntimeError : public std::runtime_error {
 public:
  explicit RuntimeError(const std::string& message, const char* code = "rb-runtime-error")
      : std::runtime_error(message), message_(message), code_(code) {}
  /// The rule code of the diagnostic it becomes (docs/diagnostics.md).
  const char* code() const { return code_; }
  /// The whole message: what() ends at a NUL byte a program's text may have put into it.
  const std::string& message() const { return message_; }

 private:
  std::string message_;
  const char* code_;
};

/// Thrown from inside a long call (waiting for input, a long search) when the run's --timeout
/// has passed: the run ends with the timeout's own status and message, not as the program's
/// error.
struct DeadlinePassed {};

}  // namespace rb
