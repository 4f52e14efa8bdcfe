#include "transport.h"

#include <catch2/catch.hpp>
#include <random>
#include <sstream>

using rb::lsp::MessageReader;
using Status = MessageReader::Status;

namespace {
std::string frame(const std::string& body) {
  return "Content-Length: " + std::to_string(body.size()) + "\r\n\r\n" + body;
}
}  // namespace

TEST_CASE("the transport reads framed messages one after another", "[lsp]") {
  std::istringstream in(frame("{\"a\":1}") + frame("{}") +
                        "content-length:  3\r\nContent-Type: application/vscode-jsonrpc; charset=utf-8\r\n\r\n[1]");
  MessageReader reader(in);
  auto r = reader.next();
  REQUIRE(r.status == Status::Ok);
  CHECK(r.body == "{\"a\":1}");
  r = reader.next();
  REQUIRE(r.status == Status::Ok);
  CHECK(r.body == "{}");
  r = reader.next();
  REQUIRE(r.status == Status::Ok);  // header names in any case, other headers ignored
  CHECK(r.body == "[1]");
  CHECK(reader.next().status == Status::End);
}

TEST_CASE("the transport accepts bare line feeds in headers", "[lsp]") {
  std::istringstream in("Content-Length: 2\n\n{}");
  MessageReader reader(in);
  auto r = reader.next();
  REQUIRE(r.status == Status::Ok);
  CHECK(r.body == "{}");
}

TEST_CASE("a header block without a usable length is skipped and reading goes on", "[lsp]") {
  std::istringstream in("Content-Type: x\r\n\r\n" "Content-Length: abc\r\n\r\n" "Content-Length: -5\r\n\r\n" +
                        frame("{}"));
  MessageReader reader(in);
  CHECK(reader.next().status == Status::BadHeader);
  CHECK(reader.next().status == Status::BadHeader);
  CHECK(reader.next().status == Status::BadHeader);
  auto r = reader.next();
  REQUIRE(r.status == Status::Ok);
  CHECK(r.body == "{}");
}

TEST_CASE("a message above the cap is read away, not kept", "[lsp]") {
  std::string big(5000, 'x');
  std::istringstream in(frame(big) + frame("{}"));
  MessageReader reader(in, 1000);
  auto r = reader.next();
  CHECK(r.status == Status::TooLarge);
  CHECK(r.body.empty());
  CHECK(r.why.find("5000") != std::string::npos);
  r = reader.next();
  REQUIRE(r.status == Status::Ok);
  CHECK(r.body == "{}");
}

TEST_CASE("an absurd Content-Length is said at once and the next message is still read", "[lsp]") {
  std::istringstream in("Content-Length: 99999999999999999999999\r\n\r\n{}" + frame("[1]"));
  MessageReader reader(in, 1000);
  CHECK(reader.next().status == Status::BadHeader);
  auto r = reader.next();
  REQUIRE(r.status == Status::Ok);
  CHECK(r.body == "[1]");
  CHECK(reader.next().status == Status::End);
  // 2^63: past what rb reads away, so it looks for the next header instead of swallowing
  // every later message.
  std::istringstream in2("Content-Length: 9223372036854775808\r\n\r\n{\"jsonrpc\": \"2.0\"}\r\n" + frame("[2]"));
  MessageReader reader2(in2, 1000);
  r = reader2.next();
  CHECK(r.status == Status::TooLarge);
  CHECK(r.why == "a message of 9223372036854775808 bytes (the limit is 1000)");
  r = reader2.next();
  REQUIRE(r.status == Status::Ok);
  CHECK(r.body == "[2]");
  std::istringstream in3("Content-Length: 18000000000000000000\r\n\r\n{}");
  MessageReader reader3(in3, 1000);
  CHECK(reader3.next().status == Status::TooLarge);
  CHECK(reader3.next().status == Status::End);
}

TEST_CASE("a body over the cap is refused before it is read, then read away", "[lsp]") {
  std::istringstream in("Content-Length: 2000\r\n\r\n" + std::string(2000, 'x') + frame("[3]"));
  MessageReader reader(in, 1000);
  CHECK(reader.next().status == Status::TooLarge);
  CHECK(in.tellg() < 100);  // nothing of the body read yet: the error is answered first
  auto r = reader.next();
  REQUIRE(r.status == Status::Ok);
  CHECK(r.body == "[3]");
}

TEST_CASE("a body cut short by the end of input ends the stream", "[lsp]") {
  std::istringstream in("Content-Length: 10\r\n\r\n{}");
  MessageReader reader(in);
  CHECK(reader.next().status == Status::End);
  CHECK(reader.next().status == Status::End);
}

TEST_CASE("endless header lines are capped", "[lsp]") {
  std::string junk(100000, 'h');
  std::istringstream in(junk + "\r\n\r\n" + frame("{}"));
  MessageReader reader(in);
  CHECK(reader.next().status == Status::BadHeader);
  auto r = reader.next();
  REQUIRE(r.status == Status::Ok);
  CHECK(r.body == "{}");
}

TEST_CASE("the transport survives mutated and random input (fuzz-ish)", "[lsp]") {
  std::mt19937 rng(11);
  std::string valid = frame("{\"jsonrpc\":\"2.0\",\"id\":1,\"method\":\"initialize\"}") + frame("{}") +
                      frame("{\"x\":[1,2,3]}");
  for (int round = 0; round < 2000; ++round) {
    std::string s = valid;
    int edits = 1 + static_cast<int>(rng() % 8);
    for (int e = 0; e < edits; ++e) {
      size_t at = rng() % (s.size() + 1);
      switch (rng() % 4) {
        case 0: if (at < s.size()) s[at] = static_cast<char>(rng() % 256); break;
        case 1: if (at < s.size()) s.erase(at, 1 + rng() % 4); break;
        case 2: s.insert(at, 1, "\r\n:0123456789 "[rng() % 14]); break;
        case 3: s.insert(at, std::string(1 + rng() % 20, static_cast<char>(rng() % 256))); break;
      }
    }
    std::istringstream in(s);
    MessageReader reader(in, 4096);
    int steps = 0;
    for (;;) {
      auto r = reader.next();
      REQUIRE(r.body.size() <= 4096);
      if (r.status == Status::End) break;
      REQUIRE(++steps <= static_cast<int>(s.size()) + 1);  // every step consumes input
    }
  }
}

TEST_CASE("writeMessage frames a body", "[lsp]") {
  std::ostringstream out;
  rb::lsp::writeMessage(out, "{\"é\":1}");
  CHECK(out.str() == "Content-Length: 8\r\n\r\n{\"é\":1}");  // bytes, not characters
}
