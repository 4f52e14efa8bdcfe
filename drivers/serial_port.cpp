#include "serial_port.h"

#include <fcntl.h>
#include <poll.h>
#include <sys/file.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>
#ifdef __linux__
#include <sys/sysmacros.h>
#endif

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>

#include "base/runtime_error.h"

namespace rb::drivers {

namespace {

struct BaudRate {
  int rate;
  speed_t code;
};

// POSIX names the rates up to 38400; the higher ones are common extensions.
constexpr BaudRate kBaudRates[] = {
    {300, B300},     {600, B600},     {1200, B1200},   {2400, B2400},   {4800, B4800},
    {9600, B9600},   {19200, B19200}, {38400, B38400},
#ifdef B57600
    {57600, B57600},
#endif
#ifdef B115200
    {115200, B115200},
#endif
#ifdef B230400
    {230400, B230400},
#endif
#ifdef B460800
    {460800, B460800},
#endif
#ifdef B500000
    {500000, B500000},
#endif
#ifdef B576000
    {576000, B576000},
#endif
#ifdef B921600
    {921600, B921600},
#endif
#ifdef B1000000
    {1000000, B1000000},
#endif
};

std::string rateList() {
  std::string s;
  for (const BaudRate& b : kBaudRates) s += (s.empty() ? "" : ", ") + std::to_string(b.rate);
  return s;
}

/// Milliseconds left until `deadline`, rounded up so that a wait never ends early.
int msUntil(Deadline deadline) {
  auto left = std::chrono::duration<double, std::milli>(deadline - std::chrono::steady_clock::now()).count();
  if (left <= 0) return 0;
  return static_cast<int>(std::min(std::ceil(left), 1e9));
}

/// The longest poll() while a whileWaiting hook is set.
constexpr int kWaitSliceMs = 50;

bool hangupErrno(int e) { return e == EIO || e == ENXIO || e == ENODEV || e == EPIPE; }

/// Pseudo-terminal slaves keep TIOCEXCL after their last close (the pty lives on while its
/// master is open), so a crashed rb would lock every later non-root run out. Ptys therefore get
/// only the flock, which the kernel drops with the process.
bool isPtySlave(int fd) {
#ifdef __linux__
  struct stat st {};
  if (fstat(fd, &st) != 0) return false;
  unsigned m = major(st.st_rdev);
  return S_ISCHR(st.st_mode) && m >= 136 && m <= 143;  // UNIX98_PTY_SLAVE_MAJOR and its range
#else
  (void)fd;
  return false;
#endif
}

}  // namespace

std::vector<int> supportedBaudRates() {
  std::vector<int> out;
  for (const BaudRate& b : kBaudRates) out.push_back(b.rate);
  return out;
}

SerialPort::SerialPort(std::string path, int baud) : path_(std::move(path)) {
  const BaudRate* rate = nullptr;
  for (const BaudRate& b : kBaudRates)
    if (b.rate == baud) rate = &b;
  if (!rate)
    throw RuntimeError("cannot open robot port " + path_ + " at " + std::to_string(baud) +
                       " baud: not a standard rate (use one of " + rateList() + ")");

  // O_NONBLOCK: opening must not wait for a carrier signal, and no read or write may block.
  fd_ = ::open(path_.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd_ < 0) {
    int e = errno;
    std::string why;
    switch (e) {
      case ENOENT: why = "no such device"; break;
      case ENXIO:
      case ENODEV: why = "the device is not there (unplugged, or the Bluetooth link is down)"; break;
      case EACCES:
      case EPERM: why = "permission denied (on most Linux systems: add your user to the dialout group)"; break;
      case EBUSY: throw RuntimeError("robot port " + path_ + " is busy: another program has it open");
      default: why = std::strerror(e);
    }
    throw RuntimeError("cannot open robot port " + path_ + ": " + why);
  }
  if (!::isatty(fd_)) {
    ::close(fd_);
    fd_ = -1;
    throw RuntimeError("cannot use " + path_ + " as a robot port: it is not a serial device");
  }
  // Two rb runs must never share a port: their commands and replies would interleave.
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    int e = errno;
    ::close(fd_);
    fd_ = -1;
    if (e == EWOULDBLOCK) throw RuntimeError("robot port " + path_ + " is busy: another rb has it open");
    throw RuntimeError("cannot lock robot port " + path_ + ": " + std::strerror(e));
  }
  // Keep other programs (modem managers probing new serial devices, terminal programs) out too.
  if (!isPtySlave(fd_) && ::ioctl(fd_, TIOCEXCL) == 0) exclusive_ = true;

