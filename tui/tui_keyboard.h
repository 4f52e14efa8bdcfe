#pragma once
// Which key a program's getKey, getKeyE and keyDown see in the live view. Terminals that speak
// the kitty keyboard protocol report releases, so a key is held from its press to its release.
// Other terminals report presses only: then a press counts as held until one read has seen it
// (a tap is one press, never held for a while), and the terminal's auto-repeat, presses of the
// same key in quick succession, keeps a held key down between its repeats.

#include <chrono>
#include <cstdint>

namespace rb::tui {

class HeldKeys {
 public:
  using Clock = std::chrono::steady_clock;
  using Time = Clock::time_point;

  /// Presses of the same key closer together than this are the terminal's auto-repeat (people
  /// cannot tap a key this fast; terminals repeat every 30 to 50 ms).
  static constexpr auto kRepeatGap = std::chrono::milliseconds(100);
  /// After an auto-repeat press the key counts as held this long, to the next repeat.
  static constexpr auto kRepeatHold = std::chrono::milliseconds(120);

  /// Whether the terminal reports releases (release() is then called for every key let go).
  void setReportsReleases(bool on) { releases_ = on; }
  bool reportsReleases() const { return releases_; }

  /// A key went down, or the terminal repeated it.
  void press(int64_t key, Time now);
  /// A key went up (terminals that report releases only).
  void release(int64_t key, Time now);
  /// The key held down now, as a read at `now` sees it (0: none); the read counts as seeing it.
  int64_t read(Time now);
  /// Every key goes up (the view paused or the program stopped reading).
  void clear() { key_ = 0; }

 private:
  bool releases_ = false;
  int64_t key_ = 0;        ///< the key down now (0: none)
  bool seen_ = false;      ///< a read has seen key_ since its last press
  bool up_ = false;        ///< released, but no read has seen it yet: one read still does
  Time pressedAt_{};       ///< the last press of key_
  Time holdUntil_{};       ///< without releases: held until then (after an auto-repeat)
};

}  // namespace rb::tui
