#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <thread>

#include "machine/watchdog.h"

using namespace rb;
using namespace std::chrono_literals;

namespace {
/// Waits up to `limit` for an alarm; returns the alarms raised.
unsigned waitForAlarm(const RunAlarms& alarms, std::chrono::milliseconds limit) {
  auto until = std::chrono::steady_clock::now() + limit;
  while (alarms.now() == 0 && std::chrono::steady_clock::now() < until) std::this_thread::sleep_for(1ms);
  return alarms.now();
}
}  // namespace

TEST_CASE("watchdog: the deadline and the memory limit raise their alarms", "[machine]") {
  Watchdog dog;
  {
    RunAlarms alarms;
    dog.arm(Watchdog::Clock::now(), WatchdogLimits{0.02, 0}, alarms, nullptr);
    CHECK(waitForAlarm(alarms, 5000ms) == RunAlarms::kDeadline);
    dog.disarm();
  }
  {
    RunAlarms alarms;
    std::atomic<uint64_t> used{100};
    dog.arm(Watchdog::Clock::now(), WatchdogLimits{0, 1000}, alarms, [&] { return used.load(); });
    std::this_thread::sleep_for(30ms);  // sampled every 10 ms, under the limit
    CHECK(alarms.now() == 0);
    used = 5000;
    CHECK(waitForAlarm(alarms, 5000ms) == RunAlarms::kMemory);
    dog.disarm();
  }
}

TEST_CASE("watchdog: disarming stops the watch at once, and it can be armed again", "[machine]") {
  Watchdog dog;
  RunAlarms alarms;
  for (int round = 0; round < 3; ++round) {
    auto start = std::chrono::steady_clock::now();
    dog.arm(start, WatchdogLimits{60, 1u << 30}, alarms, [] { return uint64_t{1}; });
    dog.disarm();
    CHECK(std::chrono::steady_clock::now() - start < 5s);  // not the 60 s deadline
  }
  CHECK(alarms.now() == 0);
  // Nothing to watch: no thread, and disarm is harmless.
  dog.arm(std::chrono::steady_clock::now(), WatchdogLimits{}, alarms, nullptr);
  dog.disarm();
  dog.disarm();
  CHECK(alarms.now() == 0);
}
