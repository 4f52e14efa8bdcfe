#pragma once
// An emulated robot that speaks RobotBASIC's wire protocol: it decodes each two-byte command,
// moves a simulated robot (core's SimRobot on a canvas of its own, with only the screen edge as
// walls) and answers with the five-byte reply. Faults can be rehearsed on purpose: commands
// left unanswered, garbled or short replies, a robot that dies. The pty loop that feeds it is
// in emulator_server.h.

#include <cstdint>
#include <string>
#include <vector>

#include "screen/canvas.h"
#include "base/rng.h"
#include "robot/robot_link.h"
#include "robot/robot_sim.h"

namespace rb::drivers {

/// The emulated robot's imperfections, all off by default (rb robot's options).
struct EmulatorOptions {
  double slipPercent = 0;   ///< --slip: random error of each move and turn, as rSlip
  uint64_t dropEvery = 0;   ///< --drop-every N: every N-th command gets no answer
  uint64_t garbleEvery = 0; ///< --garble-every N: every N-th answer is seven bytes of 0xff
  uint64_t shortEvery = 0;  ///< --short-every N: every N-th answer stops after two bytes
  uint64_t dieAfter = 0;    ///< --die-after N: the port closes after the N-th answer
  uint64_t seed = 1;        ///< --seed: for --slip
};

/// What the emulator does with one command.
struct EmulatorAnswer {
  std::vector<uint8_t> bytes;  ///< to send back (empty: no answer)
  bool die = false;            ///< close the port after sending
  std::string note;            ///< for the log: "", "dropped", "garbled", "short"
};

/// The robot behind `rb robot`: commands in, replies out, no I/O of its own.
class RobotEmulator {
 public:
  explicit RobotEmulator(const EmulatorOptions& options);
  RobotEmulator(const RobotEmulator&) = delete;
  RobotEmulator& operator=(const RobotEmulator&) = delete;

  /// Executes command `code` with `param` and says what to answer.
  EmulatorAnswer handle(uint8_t code, uint8_t param);

  /// The emulated robot, for tests.
  const SimRobot& robot() const { return robot_; }
  /// Commands received so far.
  uint64_t commands() const { return count_; }

 private:
  /// Carries out the command on the simulated robot and builds the honest reply.
  RobotReply execute(uint8_t code, uint8_t param);

  EmulatorOptions options_;
  Canvas canvas_;
  Rng rng_;
  SimRobot robot_;
  uint64_t count_ = 0;
};

}  // namespace rb::drivers