  termios t{};
  if (::tcgetattr(fd_, &t) != 0) fail("cannot read the settings of", errno);
  ::cfmakeraw(&t);
  t.c_cflag &= ~static_cast<tcflag_t>(CSIZE | PARENB | CSTOPB);
#ifdef CRTSCTS
  t.c_cflag &= ~static_cast<tcflag_t>(CRTSCTS);
#endif
  t.c_cflag |= CS8 | CLOCAL | CREAD;
  t.c_iflag &= ~static_cast<tcflag_t>(IXON | IXOFF | IXANY);
  // VMIN 1: a read with nothing waiting says EAGAIN, so a read of 0 bytes always means hang-up.
  t.c_cc[VMIN] = 1;
  t.c_cc[VTIME] = 0;
  if (::cfsetispeed(&t, rate->code) != 0 || ::cfsetospeed(&t, rate->code) != 0)
    fail("cannot set the baud rate of", errno);
  if (::tcsetattr(fd_, TCSANOW, &t) != 0) fail("cannot configure", errno);
  ::tcflush(fd_, TCIOFLUSH);
}

SerialPort::~SerialPort() { close(); }

void SerialPort::close() {
  if (fd_ < 0) return;
  // Output the robot never took would make close() wait for it to drain.
  ::tcflush(fd_, TCIOFLUSH);
  if (exclusive_) ::ioctl(fd_, TIOCNXCL);
  ::close(fd_);  // also drops the flock
  fd_ = -1;
}

void SerialPort::fail(const std::string& what, int error) {
  close();
  throw RuntimeError(what + " robot port " + path_ + ": " + std::strerror(error));
}

void SerialPort::discardInput() {
  if (fd_ >= 0) ::tcflush(fd_, TCIFLUSH);  // a failure here shows up as a hang-up on write
}

int SerialPort::waitSlice(Deadline deadline) const {
  int ms = msUntil(deadline);
  return whileWaiting ? std::min(ms, kWaitSliceMs) : ms;
}

IoStatus SerialPort::write(const uint8_t* data, size_t n, Deadline deadline) {
  size_t done = 0;
  while (done < n) {
    ssize_t w = ::write(fd_, data + done, n - done);
    if (w > 0) {
      done += static_cast<size_t>(w);
      continue;
    }
    if (w < 0 && errno == EINTR) continue;
    if (w < 0 && errno != EAGAIN && errno != EWOULDBLOCK) {
      if (hangupErrno(errno)) return IoStatus::HungUp;
      fail("cannot write to", errno);
    }
    pollfd p{fd_, POLLOUT, 0};
    int r = ::poll(&p, 1, waitSlice(deadline));
    if (r < 0) {
      if (errno == EINTR) continue;
      fail("cannot wait for", errno);
    }
    if (r == 0) {
      if (msUntil(deadline) == 0) return IoStatus::TimedOut;
      if (whileWaiting) whileWaiting();
      continue;
    }
    if (p.revents & (POLLHUP | POLLERR | POLLNVAL)) return IoStatus::HungUp;
  }
  return IoStatus::Done;
}

IoStatus SerialPort::readAtLeast(std::vector<uint8_t>& into, size_t want, Deadline deadline) {
  uint8_t buf[64];
  while (into.size() < want) {
    pollfd p{fd_, POLLIN, 0};
    int r = ::poll(&p, 1, waitSlice(deadline));
    if (r < 0) {
      if (errno == EINTR) continue;
      fail("cannot wait for", errno);
    }
    if (r == 0) {
      if (msUntil(deadline) == 0) return IoStatus::TimedOut;
      if (whileWaiting) whileWaiting();
      continue;
    }
    if (p.revents & POLLIN) {
      ssize_t n = ::read(fd_, buf, sizeof buf);
      if (n > 0) {
        into.insert(into.end(), buf, buf + n);
        continue;
      }
      if (n == 0) return IoStatus::HungUp;  // end of file on a terminal: hang-up
      if (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR) continue;
      if (hangupErrno(errno)) return IoStatus::HungUp;
      fail("cannot read from", errno);
    }
    if (p.revents & (POLLHUP | POLLERR | POLLNVAL)) return IoStatus::HungUp;
  }
  return IoStatus::Done;
}

void SerialPort::readWaiting(std::vector<uint8_t>& into, size_t limit) {
  uint8_t buf[64];
  while (into.size() < limit) {
    ssize_t n = ::read(fd_, buf, sizeof buf);
    if (n > 0) {
      into.insert(into.end(), buf, buf + n);
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    return;  // nothing more waiting, or a hang-up the next command will report
  }
  // A device that keeps sending is read no further: `limit` bytes already prove it wrong.
}

}  // namespace rb::drivers
