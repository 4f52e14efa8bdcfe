#pragma once
// The Host of a headless run: program output to a stream, `input` lines from a stream, and a
// virtual clock that only moves when the program waits (delay, robot motion at rSpeed) or
// reads timer(), so runs are fast and repeatable.

#include <chrono>
#include <cstdio>
#include <functional>
#include <istream>

#include "host.h"

namespace rb::cli {

class HeadlessHost : public Host {
 public:
  /// Program output goes to `out` (nullptr: discarded), `input` reads lines from `in`.
  HeadlessHost(std::FILE* out, std::istream& in);
  ~HeadlessHost() override;

  void output(std::string_view text) override;
  std::optional<std::string> inputLine(std::string_view prompt) override;
  double clockMs() override;
  void wait(double ms) override;
  double wallSeconds() override;
  void onLine(SourceLoc loc) override {
    if (lineHook) lineHook(loc);
  }
  void flush();

  std::unique_ptr<RobotLink> openRobot(int64_t port) override {
    if (robotOpener) return robotOpener(port);
    return Host::openRobot(port);
  }

  /// Called before each statement of a program compiled for line tracing.
  std::function<void(SourceLoc)> lineHook;
  /// Opens a real robot's port for rCommPort.
  std::function<std::unique_ptr<RobotLink>(int64_t)> robotOpener;

 private:
  std::FILE* out_;
  std::istream& in_;
  std::string buffer_;
  double virtualMs_ = 0;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace rb::cli
