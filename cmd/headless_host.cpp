#include "headless_host.h"

#include <cerrno>
#include <cstring>
#include <string>

#include "base/runtime_error.h"

namespace rb::cli {

namespace {
/// How far the virtual clock moves each time the program reads it, so that a loop waiting
/// for timer() to pass a value ends.
constexpr double kClockReadMs = 1.0;
constexpr size_t kFlushAt = 1 << 16;
}  // namespace

HeadlessHost::HeadlessHost(std::FILE* out, std::istream& in, InputScript script)
    : out_(out),
      in_(in),
      script_(std::move(script), virtualMs_),
      start_(std::chrono::steady_clock::now()) {}

HeadlessHost::~HeadlessHost() { flush(); }

void HeadlessHost::attachMachine(Machine& machine) { script_.useControls(&machine.controls); }

void HeadlessHost::output(std::string_view text) {
  if (outputHook) {
    outputHook(text);
    return;
  }
  buffer_ += text;
  if (buffer_.size() >= kFlushAt) flush();
  // Output that cannot be written stops the program at once (runHeadless reports it, exit 74).
  if (writeError_ != 0)
    throw RuntimeError(std::string("cannot write the program's output: ") + std::strerror(writeError_));
}

void HeadlessHost::flush() {
  if (!out_) {
    buffer_.clear();
    return;
  }
  if (writeError_ != 0) {  // output is lost already: the run stops at its next poll
    buffer_.clear();
    return;
  }
  errno = 0;
  bool ok = buffer_.empty() || std::fwrite(buffer_.data(), 1, buffer_.size(), out_) == buffer_.size();
  buffer_.clear();
  ok = std::fflush(out_) == 0 && ok;
  if (!ok) writeError_ = errno != 0 ? errno : EIO;
}

std::optional<std::string> HeadlessHost::inputLine(std::string_view prompt) {
  output(prompt);
  if (script_.given()) return script_.inputLine("input");
  flush();
  std::string line;
  if (!std::getline(in_, line)) return std::nullopt;
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return line;
}

double HeadlessHost::clockMs() {
  virtualMs_ += kClockReadMs;
  return virtualMs_;
}

void HeadlessHost::wait(double ms) { virtualMs_ += ms; }

double HeadlessHost::wallSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

}  // namespace rb::cli
