#include "headless_host.h"

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "base/runtime_error.h"

namespace rb::run {

ResidentMemory::ResidentMemory() : fd_(::open("/proc/self/statm", O_RDONLY | O_CLOEXEC)) {}

ResidentMemory::~ResidentMemory() {
  if (fd_ >= 0) ::close(fd_);
}

uint64_t ResidentMemory::bytes() const {
  if (fd_ < 0) return 0;
  char buf[128];
  ssize_t n = ::pread(fd_, buf, sizeof buf - 1, 0);
  if (n <= 0) return 0;
  buf[n] = '\0';
  unsigned long long pages = 0, resident = 0;
  if (std::sscanf(buf, "%llu %llu", &pages, &resident) != 2) return 0;
  return static_cast<uint64_t>(resident) * static_cast<uint64_t>(::sysconf(_SC_PAGESIZE));
}

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

HeadlessHost::~HeadlessHost() {
  disarmWatchdog();
  flush();
}

void HeadlessHost::armWatchdog(const WatchdogLimits& limits, RunAlarms& alarms) {
  alarms_ = &alarms;
  std::shared_ptr<const ResidentMemory> probe = memory;
  watchdog_.arm(start_, limits, alarms,
                probe ? Watchdog::MemorySampler([probe] { return probe->bytes(); }) : Watchdog::MemorySampler());
}

uint64_t HeadlessHost::memoryInUse() { return memory ? memory->bytes() : 0; }

void HeadlessHost::disarmWatchdog() {
  watchdog_.disarm();
  alarms_ = nullptr;
}

void HeadlessHost::attachMachine(Machine& machine) { script_.useControls(&machine.controls); }

void HeadlessHost::output(std::string_view text) {
  if (outputHook) {
    outputHook(text);
    return;
  }
  written_ += text.size();
  if (copyHook) copyHook(text);
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
  InputSpan span;
  span.start = written_;
  output(prompt);
  span.promptEnd = written_;
  if (inputSource) return inputSource();
  std::optional<std::string> line = readInput();
  if (!line) return line;
  if (echoInput || script_.given()) {
    output(*line);
    output("\n");
  }
  span.end = written_;
  span.line = *line;
  if (inputHook) inputHook(span);
  return line;
}

std::optional<std::string> HeadlessHost::readInput() {
  if (script_.given()) return script_.inputLine("input");
  flush();
  if (inputFd >= 0) return readLineFromFd();
  std::string line;
  if (!std::getline(in_, line)) return std::nullopt;
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return line;
}

/// One line from inputFd, waiting in slices so that the run's deadline can end the wait.
std::optional<std::string> HeadlessHost::readLineFromFd() {
  constexpr size_t kMaxLine = 16u << 20;
  for (;;) {
    size_t end = fdBuffer_.find('\n');
    if (end != std::string::npos || fdEnded_ || fdBuffer_.size() >= kMaxLine) {
      if (end == std::string::npos) {
        if (fdBuffer_.empty()) return std::nullopt;
        end = std::min(fdBuffer_.size(), kMaxLine);
      }
      std::string line = fdBuffer_.substr(0, end);
      fdBuffer_.erase(0, std::min(end + 1, fdBuffer_.size()));
      if (!line.empty() && line.back() == '\r') line.pop_back();
      return line;
    }
    if (alarms_ && (alarms_->now() & RunAlarms::kDeadline)) throw DeadlinePassed{};
    pollfd pfd{inputFd, POLLIN, 0};
    int ready = ::poll(&pfd, 1, 100);
    if (ready < 0) {
      if (errno == EINTR) continue;
      fdEnded_ = true;
      continue;
    }
    if (ready == 0) continue;
    char chunk[4096];
    ssize_t n = ::read(inputFd, chunk, sizeof chunk);
    if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
    if (n <= 0) fdEnded_ = true;
    else fdBuffer_.append(chunk, static_cast<size_t>(n));
  }
}

double HeadlessHost::clockMs() {
  virtualMs_ += kClockReadMs;
  return virtualMs_;
}

void HeadlessHost::wait(double ms) { virtualMs_ += ms; }

double HeadlessHost::wallSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

}  // namespace rb::run
