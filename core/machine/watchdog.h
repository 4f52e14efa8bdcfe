#pragma once
// A thread that keeps a run's limits while the program runs: it raises RunAlarms::kDeadline once
// the time is up and RunAlarms::kMemory when the memory a host measures goes past the limit.
// Hosts own one and arm it from Host::armWatchdog; the interpreter and long built-ins read the
// alarms (Machine::checkAlarms), so a statement that runs long still stops near the limit.

#include <pthread.h>

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>

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
  // A POSIX thread rather than a std::thread: std::thread's state is made by the caller and
  // freed by the new thread, and that first free() makes glibc set up a second malloc arena for
  // the thread (a 128 MiB reservation and three more system calls) in every run, short or not.
  // This thread allocates nothing until it first samples memory, and has a small stack.
  static void* threadMain(void* self);
  void watch();

  pthread_t thread_{};
  bool running_ = false;
  Clock::time_point deadline_;
  uint64_t memoryLimit_ = 0;
  MemorySampler memory_;
  RunAlarms* alarms_ = nullptr;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
};

}  // namespace rb
