#pragma once
// What the keyboard, the mouse and the program's dialog controls look like to the input
// built-ins, the hosts and the live views: key codes, the mouse state, and the buttons and edit
// boxes a program adds. docs/interaction.md lists every code.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rb {

/// Key codes. A character key reads as its character code (letters lower-case unless Shift is
/// held); the keys that have no character read as 256 + their Windows virtual-key code, so they
/// never collide with a character and stay recognisable to anyone who knows the Windows codes.
namespace keys {
constexpr int64_t kExtended = 256;  ///< codes from here on are extended keys (getKeyE)
constexpr int64_t kBackspace = 8, kTab = 9, kEnter = 13, kEsc = 27, kSpace = 32;
constexpr int64_t kPageUp = kExtended + 33, kPageDown = kExtended + 34, kEnd = kExtended + 35,
                  kHome = kExtended + 36, kLeft = kExtended + 37, kUp = kExtended + 38,
                  kRight = kExtended + 39, kDown = kExtended + 40, kInsert = kExtended + 45,
                  kDelete = kExtended + 46;
constexpr int64_t kF1 = kExtended + 112;  ///< F1..F12 are kF1 .. kF1 + 11
constexpr int kFunctionKeys = 12;
}  // namespace keys

/// A key that has a name rather than one printable character ("up", "f1", "enter").
struct KeyName {
  std::string_view name;
  int64_t code;
};

/// Every named key, in the order the docs list them.
const std::vector<KeyName>& keyNames();
/// The code of a named key (case-insensitive), nullopt when there is no such name.
std::optional<int64_t> keyCodeByName(std::string_view name);
/// A key as scripts and messages write it: its name ("up"), else its character ("h").
std::string describeKey(int64_t code);

/// The mouse: the pointer in screen pixels and the buttons held down.
struct MouseState {
  int x = 0, y = 0;
  int buttons = 0;  ///< bits: kLeft, kRight, kMiddle
};

namespace mouse {
constexpr int kLeft = 1, kRight = 2, kMiddle = 4;
}  // namespace mouse

/// A push button added by AddButton, in screen pixels.
struct Button {
  std::string name;
  int x = 0, y = 0, width = 0, height = 0;
  bool contains(int px, int py) const {
    return px >= x && py >= y && px < x + width && py < y + height;
  }
  /// Shares a pixel with the area [ax, ax + aw) x [ay, ay + ah).
  bool overlaps(int ax, int ay, int aw, int ah) const {
    return ax < x + width && ay < y + height && ax + aw > x && ay + ah > y;
  }
};

/// A one-line text box added by AddEdit, in screen pixels.
struct EditBox {
  std::string name;
  int x = 0, y = 0, width = 0, height = 0;
  std::string text;
  bool contains(int px, int py) const {
    return px >= x && py >= y && px < x + width && py < y + height;
  }
  bool overlaps(int ax, int ay, int aw, int ah) const {
    return ax < x + width && ay < y + height && ax + aw > x && ay + ah > y;
  }
};

/// The program's dialog controls. They belong to the Machine so that live views can draw them,
/// but they are never drawn into the canvas: the robot does not sense them.
class Controls {
 public:
  static constexpr int kButtonHeight = 24;
  static constexpr int kEditHeight = 24;

  std::vector<Button> buttons;
  std::vector<EditBox> edits;
  /// The last button pressed and not yet read by GetButton ("" when none).
  std::string pressed;

  /// Lookups by exact name; nullptr when there is none.
  Button* button(std::string_view name);
  EditBox* edit(std::string_view name);
  /// The topmost control (the last added) over the screen pixels [x, x + w) x [y, y + h): a
  /// pixel by default, or the pixels a terminal cell shows; nullptr when there is none.
  const Button* buttonAt(int x, int y, int w = 1, int h = 1) const;
  const EditBox* editAt(int x, int y, int w = 1, int h = 1) const;
  /// The names of all buttons, for messages ("A, B" or "none").
  std::string buttonNames() const;
};

}  // namespace rb
