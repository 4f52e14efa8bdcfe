#include "input/input_script.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace rb {

// ---- parsing

namespace {

std::string lowerCase(std::string_view s) {
  std::string r(s);
  for (char& c : r) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return r;
}

bool isSpace(char c) { return c == ' ' || c == '\t'; }

/// The code of a token that is exactly one character: ASCII, or a UTF-8 character up to U+00FF
/// (read as its Latin-1 code, as Windows reports such keys).
std::optional<int64_t> singleCharacter(std::string_view t) {
  if (t.size() == 1) return static_cast<unsigned char>(t[0]);
  if (t.size() == 2) {
    auto b0 = static_cast<unsigned char>(t[0]), b1 = static_cast<unsigned char>(t[1]);
    if ((b0 == 0xC2 || b0 == 0xC3) && (b1 & 0xC0) == 0x80) return ((b0 & 0x1F) << 6) | (b1 & 0x3F);
  }
  return std::nullopt;
}

/// The words of one events line. A word is a run of non-blank characters or a "quoted" string.
class LineReader {
 public:
  LineReader(std::string_view text, int line) : text_(text), line_(line) {}

  bool atEnd() {
    skipBlanks();
    return pos_ >= text_.size();
  }

  std::string word(std::string_view what) {
    skipBlanks();
    if (pos_ >= text_.size()) fail("expected " + std::string(what));
    if (text_[pos_] == '"') {
      size_t close = text_.find('"', pos_ + 1);
      if (close == std::string_view::npos) fail("missing closing \" in " + std::string(what));
      std::string w(text_.substr(pos_ + 1, close - pos_ - 1));
      pos_ = close + 1;
      return w;
    }
    size_t start = pos_;
    while (pos_ < text_.size() && !isSpace(text_[pos_])) ++pos_;
    return std::string(text_.substr(start, pos_ - start));
  }

  /// The rest of the line without surrounding blanks; quotes around all of it are removed.
  std::string rest() {
    skipBlanks();
    std::string_view r = text_.substr(std::min(pos_, text_.size()));
    pos_ = text_.size();
    while (!r.empty() && isSpace(r.back())) r.remove_suffix(1);
    if (r.size() >= 2 && r.front() == '"' && r.back() == '"') r = r.substr(1, r.size() - 2);
    return std::string(r);
  }

  double number(std::string_view what, bool allowNegative) {
    std::string w = word(what);
    double v = 0;
    auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), v);
    if (ec != std::errc() || end != w.data() + w.size() || !std::isfinite(v) ||
        (!allowNegative && v < 0))
      fail("expected " + std::string(what) + ", not '" + w + "'");
    return v;
  }

  int pixel(std::string_view what) {
    double v = number(what, true);
    if (v != std::floor(v) || std::abs(v) > 1e6)
      fail(std::string(what) + " must be a whole number of pixels");
    return static_cast<int>(v);
  }

  void end(std::string_view command) {
    if (!atEnd()) fail("unexpected '" + word("") + "' after " + std::string(command));
  }

  [[noreturn]] void fail(const std::string& message) const { throw ScriptError(line_, message); }
  int line() const { return line_; }

 private:
  void skipBlanks() {
    while (pos_ < text_.size() && isSpace(text_[pos_])) ++pos_;
  }

  std::string_view text_;
  size_t pos_ = 0;
  int line_;
};

int64_t keyToken(LineReader& r, std::string_view command) {
  std::string w = r.word("a key after " + std::string(command) +
                         " (one character, or a name such as up, enter, f1)");
  std::string_view name = w;
  if (name.size() > 2 && name.front() == '{' && name.back() == '}')
    name = name.substr(1, name.size() - 2);
  if (auto c = singleCharacter(name)) return *c;
  if (auto c = keyCodeByName(name)) return *c;
  r.fail("unknown key '" + w +
         "' (one character, or a name: up, down, left, right, enter, esc, "
         "space, tab, backspace, delete, insert, home, end, pgup, pgdn, f1 to f12)");
}

int buttonsToken(LineReader& r, const std::string& w) {
  int bits = 0;
  size_t start = 0;
  std::string lower = lowerCase(w);
  if (lower == "none") return 0;
  while (start <= lower.size()) {
    size_t plus = lower.find('+', start);
    std::string part =
        lower.substr(start, plus == std::string::npos ? std::string::npos : plus - start);
    if (part == "left") bits |= mouse::kLeft;
    else if (part == "right") bits |= mouse::kRight;
    else if (part == "middle") bits |= mouse::kMiddle;
    else
      r.fail("unknown mouse button '" + w +
             "' (left, right, middle, none, or a sum like left+right)");
    if (plus == std::string::npos) break;
    start = plus + 1;
  }
  return bits;
}

