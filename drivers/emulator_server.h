#pragma once
// The loop of `rb robot --pty`: reads two-byte commands from a pseudo-terminal's master side,
// lets a RobotEmulator answer them and writes the replies back. When the client closes the
// port the loop forgets any half-received command and waits for the next client, so one
// emulator serves any number of runs.

#include <signal.h>

#include <cstdio>
#include <functional>

#include "pty.h"
#include "robot_emulator.h"

namespace rb::drivers {

/// Blocks SIGINT, SIGTERM and SIGHUP for the rest of the process, so that a loop can notice
/// them between two waits and end cleanly (removing its link) without a signal handler. They
/// stay blocked through the exit: a signal that arrives while the process ends (the caller saw
/// the port close and sent SIGTERM) does not turn a clean exit into death by that signal.
class StopSignals {
 public:
  StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

  /// True once one of the signals has arrived.
  bool requested() const;

 private:
  sigset_t stop_;
};

/// How the loop answers and what it logs.
struct ServeOptions {
  int latencyMs = 0;          ///< --latency: wait this long before each answer
  std::FILE* log = nullptr;   ///< --verbose: one line per command
};

/// Why serveRobot returned.
enum class ServeEnd {
  Stopped,  ///< `stop` said so
  Died,     ///< --die-after: the port was closed
};

/// Serves the emulator on `pty` until `stop()` returns true (checked at least every 50 ms) or
/// the emulator dies.
ServeEnd serveRobot(Pty& pty, RobotEmulator& emulator, const ServeOptions& options,
                    const std::function<bool()>& stop);

}  // namespace rb::drivers
