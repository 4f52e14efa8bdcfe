#pragma once
// Judging what a robot sent back for one command, the same for every link (a serial port in
// drivers/, Web Serial on the page): the reply decoded, or the fault in the words rb run uses
// ("robot on /dev/rfcomm0 did not answer within 2 s").

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "robot/robot_link.h"

namespace rb::protocol {

/// How many bytes of a too-long reply a link reads before giving up on it.
constexpr size_t kMaxReadReply = 256;

/// What came back for one command, as the link read it.
struct Exchange {
  enum class End : uint8_t {
    Complete,  ///< at least a reply's worth arrived (and what came with it, up to kMaxReadReply)
    TimedOut,  ///< the timeout passed first; `bytes` is what came before it
    HungUp,    ///< the device went away
  };
  std::vector<uint8_t> bytes;
  End end = End::Complete;
};

/// The fault in an exchange (no answer, a short, long or malformed reply, the device gone), or
/// nullopt when `bytes` is one plausible reply. `port` names the port ("/dev/rfcomm0").
std::optional<std::string> replyFault(const Exchange& exchange, const std::string& port, double timeoutSeconds);

/// The reply of an exchange replyFault() accepted.
RobotReply decodeExchange(const Exchange& exchange);

/// "2", "0.5": seconds as users wrote them, for messages.
std::string secondsText(double seconds);

}  // namespace rb::protocol
