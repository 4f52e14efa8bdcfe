#pragma once
// A POSIX serial device opened for RobotBASIC's robot protocol: 8 data bits, no parity, one
// stop bit, raw bytes, no flow control. It works the same over a real UART, a USB adapter, a
// Bluetooth rfcomm device or a pseudo-terminal. Every wait has a deadline: nothing here blocks
// without one.

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace rb::drivers {

using Deadline = std::chrono::steady_clock::time_point;

/// How a read or a write ended.
enum class IoStatus {
  Done,      ///< everything asked for was transferred
  TimedOut,  ///< the deadline passed first
  HungUp,    ///< the device went away (unplugged, Bluetooth link lost, pty master closed)
};

/// The standard baud rates this build of rb can set, ascending.
std::vector<int> supportedBaudRates();

/// An open, configured and locked serial device; destroying it releases the device.
class SerialPort {
 public:
  /// Opens and configures `path` at `baud`, locking it so that no second rb (nor, for real
  /// serial devices, any other program) can open it meanwhile. Throws RuntimeError naming the
  /// path when the rate is not standard, the device is missing, not a serial device, busy, or
  /// cannot be configured.
  SerialPort(std::string path, int baud);
  ~SerialPort();
  SerialPort(const SerialPort&) = delete;
  SerialPort& operator=(const SerialPort&) = delete;

  /// The path as given ("/dev/rfcomm4", "/tmp/robot").
  const std::string& path() const { return path_; }
  /// False after close() or a fault.
  bool isOpen() const { return fd_ >= 0; }
  /// Releases the device (and its lock) now rather than at destruction.
  void close();

  /// Drops bytes that arrived but were not read: a late answer to an earlier command must not
  /// be taken for the answer to the next one.
  void discardInput();
  /// Writes all `n` bytes before `deadline`.
  IoStatus write(const uint8_t* data, size_t n, Deadline deadline);
  /// Reads into `into` until it holds at least `want` bytes, the deadline passes or the device
  /// hangs up. Bytes are read in blocks, so a reply longer than `want` that arrived at once is
  /// kept whole. Data that arrived before a hang-up is returned first (status Done).
  IoStatus readAtLeast(std::vector<uint8_t>& into, size_t want, Deadline deadline);
  /// Appends whatever bytes are already waiting, without waiting for more, until `into` holds
  /// `limit` bytes (a device that floods the line is not read forever).
  void readWaiting(std::vector<uint8_t>& into, size_t limit);
  /// When set, write() and readAtLeast() wait in slices of at most 50 ms and call it between
  /// them; it may throw to end the wait (the run's time limit).
  std::function<void()> whileWaiting;

 private:
  [[noreturn]] void fail(const std::string& what, int error);
  /// How long the next poll() may wait: until the deadline, or one slice with a whileWaiting hook.
  int waitSlice(Deadline deadline) const;

  std::string path_;
  int fd_ = -1;
  bool exclusive_ = false;  ///< TIOCEXCL set: cleared again before closing
};

}  // namespace rb::drivers
