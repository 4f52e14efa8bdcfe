#pragma once
// rb's exit codes (from sysexits.h), documented in man/rb.1.

namespace rb::run::exitcode {
constexpr int kOk = 0;           ///< success
constexpr int kUsage = 64;       ///< bad command line
constexpr int kRejected = 65;    ///< the program has errors found before running (rb check: errors)
constexpr int kNoInput = 66;     ///< a file named on the command line does not exist
constexpr int kUnavailable = 69; ///< rb cannot do what was asked here (--require-sandbox without Landlock)
constexpr int kRuntime = 70;     ///< the program stopped with a runtime error or a limit
constexpr int kIoError = 74;     ///< reading, writing or a device failed
}  // namespace rb::run::exitcode