/// The line without its comment: a # at the start of a word, outside quotes, to the line's end.
std::string_view withoutComment(std::string_view text) {
  bool quoted = false;
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '"') quoted = !quoted;
    if (text[i] == '#' && !quoted && (i == 0 || isSpace(text[i - 1]))) return text.substr(0, i);
  }
  return text;
}

[[noreturn]] void tooManySteps(int line) {
  throw ScriptError(line, "more than " + std::to_string(kMaxScriptSteps) + " steps: a script holds at most that many");
}

void parseLine(std::string_view text, int line, std::vector<ScriptStep>& out) {
  text = withoutComment(text);
  if (text.find_first_not_of(" \t") == std::string_view::npos) return;
  LineReader r(text, line);
  std::string command = lowerCase(r.word("an event"));
  ScriptStep s;
  s.line = line;
  if (command == "key" || command == "press") {
    s.kind = command == "key" ? ScriptStep::Key : ScriptStep::Press;
    s.key = keyToken(r, command);
    r.end(command);
  } else if (command == "hold") {
    s.kind = ScriptStep::Hold;
    s.key = keyToken(r, command);
    s.ms = r.number("a duration in milliseconds after the key", false);
    r.end(command);
  } else if (command == "release") {
    s.kind = ScriptStep::Release;
    r.end(command);
  } else if (command == "keys") {
    for (ScriptStep& k : parseKeyText(r.rest(), line)) out.push_back(std::move(k));
    return;
  } else if (command == "mouse" || command == "click") {
    s.kind = command == "mouse" ? ScriptStep::Mouse : ScriptStep::Click;
    s.mouse.x = r.pixel("x");
    s.mouse.y = r.pixel("y");
    if (!r.atEnd()) s.mouse.buttons = buttonsToken(r, r.word("a mouse button"));
    else if (s.kind == ScriptStep::Click) s.mouse.buttons = mouse::kLeft;
    if (s.kind == ScriptStep::Click && s.mouse.buttons == 0)
      r.fail("click: which button? (left, right or middle)");
    r.end(command);
  } else if (command == "button") {
    s.kind = ScriptStep::Button;
    s.name = r.rest();
    if (s.name.empty()) r.fail("button: expected the name of the program's button");
  } else if (command == "edit") {
    s.kind = ScriptStep::Edit;
    s.name = r.word("the name of the program's edit box");
    s.text = r.rest();
  } else if (command == "msgbox") {
    s.kind = ScriptStep::MsgBox;
    if (!r.atEnd() && lowerCase(r.word("")) != "ok") r.fail("msgbox: the only answer is ok");
    r.end(command);
  } else if (command == "input") {
    s.kind = ScriptStep::Input;
    s.text = r.rest();
  } else if (command == "wait") {
    s.kind = ScriptStep::Wait;
    s.ms = r.number("a duration in milliseconds", false);
    r.end(command);
  } else {
    r.fail("unknown event '" + command +
           "' (expected key, hold, press, release, keys, mouse, click, button, edit, msgbox, "
           "input or wait)");
  }
  out.push_back(std::move(s));
}

std::string fmtMs(double ms) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", ms);
  return buf;
}

std::string buttonsText(int bits) {
  std::string s;
  for (auto [bit, name] :
       {std::pair{mouse::kLeft, "left"}, {mouse::kRight, "right"}, {mouse::kMiddle, "middle"}}) {
    if (!(bits & bit)) continue;
    if (!s.empty()) s += '+';
    s += name;
  }
  return s;
}

}  // namespace

std::vector<ScriptStep> parseEventScript(std::string_view text) {
  std::vector<ScriptStep> steps;
  int line = 0;
  size_t pos = 0;
  while (pos <= text.size()) {
    size_t nl = text.find('\n', pos);
    std::string_view l =
        text.substr(pos, nl == std::string_view::npos ? std::string_view::npos : nl - pos);
    ++line;
    if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
    size_t first = l.find_first_not_of(" \t");
    if (first != std::string_view::npos) parseLine(l.substr(first), line, steps);
    if (steps.size() > kMaxScriptSteps) tooManySteps(line);
    if (nl == std::string_view::npos) break;
    pos = nl + 1;
  }
  return steps;
}

