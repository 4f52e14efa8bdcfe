#include "tui_keyboard.h"

namespace rb::tui {

void HeldKeys::press(int64_t key, Time now) {
  bool repeat = key == key_ && key_ != 0 && now - pressedAt_ < kRepeatGap;
  key_ = key;
  pressedAt_ = now;
  up_ = false;
  if (releases_) {
    seen_ = false;
    return;
  }
  // A new press must be seen once; an auto-repeat keeps the key held until the next one is due.
  seen_ = repeat && seen_;
  holdUntil_ = repeat ? now + kRepeatHold : Time{};
}

void HeldKeys::release(int64_t key, Time) {
  if (key != key_) return;  // another key went up: the last one pressed is still held
  if (seen_) key_ = 0;
  else up_ = true;
}

int64_t HeldKeys::read(Time now) {
  if (key_ == 0) return 0;
  int64_t key = key_;
  if (releases_) {
    if (up_) {
      key_ = 0;  // the tap, seen once
      up_ = false;
    }
    seen_ = true;
    return key;
  }
  if (!seen_ || now < holdUntil_) {
    seen_ = true;
    return key;
  }
  key_ = 0;
  return 0;
}

}  // namespace rb::tui
