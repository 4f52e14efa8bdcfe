// Input built-ins: the keyboard, the mouse, message boxes, buttons and edit boxes. Every read
// goes through the Host (a live view, or scripted input when headless); the controls a program
// adds are Machine state that live views draw as overlays. docs/interaction.md documents them.
#include <cctype>
#include <cmath>

#include "machine/builtins_impl.h"
#include "base/runtime_error.h"

namespace rb::builtins {

namespace {

using K = BuiltinKind;

/// The default width of a button: room for its name in an 8-pixel font plus a margin.
int defaultButtonWidth(const std::string& name) { return static_cast<int>(name.size()) * 8 + 16; }

int positiveSize(Args& a, int i) {
  int v = a.coordinate(i);
  if (v < 1) throw RuntimeError(a.describe(i) + " must be at least 1 pixel");
  return v;
}

/// A control's name: a non-empty string.
const std::string& controlName(Args& a, int i) {
  const std::string& s = a.str(i);
  if (s.empty()) throw RuntimeError(a.describe(i) + " must not be empty");
  return s;
}

bool isExtended(int64_t code) { return code >= keys::kExtended; }

Value getKey(Machine& m, Args& a) {
  int64_t code = m.host().heldKey("getKey");
  a[0] = Value::integer(isExtended(code) ? 0 : code);
  return {};
}

Value getKeyE(Machine& m, Args& a) {
  a[0] = Value::integer(m.host().heldKey("getKeyE"));
  return {};
}

Value waitKey(Machine& m, Args& a) {
  if (a.size() == 2) m.printPrompt(formatValue(a[0]));
  a[a.size() - 1] = Value::integer(m.host().waitKey("waitKey"));
  return {};
}

Value keyDown(Machine& m, Args& a) {
  int64_t want = a.integer(0);
  int64_t held = m.host().heldKey("keyDown");
  // A letter is down whether or not Shift is held with it.
  auto fold = [](int64_t c) {
    return c < 128 ? static_cast<int64_t>(std::tolower(static_cast<int>(c))) : c;
  };
  return Value::boolean(held != 0 && fold(held) == fold(want));
}

void storeMouse(Args& a, const MouseState& s) {
  a[0] = Value::integer(s.x);
  a[1] = Value::integer(s.y);
  if (a.has(2)) a[2] = Value::integer(s.buttons);
}

Value readMouse(Machine& m, Args& a) {
  storeMouse(a, m.host().mouse("readMouse"));
  return {};
}

Value waitClick(Machine& m, Args& a) {
  storeMouse(a, m.host().waitClick("waitClick"));
  return {};
}

/// MsgBox's text: a value, or an array whose elements are its lines (a published program builds
/// the text with `data IM; "line"` and shows it with `MsgBox(IM)`). Lines are joined while the
/// text stays one string (kMaxString), with the run's limits looked at every 65,536 lines: an
/// array of many long strings (sharing one text) cannot make the join take memory or time
/// without end.
std::string messageText(Machine& m, const Value& v) {
  if (!v.isArr()) return formatValue(v);
  std::string text;
  char room[kNumberTextSize];
  uint32_t count = 0;
  for (const Value& line : v.arr().items) {
    if (++count % 65536 == 0) m.checkAlarms();
    std::string_view part = line.isUndef() ? std::string_view() : printedForm(line, room);
    bool newline = !text.empty();
    if (text.size() + newline + part.size() > static_cast<uint64_t>(kMaxString))
      throw RuntimeError("MsgBox: the array's lines make a text longer than " + std::to_string(kMaxString) +
                         " characters");
    if (newline) text += '\n';
    text += part;
  }
  return text;
}

Value msgBox(Machine& m, Args& a) {
  std::string title = a.has(1) ? formatValue(a[1]) : "RobotBASIC";
  m.host().messageBox(messageText(m, a[0]), title);
  return Value::integer(1);  // the button that closed it: OK
}

Value addButton(Machine& m, Args& a) {
  const std::string& name = controlName(a, 0);
  Button b{name, a.coordinate(1), a.coordinate(2),
           a.has(3) ? positiveSize(a, 3) : defaultButtonWidth(name),
           a.has(4) ? positiveSize(a, 4) : Controls::kButtonHeight};
  // Adding a name again moves that button.
  if (Button* old = m.controls.button(name)) *old = b;
  else m.controls.buttons.push_back(b);
  return {};
}

/// The last button pressed, consumed by reading it.
std::string takePressed(Machine& m, std::string_view who) {
  m.host().updateControls(m.controls, who);
  std::string name = std::move(m.controls.pressed);
  m.controls.pressed.clear();
  return name;
}

Value getButton(Machine& m, Args& a) {
  a[0] = Value::string(takePressed(m, "GetButton"));
  return {};
}

Value lastButton(Machine& m, Args&) { return Value::string(takePressed(m, "LastButton")); }

Value removeButton(Machine& m, Args& a) {
  const std::string& name = a.str(0);
  auto& list = m.controls.buttons;
  for (auto it = list.begin(); it != list.end(); ++it) {
    if (it->name == name) {
      list.erase(it);
      if (m.controls.pressed == name) m.controls.pressed.clear();
      return {};
    }
  }
  throw RuntimeError("RemoveButton: there is no button named '" + name + "'");
}

Value addEdit(Machine& m, Args& a) {
  const std::string& name = controlName(a, 0);
  EditBox e{name, a.coordinate(1), a.coordinate(2), positiveSize(a, 3), Controls::kEditHeight,
            a.has(4) ? formatValue(a[4]) : std::string()};
  if (EditBox* old = m.controls.edit(name)) *old = e;
  else m.controls.edits.push_back(e);
  return {};
}

EditBox& editNamed(Machine& m, Args& a, std::string_view who) {
  const std::string& name = a.str(0);
  EditBox* e = m.controls.edit(name);
  if (!e) throw RuntimeError(std::string(who) + ": there is no edit box named '" + name + "'");
  return *e;
}

// Reading an edit box's text reads state, not input: it does not move scripted input on, so a
// program that reads the box right after a button press sees the text of that moment.
Value getEdit(Machine& m, Args& a) { return Value::string(editNamed(m, a, "GetEdit").text); }

Value setEdit(Machine& m, Args& a) {
  editNamed(m, a, "SetEdit").text = formatValue(a[1]);
  return {};
}

Value removeEdit(Machine& m, Args& a) {
  EditBox& e = editNamed(m, a, "RemoveEdit");
  auto& list = m.controls.edits;
  list.erase(list.begin() + (&e - list.data()));
  return {};
}

}  // namespace

void appendInputBuiltins(std::vector<Builtin>& t) {
  t.insert(t.end(), {
      {"getKey", K::Command, "input", "&key", getKey, 0,
       "code of the key held down now, 0 if none (letters lower-case unless Shift; 0 for the "
       "extended keys getKeyE reads)"},
      {"getKeyE", K::Command, "input", "&key", getKeyE, 0,
       "like getKey, and extended keys too: arrows, F1..F12, ... with codes above 255 (kc_Up, ...)"},
      {"waitKey", K::Command, "input", "[prompt,] &key", waitKey, 0,
       "waits for a key and stores its code (at once if one is held); prints the prompt like "
       "print without a line end"},
      {"keyDown", K::Function, "input", "code", keyDown, 0,
       "1 if the key with that code (kc_Up, ascii(\"a\"), ...) is held down now, else 0"},
      {"readMouse", K::Command, "input", "&x, &y [, &button]", readMouse, 0,
       "the mouse pointer in screen pixels and its buttons: 0 none, 1 left, 2 right, 4 middle "
       "(added when several are held)"},
      {"waitClick", K::Command, "input", "&x, &y [, &button]", waitClick, 0,
       "waits for a mouse button to go down (a click made while the program was busy counts), "
       "then reads like readMouse"},
      {"MsgBox", K::Command, "input", "text [, title]", msgBox, 0,
       "shows a message box and waits until it is answered with OK; text may be an array of "
       "lines"},
      {"MsgBox", K::Function, "input", "text [, title]", msgBox, 0,
       "shows a message box like the MsgBox command and returns the button that closed it "
       "(1: OK)"},
      {"AddButton", K::Command, "input", "name, x, y [, width [, height]]", addButton, 0,
       "adds a push button labelled name at (x, y) in screen pixels (the same name again moves it)"},
      {"GetButton", K::Command, "input", "&name", getButton, 0,
       "the name of the last button pressed, \"\" if none; reading it clears it"},
      {"LastButton", K::Function, "input", "", lastButton, 0,
       "the name of the last button pressed, \"\" if none; reading it clears it"},
      {"RemoveButton", K::Command, "input", "name", removeButton, 0, "removes the button"},
      {"AddEdit", K::Command, "input", "name, x, y, width [, text]", addEdit, 0,
       "adds a one-line text box at (x, y) in screen pixels, holding text (\"\" by default)"},
      {"GetEdit", K::Function, "input", "name", getEdit, 0, "the text in the edit box"},
      {"SetEdit", K::Command, "input", "name, text", setEdit, 0, "replaces the text in the edit box"},
      {"RemoveEdit", K::Command, "input", "name", removeEdit, 0, "removes the edit box"},

      // ---- key codes (core/input/input.h)
      {"kc_Enter", K::Constant, "key codes", "", nullptr, keys::kEnter, "Enter key (13)"},
      {"kc_Esc", K::Constant, "key codes", "", nullptr, keys::kEsc, "Esc key (27)"},
      {"kc_Space", K::Constant, "key codes", "", nullptr, keys::kSpace, "space bar (32)"},
      {"kc_Tab", K::Constant, "key codes", "", nullptr, keys::kTab, "Tab key (9)"},
      {"kc_BackSpace", K::Constant, "key codes", "", nullptr, keys::kBackspace, "Backspace key (8)"},
      {"kc_Up", K::Constant, "key codes", "", nullptr, keys::kUp, "up arrow (294)"},
      {"kc_Down", K::Constant, "key codes", "", nullptr, keys::kDown, "down arrow (296)"},
      {"kc_Left", K::Constant, "key codes", "", nullptr, keys::kLeft, "left arrow (293)"},
      {"kc_Right", K::Constant, "key codes", "", nullptr, keys::kRight, "right arrow (295)"},
      {"kc_PgUp", K::Constant, "key codes", "", nullptr, keys::kPageUp, "Page Up (289)"},
      {"kc_PgDn", K::Constant, "key codes", "", nullptr, keys::kPageDown, "Page Down (290)"},
      {"kc_End", K::Constant, "key codes", "", nullptr, keys::kEnd, "End (291)"},
      {"kc_Home", K::Constant, "key codes", "", nullptr, keys::kHome, "Home (292)"},
      {"kc_Insert", K::Constant, "key codes", "", nullptr, keys::kInsert, "Insert (301)"},
      {"kc_Delete", K::Constant, "key codes", "", nullptr, keys::kDelete, "Delete (302)"},
      {"kc_F1", K::Constant, "key codes", "", nullptr, keys::kF1, "F1 (368)"},
      {"kc_F2", K::Constant, "key codes", "", nullptr, keys::kF1 + 1, "F2 (369)"},
      {"kc_F3", K::Constant, "key codes", "", nullptr, keys::kF1 + 2, "F3 (370)"},
      {"kc_F4", K::Constant, "key codes", "", nullptr, keys::kF1 + 3, "F4 (371)"},
      {"kc_F5", K::Constant, "key codes", "", nullptr, keys::kF1 + 4, "F5 (372)"},
      {"kc_F6", K::Constant, "key codes", "", nullptr, keys::kF1 + 5, "F6 (373)"},
      {"kc_F7", K::Constant, "key codes", "", nullptr, keys::kF1 + 6, "F7 (374)"},
      {"kc_F8", K::Constant, "key codes", "", nullptr, keys::kF1 + 7, "F8 (375)"},
      {"kc_F9", K::Constant, "key codes", "", nullptr, keys::kF1 + 8, "F9 (376)"},
      {"kc_F10", K::Constant, "key codes", "", nullptr, keys::kF1 + 9, "F10 (377)"},
      {"kc_F11", K::Constant, "key codes", "", nullptr, keys::kF1 + 10, "F11 (378)"},
      {"kc_F12", K::Constant, "key codes", "", nullptr, keys::kF1 + 11, "F12 (379)"},
  });
}

}  // namespace rb::builtins