std::vector<ScriptStep> parseKeyText(std::string_view keys, int line) {
  std::vector<ScriptStep> steps;
  for (size_t i = 0; i < keys.size();) {
    ScriptStep s;
    s.line = line;
    if (keys[i] == '{' && i + 1 < keys.size() && keys[i + 1] == '{') {
      s.key = '{';
      i += 2;
    } else if (keys[i] == '{') {
      size_t close = keys.find('}', i);
      if (close == std::string_view::npos)
        throw ScriptError(line, "missing } after '" + std::string(keys.substr(i)) + "'");
      std::string_view inner = keys.substr(i + 1, close - i - 1);
      i = close + 1;
      if (auto code = keyCodeByName(inner)) {
        s.key = *code;
      } else {
        if (inner.find_first_not_of(" \t") == std::string_view::npos)
          throw ScriptError(line, "empty {} (write {{ for a {)");
        parseLine(inner, line, steps);
        continue;
      }
    } else {
      size_t len = 1;
      auto b0 = static_cast<unsigned char>(keys[i]);
      if (b0 >= 0x80) len = b0 >= 0xC0 && b0 < 0xE0 ? 2 : 0;
      auto code = len ? singleCharacter(keys.substr(i, len)) : std::nullopt;
      if (!code) throw ScriptError(line, "only characters up to U+00FF can be typed as keys");
      s.key = *code;
      i += len;
    }
    if (steps.size() >= kMaxScriptSteps) tooManySteps(line);
    steps.push_back(std::move(s));
  }
  return steps;
}

std::string describeStep(const ScriptStep& s) {
  switch (s.kind) {
    case ScriptStep::Key: return "key " + describeKey(s.key);
    case ScriptStep::Hold: return "hold " + describeKey(s.key) + " " + fmtMs(s.ms);
    case ScriptStep::Press: return "press " + describeKey(s.key);
    case ScriptStep::Release: return "release";
    case ScriptStep::Mouse:
    case ScriptStep::Click: {
      std::string t = s.kind == ScriptStep::Mouse ? "mouse " : "click ";
      t += std::to_string(s.mouse.x);
      t += ' ';
      t += std::to_string(s.mouse.y);
      if (s.mouse.buttons) {
        t += ' ';
        t += buttonsText(s.mouse.buttons);
      }
      return t;
    }
    case ScriptStep::Button: return "button " + s.name;
    case ScriptStep::Edit: return "edit " + s.name + " " + s.text;
    case ScriptStep::MsgBox: return "msgbox ok";
    case ScriptStep::Input: return "input " + s.text;
    case ScriptStep::Wait: return "wait " + fmtMs(s.ms);
  }
  return "?";
}

// ---- playing

ScriptedInput::ScriptedInput(InputScript script, double& clockMs)
    : script_(std::move(script)), clock_(clockMs), quietSince_(clockMs) {}

ScriptedInput::Device ScriptedInput::deviceOf(ScriptStep::Kind kind) {
  switch (kind) {
    case ScriptStep::Mouse:
    case ScriptStep::Click: return Device::Mouse;
    case ScriptStep::Button:
    case ScriptStep::Edit: return Device::Controls;
    case ScriptStep::MsgBox: return Device::MessageBox;
    case ScriptStep::Input: return Device::Line;
    default: return Device::Keyboard;  // keys, and Wait, which no read sees
  }
}

void ScriptedInput::progressed() {
  quietSince_ = clock_;
  quietReads_ = 0;
}

void ScriptedInput::apply(const ScriptStep& s) {
  absorbed_ = false;
  switch (s.kind) {
    case ScriptStep::Key:
    case ScriptStep::Hold:
    case ScriptStep::Press:
      // An edit box that has the keyboard takes the key: the program's keyboard never sees it.
      if (!modal_ && controls_ && rules_.typeInto(*controls_, s.key)) absorbed_ = true;
      else key_ = s.key;
      break;
    case ScriptStep::Release: key_ = 0; break;
    case ScriptStep::Mouse:
    case ScriptStep::Click: {
      int pressed = s.mouse.buttons & ~mouse_.buttons;
      if (modal_ && s.kind == ScriptStep::Click) break;  // it answers the box (messageBox())
      // A press on a button or an edit box goes to it, not to the program's mouse reads.
      if (pressed && !modal_ && controls_ &&
          rules_.press(*controls_, s.mouse.x, s.mouse.y) != InputRules::Target::Program) {
        absorbed_ = true;
        break;
      }
      if (pressed) ++presses_;
      mouse_ = s.mouse;
      break;
    }
    default: break;  // the rest take effect when a read of their kind sees them
  }
  applied_ = true;
  seen_ = false;
  appliedAt_ = clock_;
  progressed();
}

