#include "machine/watchdog.h"

#include <algorithm>
#include <utility>

namespace rb {

void Watchdog::arm(Clock::time_point start, const WatchdogLimits& limits, RunAlarms& alarms,
                   MemorySampler memory) {
  disarm();
  stop_ = false;
  Clock::time_point deadline =
      limits.seconds > 0 ? start + std::chrono::duration_cast<Clock::duration>(
                                       std::chrono::duration<double>(limits.seconds))
                         : Clock::time_point::max();
  uint64_t memoryLimit = memory ? limits.memoryBytes : 0;
  if (deadline == Clock::time_point::max() && memoryLimit == 0) return;
  thread_ = std::thread([this, deadline, memoryLimit, memory = std::move(memory), &alarms] {
    constexpr auto kSample = std::chrono::milliseconds(10);
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      Clock::time_point wake = memoryLimit > 0 ? std::min(deadline, Clock::now() + kSample) : deadline;
      if (wake_.wait_until(lock, wake, [this] { return stop_; })) return;
      if (Clock::now() >= deadline) {
        alarms.raise(RunAlarms::kDeadline);
        return;
      }
      if (memoryLimit > 0 && memory() > memoryLimit) {
        alarms.raise(RunAlarms::kMemory);
        return;
      }
    }
  });
}

void Watchdog::disarm() {
  if (!thread_.joinable()) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

}  // namespace rb
