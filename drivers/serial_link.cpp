#include "serial_link.h"

#include <array>
#include <cstdio>
#include <vector>

#include "robot/protocol.h"
#include "robot/reply_check.h"
#include "base/runtime_error.h"

namespace rb::drivers {

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
  protocol::Exchange exchange;
  port_.discardInput();
  const uint8_t command[2] = {code, param};
  switch (port_.write(command, sizeof command, deadline)) {
    case IoStatus::Done: break;
    case IoStatus::TimedOut:
      fault(who + " did not take the command within " + protocol::secondsText(timeoutSeconds_) +
            " s (output blocked)");
    case IoStatus::HungUp: exchange.end = protocol::Exchange::End::HungUp; break;
  }
  if (exchange.end == protocol::Exchange::End::Complete) {
    IoStatus status = port_.readAtLeast(exchange.bytes, protocol::kReplySize, deadline);
    if (status == IoStatus::HungUp) exchange.end = protocol::Exchange::End::HungUp;
    if (status == IoStatus::TimedOut) exchange.end = protocol::Exchange::End::TimedOut;
    // A reply longer than five bytes that arrived at once (read up to a bound: a port that
    // floods bytes must not keep rb reading).
    if (status == IoStatus::Done) port_.readWaiting(exchange.bytes, protocol::kMaxReadReply);
  }
  if (auto message = protocol::replyFault(exchange, port_.path(), timeoutSeconds_)) fault(*message);
  return protocol::decodeExchange(exchange);
}

}  // namespace rb::drivers