void ScriptedInput::finish() {
  ++next_;
  applied_ = false;
  absorbed_ = false;
  seen_ = false;
  progressed();
}

void ScriptedInput::settle(Device device, Controls* controls, std::string_view who) {
  while (!exhausted()) {
    const ScriptStep& s = script_.steps[next_];
    if (!applied_) apply(s);
    if (absorbed_) {  // taken by a button or an edit box: nothing more for a read to see
      finish();
      continue;
    }
    if (s.kind == ScriptStep::Wait) {
      if (clock_ < appliedAt_ + s.ms) return;
      finish();
      continue;
    }
    Device own = deviceOf(s.kind);
    if (!seen_) {
      if (own != device) return;  // it waits for a read of its kind
      if (s.kind == ScriptStep::Button) {
        Button* b = controls->button(s.name);
        if (!b)
          throw RuntimeError(std::string(who) + ": " + script_.origin + " presses button '" +
                             s.name + "' (" + where(s) +
                             "), but the program has no button of that name "
                             "(its buttons: " +
                             controls->buttonNames() + ")");
        controls->pressed = b->name;
      } else if (s.kind == ScriptStep::Edit) {
        EditBox* e = controls->edit(s.name);
        if (!e)
          throw RuntimeError(std::string(who) + ": " + script_.origin + " types into edit box '" +
                             s.name + "' (" + where(s) +
                             "), but the program has no edit box of that name");
        e->text = s.text;
        finish();  // typing is lasting state: there is nothing more to see
        continue;
      }
      seen_ = true;
      progressed();
      return;
    }
    // Seen by an earlier read: this read ends it (a held key only once its time is up).
    if (s.kind == ScriptStep::Hold && clock_ < appliedAt_ + s.ms) return;
    bool tap =
        s.kind == ScriptStep::Key || s.kind == ScriptStep::Hold || s.kind == ScriptStep::Click;
    if (tap) {
      if (own == Device::Keyboard) key_ = 0;
      else mouse_.buttons = 0;
    }
    finish();
    if (tap && own == device) return;  // this read sees the key or the button go up
  }
}

std::string ScriptedInput::where(const ScriptStep& s) const {
  if (s.line == 0) return "from --keys";
  return (script_.eventsFile.empty() ? "line " : script_.eventsFile + " line ") +
         std::to_string(s.line);
}

void ScriptedInput::checkStall(std::string_view who, std::string_view what) {
  bool stuck = exhausted() || (applied_ && !seen_ && script_.steps[next_].kind != ScriptStep::Wait);
  if (!stuck) return;
  ++quietReads_;
  if (quietReads_ < kStallReads || clock_ - quietSince_ < kStallMs) return;
  std::string polled =
      "the program kept polling for " + fmtMs(kStallMs / 1000) + " s of virtual time";
  if (!script_.given)
    throw RuntimeError(std::string(who) +
                       ": no input (this headless run has no scripted input, and " + polled +
                       "; give keys and clicks with --keys or --events)");
  if (exhausted())
    throw RuntimeError(std::string(who) + ": no more scripted input (" + script_.origin +
                       " is exhausted, and " + polled + ")");
  const ScriptStep& s = script_.steps[next_];
  static const char* const kReads[] = {"the keyboard", "the mouse", "its buttons or edit boxes",
                                       "a message box", "a line of input"};
  throw RuntimeError(std::string(who) + ": " + script_.origin + " is stuck at '" + describeStep(s) +
                     "' (" + where(s) + "): " + polled + " without reading " +
                     kReads[static_cast<int>(deviceOf(s.kind))] + " (it read " + std::string(what) +
                     ")");
}

void ScriptedInput::exhaustedError(std::string_view who) const {
  if (!script_.given)
    throw RuntimeError(std::string(who) +
                       ": no scripted input to wait for (a headless run takes keys, clicks and "
                       "dialog answers only from --keys or --events)");
  throw RuntimeError(std::string(who) + ": no more scripted input (" + script_.origin +
                     " is exhausted)");
}

void ScriptedInput::mismatchError(std::string_view who, std::string_view wanted) const {
  const ScriptStep& s = script_.steps[next_];
  throw RuntimeError(std::string(who) + ": waiting for " + std::string(wanted) +
                     ", but the next scripted event is '" + describeStep(s) + "' (" + where(s) +
                     ")");
}

