#pragma once
// The rules of input that do not depend on where the input comes from: which keys answer a
// message box, which keys type a character, how a line is typed at an `input` prompt, what a
// mouse press on the program's buttons and edit boxes does, and which edit box has the keyboard.
// The live view (tui/tui_host.cpp) and scripted input (input_script.cpp) both follow them, so a
// script and a person at the keyboard get the same answers. docs/interaction.md states them.

#include <cstdint>
#include <string>

#include "input/input.h"

namespace rb {

class InputRules {
 public:
  // ---- keys

  /// Keys that answer a message box (its one button, OK): Enter, Esc and space.
  static bool answersMessageBox(int64_t key);
  /// Mouse buttons that answer a message box when they go down: the left one.
  static bool clickAnswersMessageBox(int buttons) { return (buttons & mouse::kLeft) != 0; }
  /// Keys that type their character: the printable Latin-1 characters (32..126 and 160..255;
  /// characters beyond U+00FF have no key code, as on Windows' 8-bit keyboard input).
  static bool typesCharacter(int64_t key);

  /// What a key does to a line being typed (at an `input` prompt or in an edit box).
  enum class LineKey : uint8_t {
    Typed,       ///< a character was added
    Deleted,     ///< Backspace took the last character away
    Done,        ///< Enter: the line is finished
    EndOfInput,  ///< Ctrl-D on an empty line: there is no more input
    Ignored,     ///< anything else
  };
  /// Applies `key` to `text`.
  static LineKey editLine(std::string& text, int64_t key);

  // ---- the program's controls (state: which edit box has the keyboard)

  /// What a mouse press went to.
  enum class Target : uint8_t { Program, Button, EditBox };
  /// A mouse button went down over the screen pixels [x, x + w) x [y, y + h) (a point, or the
  /// pixels one terminal cell shows). The topmost button there is pressed (`controls.pressed`
  /// names it until GetButton reads it); else the topmost edit box there gets the keyboard;
  /// else the press is the program's to read and no edit box has the keyboard any more.
  Target press(Controls& controls, int x, int y, int w = 1, int h = 1);
  /// A key typed while an edit box has the keyboard goes into it (Enter, Tab and Esc give the
  /// keyboard back). Returns false when no edit box has the keyboard: the key is the program's.
  bool typeInto(Controls& controls, int64_t key);
  /// The edit box that has the keyboard ("" when none).
  const std::string& focusedEdit() const { return focused_; }

 private:
  std::string focused_;
};

}  // namespace rb
