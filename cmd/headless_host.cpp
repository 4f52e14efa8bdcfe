#include "headless_host.h"

#include <string>

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

void HeadlessHost::output(std::string_view text) {
  if (outputHook) {
    outputHook(text);
    return;
  }
  buffer_ += text;
  if (buffer_.size() >= kFlushAt) flush();
}

void HeadlessHost::flush() {
  if (!out_) {
    buffer_.clear();
    return;
  }
  if (!buffer_.empty()) {
    std::fwrite(buffer_.data(), 1, buffer_.size(), out_);
    buffer_.clear();
  }
  std::fflush(out_);
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
