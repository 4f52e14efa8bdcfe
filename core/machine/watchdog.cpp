#include "machine/watchdog.h"

#include <algorithm>
#include <system_error>
#include <utility>

namespace rb {

namespace {
/// The watching thread's stack: it calls the memory sampler (a file read) and waits.
constexpr size_t kStackBytes = size_t{256} << 10;
}  // namespace

void Watchdog::arm(Clock::time_point start, const WatchdogLimits& limits, RunAlarms& alarms,
                   MemorySampler memory) {
  disarm();
  stop_ = false;
  deadline_ = limits.seconds > 0 ? start + std::chrono::duration_cast<Clock::duration>(
                                               std::chrono::duration<double>(limits.seconds))
                                 : Clock::time_point::max();
  memoryLimit_ = memory ? limits.memoryBytes : 0;
  if (deadline_ == Clock::time_point::max() && memoryLimit_ == 0) return;
  memory_ = std::move(memory);
  alarms_ = &alarms;
  pthread_attr_t attr;
  pthread_attr_init(&attr);
  pthread_attr_setstacksize(&attr, kStackBytes);  // refused below the system's minimum: the default
  int err = pthread_create(&thread_, &attr, &Watchdog::threadMain, this);
  pthread_attr_destroy(&attr);
  if (err != 0) throw std::system_error(err, std::generic_category(), "cannot start the watchdog thread");
  running_ = true;
}

void* Watchdog::threadMain(void* self) {
  static_cast<Watchdog*>(self)->watch();
  return nullptr;
}

void Watchdog::watch() {
  constexpr auto kSample = std::chrono::milliseconds(10);
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    Clock::time_point wake = memoryLimit_ > 0 ? std::min(deadline_, Clock::now() + kSample) : deadline_;
    if (wake_.wait_until(lock, wake, [this] { return stop_; })) return;
    if (Clock::now() >= deadline_) {
      alarms_->raise(RunAlarms::kDeadline);
      return;
    }
    if (memoryLimit_ > 0 && memory_() > memoryLimit_) {
      alarms_->raise(RunAlarms::kMemory);
      return;
    }
  }
}

void Watchdog::disarm() {
  if (!running_) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  pthread_join(thread_, nullptr);
  running_ = false;
}

}  // namespace rb
