#pragma once
// The Host of a headless run: program output to a stream, `input` lines from a stream, and a
// virtual clock that only moves when the program waits (delay, robot motion at rSpeed) or
// reads timer(), so runs are fast and repeatable.

#include <chrono>
#include <cstdio>
#include <istream>

#include "host.h"

namespace rb::cli {

class HeadlessHost : public Host {
 public:
  HeadlessHost(std::FILE* out, std::istream& in);
  ~HeadlessHost() override;

  void output(std::string_view text) override;
  std::optional<std::string> inputLine(std::string_view prompt) override;
  double clockMs() override;
  void wait(double ms) override;
  double wallSeconds() override;
  void flush();

 private:
  std::FILE* out_;
  std::istream& in_;
  std::string buffer_;
  double virtualMs_ = 0;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace rb::cli
