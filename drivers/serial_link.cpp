#include "serial_link.h"

#include <array>
#include <cstdio>
#include <vector>

#include "robot/protocol.h"
#include "base/runtime_error.h"

namespace rb::drivers {

namespace {
/// How many bytes of a too-long reply rb reads before giving up on it, and how many it shows.
constexpr size_t kMaxShownReply = 256;
constexpr size_t kShownBytes = 16;
}  // namespace

std::string secondsText(double seconds) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", seconds);
  return buf;
}

SerialLink::SerialLink(std::string path, const SerialLinkOptions& options)
    : port_(std::move(path), options.baud), timeoutSeconds_(options.timeoutSeconds) {}

void SerialLink::fault(const std::string& message) {
  // After a fault the byte stream can no longer be trusted; release the device right away.
  port_.close();
  throw RuntimeError(message);
}

RobotReply SerialLink::transact(uint8_t code, uint8_t param) {
  const std::string who = "robot on " + port_.path();
  if (!port_.isOpen()) throw RuntimeError(who + " is disconnected after an earlier fault");
  auto deadline = std::chrono::steady_clock::now() +
                  std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                      std::chrono::duration<double>(timeoutSeconds_));
  const std::string within = " within " + secondsText(timeoutSeconds_) + " s";
  const std::string lost = "lost the connection to the robot on " + port_.path() + ": the device hung up";

  port_.discardInput();
  const uint8_t command[2] = {code, param};
  switch (port_.write(command, sizeof command, deadline)) {
    case IoStatus::Done: break;
    case IoStatus::TimedOut: fault(who + " did not take the command" + within + " (output blocked)");
    case IoStatus::HungUp: fault(lost);
  }

  std::vector<uint8_t> got;
  IoStatus status = port_.readAtLeast(got, protocol::kReplySize, deadline);
  if (status == IoStatus::HungUp) fault(lost);
  if (status == IoStatus::TimedOut) {
    if (got.empty()) fault(who + " did not answer" + within);
    fault(who + " sent a short reply: " + std::to_string(got.size()) + " of " +
          std::to_string(protocol::kReplySize) + " bytes" + within + " (" +
          protocol::hexBytes(got.data(), got.size()) + ")");
  }
  // A reply longer than five bytes that arrived at once (read up to a bound: a port that
  // floods bytes must not keep rb reading).
  port_.readWaiting(got, kMaxShownReply);
  if (got.size() > static_cast<size_t>(protocol::kReplySize))
    fault(who + " sent a malformed reply: " +
          (got.size() >= kMaxShownReply ? "at least " : "") + std::to_string(got.size()) +
          " bytes instead of " + std::to_string(protocol::kReplySize) + " (" +
          protocol::hexBytes(got.data(), got.size(), kShownBytes) + ")");
  std::array<uint8_t, protocol::kReplySize> bytes{};
  std::copy(got.begin(), got.end(), bytes.begin());
  if (!protocol::plausibleReply(bytes))
    fault(who + " sent a malformed reply (" + protocol::hexBytes(bytes.data(), bytes.size()) +
          "): sensor bits no robot sets");
  return protocol::decodeReply(bytes);
}

}  // namespace rb::drivers