void ScriptedInput::jumpOverWait() {
  clock_ = std::max(clock_, appliedAt_ + script_.steps[next_].ms);
}

int64_t ScriptedInput::heldKey(std::string_view who) {
  clock_ += kReadMs;
  settle(Device::Keyboard, nullptr, who);
  checkStall(who, "the keyboard");
  return key_;
}

int64_t ScriptedInput::waitKey(std::string_view who) {
  clock_ += kReadMs;
  for (;;) {
    settle(Device::Keyboard, nullptr, who);
    if (key_ != 0) {
      checkStall(who, "the keyboard");  // a key left down forever must not loop forever
      return key_;
    }
    if (exhausted()) exhaustedError(who);
    const ScriptStep& s = script_.steps[next_];
    if (s.kind == ScriptStep::Wait) jumpOverWait();
    else if (deviceOf(s.kind) != Device::Keyboard) mismatchError(who, "a key");
    // else a release, or a tap that just went up: go on to the next step
  }
}

MouseState ScriptedInput::mouse(std::string_view who) {
  clock_ += kReadMs;
  settle(Device::Mouse, nullptr, who);
  checkStall(who, "the mouse");
  return mouse_;
}

MouseState ScriptedInput::waitClick(std::string_view who) {
  clock_ += kReadMs;
  for (;;) {
    settle(Device::Mouse, nullptr, who);
    // A button that went down since the last waitClick returned (a held one does not repeat).
    if (presses_ != pressesTaken_ && mouse_.buttons != 0) {
      pressesTaken_ = presses_;
      return mouse_;
    }
    if (exhausted()) exhaustedError(who);
    const ScriptStep& s = script_.steps[next_];
    if (s.kind == ScriptStep::Wait) jumpOverWait();
    else if (deviceOf(s.kind) != Device::Mouse) mismatchError(who, "a mouse click");
  }
}

void ScriptedInput::updateControls(Controls& controls, std::string_view who) {
  clock_ += kReadMs;
  settle(Device::Controls, &controls, who);
  checkStall(who, "its buttons and edit boxes");
}

namespace {
/// Sets a flag for the time of a call, also when it ends by an exception.
class Raised {
 public:
  explicit Raised(bool& flag) : flag_(flag) { flag_ = true; }
  ~Raised() { flag_ = false; }
  Raised(const Raised&) = delete;
  Raised& operator=(const Raised&) = delete;

 private:
  bool& flag_;
};
}  // namespace

void ScriptedInput::messageBox(std::string_view who) {
  clock_ += kReadMs;
  Raised modal(modal_);
  for (;;) {
    settle(Device::MessageBox, nullptr, who);
    if (exhausted()) exhaustedError(who);
    const ScriptStep& s = script_.steps[next_];
    if (s.kind == ScriptStep::MsgBox && seen_) {
      finish();
      return;
    }
    bool answer = (s.kind == ScriptStep::Key && InputRules::answersMessageBox(s.key)) ||
                  (s.kind == ScriptStep::Click && InputRules::clickAnswersMessageBox(s.mouse.buttons));
    if (answer) {
      key_ = 0;  // the dialog takes the key or the click: the program never sees it
      finish();
      return;
    }
    if (s.kind == ScriptStep::Wait) jumpOverWait();
    else if (s.kind == ScriptStep::Release) finish();
    else
      mismatchError(who,
                    "an answer to the message box (msgbox, a left click, or the key enter, esc or "
                    "space)");
  }
}

std::optional<std::string> ScriptedInput::inputLine(std::string_view who) {
  clock_ += kReadMs;
  Raised modal(modal_);
  std::string typed;
  for (;;) {
    settle(Device::Line, nullptr, who);
    if (exhausted()) exhaustedError(who);
    const ScriptStep& s = script_.steps[next_];
    if (s.kind == ScriptStep::Input && seen_) {
      finish();
      return typed + s.text;
    }
    if (s.kind == ScriptStep::Key || s.kind == ScriptStep::Hold || s.kind == ScriptStep::Press) {
      // Keys typed at an input prompt make up the line; enter ends it.
      key_ = 0;
      finish();
      switch (InputRules::editLine(typed, s.key)) {
        case InputRules::LineKey::Done: return typed;
        case InputRules::LineKey::EndOfInput: return std::nullopt;
        default: break;
      }
      continue;
    }
    if (s.kind == ScriptStep::Wait) jumpOverWait();
    else if (s.kind == ScriptStep::Release) finish();
    else mismatchError(who, "a line of input (input TEXT, or keys ending with {enter})");
  }
}

}  // namespace rb
