#include "emulator_server.h"

#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include "robot/protocol.h"
#include "base/runtime_error.h"

namespace rb::drivers {

namespace {

using Clock = std::chrono::steady_clock;

/// How often the loop looks at `stop` and, between clients, for a new one.
constexpr int kTickMs = 50;
/// How long the last reply before --die-after closes the port stays readable.
constexpr int kDieLingerMs = 200;
/// A command byte whose partner does not follow within this time is noise and is dropped,
/// so that one stray byte cannot shift every later command.
constexpr auto kCommandGap = std::chrono::milliseconds(500);

/// Sleeps `ms` in short steps; returns false when `stop` cut it short.
bool pause(int ms, const std::function<bool()>& stop) {
  auto end = Clock::now() + std::chrono::milliseconds(ms);
  while (Clock::now() < end) {
    if (stop()) return false;
    auto step = std::min<Clock::duration>(end - Clock::now(), std::chrono::milliseconds(kTickMs));
    std::this_thread::sleep_for(step);
  }
  return true;
}

/// Writes all bytes to the master; false when the client has gone.
bool writeAll(int fd, const std::vector<uint8_t>& bytes) {
  size_t done = 0;
  while (done < bytes.size()) {
    ssize_t w = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (w > 0) {
      done += static_cast<size_t>(w);
    } else if (w < 0 && (errno == EAGAIN || errno == EINTR)) {
      pollfd p{fd, POLLOUT, 0};
      ::poll(&p, 1, kTickMs);
    } else {
      return false;
    }
  }
  return true;
}

void logLine(std::FILE* log, uint8_t code, uint8_t param, const EmulatorAnswer& a) {
  if (!log) return;
  uint8_t cmd[2] = {code, param};
  std::string name(protocol::commandName(code));
  std::string line = protocol::hexBytes(cmd, 2) + " " + (name.empty() ? "(user command)" : name) + " -> ";
  if (a.bytes.empty()) line += a.note;
  else line += (a.note.empty() ? "" : a.note + " ") + protocol::hexBytes(a.bytes.data(), a.bytes.size());
  if (a.die) line += ", then the port closes";
  std::fprintf(log, "%s\n", line.c_str());
  std::fflush(log);
}

}  // namespace

StopSignals::StopSignals() {
  sigemptyset(&stop_);
  sigaddset(&stop_, SIGINT);
  sigaddset(&stop_, SIGTERM);
  sigaddset(&stop_, SIGHUP);
  pthread_sigmask(SIG_BLOCK, &stop_, nullptr);
}

bool StopSignals::requested() const {
  sigset_t pending;
  if (sigpending(&pending) != 0) return false;
  for (int s : {SIGINT, SIGTERM, SIGHUP})
    if (sigismember(&pending, s)) return true;
  return false;
}

ServeEnd serveRobot(Pty& pty, RobotEmulator& emulator, const ServeOptions& options,
                    const std::function<bool()>& stop) {
  std::vector<uint8_t> pending;
  Clock::time_point firstByte{};
  bool connected = false;
  while (!stop()) {
    pollfd p{pty.master(), POLLIN, 0};
    int r = ::poll(&p, 1, kTickMs);
    if (r < 0) {
      if (errno == EINTR) continue;
      throw RuntimeError(std::string("rb robot: waiting for commands failed: ") + std::strerror(errno));
    }
    if (r == 0) {
      if (!pending.empty() && Clock::now() - firstByte > kCommandGap) pending.clear();
      continue;
    }
    bool hungUp = false;
    if (p.revents & POLLIN) {
      uint8_t buf[64];
      ssize_t n = ::read(pty.master(), buf, sizeof buf);
      if (n > 0) {
        if (!connected && options.log) std::fprintf(options.log, "client connected\n");
        connected = true;
        if (pending.empty()) firstByte = Clock::now();
        pending.insert(pending.end(), buf, buf + n);
      } else if (n == 0 || (errno != EAGAIN && errno != EINTR)) {
        hungUp = true;  // EIO: no client has the slave side open
      }
    } else if (p.revents & (POLLHUP | POLLERR)) {
      hungUp = true;
    }
    if (hungUp) {
      // Between clients the master reports a hang-up at once; wait for the next one.
      pending.clear();
      if (connected && options.log) std::fprintf(options.log, "client disconnected\n");
      connected = false;
      pause(kTickMs, stop);
      continue;
    }
    while (pending.size() >= 2) {
      uint8_t code = pending[0], param = pending[1];
      pending.erase(pending.begin(), pending.begin() + 2);
      if (!pending.empty()) firstByte = Clock::now();
      EmulatorAnswer answer = emulator.handle(code, param);
      logLine(options.log, code, param, answer);
      if (options.latencyMs > 0 && !pause(options.latencyMs, stop)) return ServeEnd::Stopped;
      if (!answer.bytes.empty() && !writeAll(pty.master(), answer.bytes)) pending.clear();
      if (answer.die) {
        // Closing a pty master flushes what the client has not read yet: give it time to take
        // the last reply, so that the hang-up meets the command after it.
        pause(kDieLingerMs, stop);
        pty.close();
        return ServeEnd::Died;
      }
    }
  }
  return ServeEnd::Stopped;
}

}  // namespace rb::drivers
