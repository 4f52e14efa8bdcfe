#pragma once
// Terminal input bytes turned into rb's key and mouse events, for terminals that speak the kitty
// keyboard protocol (kitty, foot, WezTerm, Ghostty): there every key, its repeats and its
// release arrive as escape sequences (CSI code;mods:event u, CSI 1;mods:event A, CSI n~), which
// ncurses does not decode. Mouse reports are xterm's SGR form (CSI < b;x;y M/m). Pure: fed
// bytes, it hands out events; curses_screen.cpp reads the terminal into it.

#include <cstdint>
#include <deque>
#include <string>
#include <string_view>

namespace rb::render {

/// Something the terminal reported.
struct TermEvent {
  enum Kind { None, Key, Mouse, Resize } kind = None;
  /// Key: rb's key code (core/input/input.h); Ctrl+letter reads as its control character (1..26).
  int64_t key = 0;
  /// Key: the key went up (terminals that report releases only); a repeat reads as a press.
  bool release = false;
  // Mouse: the cell under the pointer and what changed.
  int col = 0, row = 0;
  int pressed = 0;   ///< buttons that went down (1 left, 2 right, 4 middle)
  int released = 0;  ///< buttons that went up
};

/// The kitty keyboard protocol's progressive enhancement flags rb asks for: disambiguate escape
/// codes (1), report event types (2: repeats and releases), report alternate keys (4: the
/// shifted character), report all keys as escape codes (8: letters too, so they have releases).
constexpr int kKittyKeyFlags = 1 | 2 | 4 | 8;

class KittyInput {
 public:
  /// Appends bytes read from the terminal.
  void feed(std::string_view bytes);
  /// The next complete event (kind None when none is complete). Bytes of an unfinished escape
  /// sequence stay until more arrive or flush() is called.
  TermEvent next();
  /// No more bytes came for a while: a lone ESC is the Esc key, other unfinished bytes are
  /// dropped.
  void flush();
  /// True when bytes of an unfinished sequence wait.
  bool pending() const { return !buffer_.empty(); }

 private:
  /// Decodes one event from the front of buffer_; false when it needs more bytes. Sets `out`
  /// (kind None for sequences that mean nothing to rb, which are dropped).
  bool decode(TermEvent& out);

  std::string buffer_;
  std::deque<TermEvent> ready_;
};

/// Decodes a `CSI ... u` key's parameters ("97:65;2:3"); kind None when rb has no code for it.
TermEvent kittyKeyEvent(std::string_view params, char final);

}  // namespace rb::render
