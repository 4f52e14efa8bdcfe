// What a link makes of the bytes a robot sent back for one command: every link (the serial port,
// Web Serial on the page) reports the same faults in the same words.
#include <catch2/catch.hpp>

#include "robot/protocol.h"
#include "robot/reply_check.h"

using rb::protocol::Exchange;
using rb::protocol::replyFault;

namespace {
Exchange exchange(std::vector<uint8_t> bytes, Exchange::End end = Exchange::End::Complete) {
  Exchange e;
  e.bytes = std::move(bytes);
  e.end = end;
  return e;
}
}  // namespace

TEST_CASE("a plausible five-byte reply is decoded") {
  Exchange e = exchange({0, 0, 0, 0x01, 0x2c});
  CHECK_FALSE(replyFault(e, "COM5", 2).has_value());
  CHECK(rb::protocol::decodeExchange(e).result == 300);
}

TEST_CASE("each fault of an exchange has rb run's message") {
  CHECK(replyFault(exchange({}, Exchange::End::TimedOut), "COM5", 2) == "robot on COM5 did not answer within 2 s");
  CHECK(replyFault(exchange({1, 2}, Exchange::End::TimedOut), "COM5", 0.5) ==
        "robot on COM5 sent a short reply: 2 of 5 bytes within 0.5 s (01 02)");
  CHECK(replyFault(exchange({0, 0, 0, 0, 0, 0, 0}), "COM5", 2) ==
        "robot on COM5 sent a malformed reply: 7 bytes instead of 5 (00 00 00 00 00 00 00)");
  CHECK(replyFault(exchange(std::vector<uint8_t>(rb::protocol::kMaxReadReply, 0xff)), "COM5", 2)->starts_with(
      "robot on COM5 sent a malformed reply: at least 256 bytes instead of 5 (ff ff"));
  CHECK(replyFault(exchange({0xff, 0xff, 0xff, 0xff, 0xff}), "COM5", 2) ==
        "robot on COM5 sent a malformed reply (ff ff ff ff ff): sensor bits no robot sets");
  CHECK(replyFault(exchange({}, Exchange::End::HungUp), "COM5", 2) ==
        "lost the connection to the robot on COM5: the device hung up");
}
