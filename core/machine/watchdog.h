#pragma once
// A thread that keeps a run's limits while the program runs: it raises RunAlarms::kDeadline once
// the time is up and RunAlarms::kMemory when the memory a host measures goes past the limit.
// Hosts own one and arm it from Host::armWatchdog; the interpreter and long built-ins read the
// alarms (Machine::checkAlarms), so a statement that runs long still stops near the limit.

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>

#include "machine/host.h"

namespace rb {

class Watchdog {
 public:
  using Clock = std::chrono::steady_clock;
  /// The memory to compare with WatchdogLimits::memoryBytes, sampled every 10 ms.
  using MemorySampler = std::function<uint64_t()>;

  Watchdog() = default;
  Watchdog(const Watchdog&) = delete;
  Watchdog& operator=(const Watchdog&) = delete;
  ~Watchdog() { disarm(); }

  /// Starts watching: the deadline is `start` + limits.seconds (none when 0); memory is watched
  /// when limits.memoryBytes and `memory` are both given. Disarms an earlier watch first.
  void arm(Clock::time_point start, const WatchdogLimits& limits, RunAlarms& alarms,
           MemorySampler memory);
  /// Stops the thread (at once; it is waiting on a condition variable).
  void disarm();

 private:
  std::thread thread_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
};

}  // namespace rb
