#include "robot/reply_check.h"

#include <algorithm>
#include <array>
#include <cstdio>

#include "robot/protocol.h"

namespace rb::protocol {

namespace {
/// How many bytes of a too-long reply a message shows.
constexpr size_t kShownBytes = 16;

std::array<uint8_t, kReplySize> replyBytes(const Exchange& exchange) {
  std::array<uint8_t, kReplySize> bytes{};
  std::copy_n(exchange.bytes.begin(), std::min(exchange.bytes.size(), bytes.size()), bytes.begin());
  return bytes;
}
}  // namespace

std::string secondsText(double seconds) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", seconds);
  return buf;
}

std::optional<std::string> replyFault(const Exchange& exchange, const std::string& port, double timeoutSeconds) {
  const std::string who = "robot on " + port;
  const std::string within = " within " + secondsText(timeoutSeconds) + " s";
  const std::vector<uint8_t>& got = exchange.bytes;
  if (exchange.end == Exchange::End::HungUp)
    return "lost the connection to the robot on " + port + ": the device hung up";
  if (exchange.end == Exchange::End::TimedOut || got.size() < static_cast<size_t>(kReplySize)) {
    if (got.empty()) return who + " did not answer" + within;
    return who + " sent a short reply: " + std::to_string(got.size()) + " of " + std::to_string(kReplySize) +
           " bytes" + within + " (" + hexBytes(got.data(), got.size()) + ")";
  }
  if (got.size() > static_cast<size_t>(kReplySize))
    return who + " sent a malformed reply: " + (got.size() >= kMaxReadReply ? "at least " : "") +
           std::to_string(got.size()) + " bytes instead of " + std::to_string(kReplySize) + " (" +
           hexBytes(got.data(), got.size(), kShownBytes) + ")";
  const std::array<uint8_t, kReplySize> bytes = replyBytes(exchange);
  if (!plausibleReply(bytes))
    return who + " sent a malformed reply (" + hexBytes(bytes.data(), bytes.size()) + "): sensor bits no robot sets";
  return std::nullopt;
}

RobotReply decodeExchange(const Exchange& exchange) { return decodeReply(replyBytes(exchange)); }

}  // namespace rb::protocol
