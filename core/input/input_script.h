#pragma once
// Scripted input for headless runs: the --events file format and --keys text, and the player
// that feeds them to a program on the run's virtual clock. docs/interaction.md describes the
// format and the rules below for users.
//
// The player's rules, in short. A script is a list of steps taken in order. A step that the
// program must notice (a key, a click, a button press, a message box answer, an input line)
// stays current until a read of its kind has seen it; the next read of any kind then ends it
// (a tap's key or button goes up) and makes the following step current. A `wait` step ends when
// its virtual time has passed. Every read moves the virtual clock by kReadMs, so a program that
// polls sees time pass. A blocking read (waitKey, waitClick, MsgBox, input) takes steps until
// one satisfies it, jumping the clock over waits; a step of another kind stops the run with an
// error, since the program cannot read it while it waits. When nothing is left, a blocking read
// is a runtime error, and a program that keeps polling is stopped once it has polled kStallReads
// times over kStallMs of virtual time without the script moving on.
//
// What the steps do follows the input rules every source of input shares (input_rules.h): a
// click on one of the program's buttons presses it, a click on an edit box gives it the keys
// that follow until enter, tab or esc, a left click or enter, esc or space answers a message
// box, and keys typed at an input prompt make its line.

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "base/runtime_error.h"
#include "input/input.h"
#include "input/input_rules.h"

namespace rb {

/// One step of a script.
struct ScriptStep {
  enum Kind : uint8_t {
    Key,      ///< key K: a tap
    Hold,     ///< hold K MS: K down for MS virtual milliseconds
    Press,    ///< press K: K goes down and stays down
    Release,  ///< release: every key goes up
    Mouse,    ///< mouse X Y [BUTTONS]: the pointer moves, with these buttons held
    Click,    ///< click X Y [BUTTON]: a button goes down at (X, Y), then up
    Button,   ///< button NAME: the program's button NAME is pressed
    Edit,     ///< edit NAME TEXT: TEXT is typed into the edit box NAME
    MsgBox,   ///< msgbox [ok]: the message box is answered
    Input,    ///< input TEXT: a line for `input`
    Wait,     ///< wait MS: nothing happens for MS virtual milliseconds
  };
  Kind kind = Key;
  int64_t key = 0;   ///< Key, Hold, Press
  double ms = 0;     ///< Hold, Wait
  MouseState mouse;  ///< Mouse, Click
  std::string name;  ///< Button, Edit
  std::string text;  ///< Edit, Input
  int line = 0;      ///< its line in the events file; 0 when it came from --keys
};

/// The most steps a script holds (a key of `keys` text is one): far more than a program's test
/// needs, and a bound on the memory an events file takes (about 100 bytes a step).
constexpr size_t kMaxScriptSteps = 100'000;

/// A malformed script; `line` is 0 for --keys text.
class ScriptError : public std::runtime_error {
 public:
  ScriptError(int atLine, const std::string& message) : std::runtime_error(message), line(atLine) {}
  int line;
};

/// Parses an events file (one step per line, `#` comments). Throws ScriptError.
std::vector<ScriptStep> parseEventScript(std::string_view text);
/// Parses --keys text: one tap per character, `{name}` for a named key, `{STEP}` for any events
/// line (`{wait 500}`), `{{` for a literal `{`. `line` is recorded in the steps. Throws
/// ScriptError.
std::vector<ScriptStep> parseKeyText(std::string_view keys, int line = 0);
/// A step as the events format writes it ("click 100 200 left").
std::string describeStep(const ScriptStep& step);

/// A parsed script and where it came from, for messages.
struct InputScript {
  std::vector<ScriptStep> steps;
  bool given = false;      ///< false: the run has no scripted input at all
  std::string origin;      ///< "the --events script", "the --keys text", ...
  std::string eventsFile;  ///< the events file's name, for "events.txt line 4"
};

/// Plays a script to a program. Each method is one read of one kind of input; `who` names the
/// built-in for messages. Errors are RuntimeErrors, which stop the program.
class ScriptedInput {
 public:
  static constexpr double kReadMs = 1;           ///< virtual time each read takes
  static constexpr double kStallMs = 60000;      ///< polling without progress for this long...
  static constexpr uint64_t kStallReads = 1000;  ///< ...and this many reads stops the run

  /// `clockMs` is the run's virtual clock: reads move it, blocking reads jump it over waits.
  ScriptedInput(InputScript script, double& clockMs);

  bool given() const { return script_.given; }
  /// The program's buttons and edit boxes, which clicks and typed keys may reach (nullptr: none).
  void useControls(Controls* controls) { controls_ = controls; }
  int64_t heldKey(std::string_view who);
  int64_t waitKey(std::string_view who);
  MouseState mouse(std::string_view who);
  MouseState waitClick(std::string_view who);
  void updateControls(Controls& controls, std::string_view who);
  void messageBox(std::string_view who);
  /// nullopt: the script typed Ctrl-D on an empty line (the end of input).
  std::optional<std::string> inputLine(std::string_view who);

  /// True when every step has been taken.
  bool exhausted() const { return next_ >= script_.steps.size(); }

 private:
  enum class Device : uint8_t { Keyboard, Mouse, Controls, MessageBox, Line };
  static Device deviceOf(ScriptStep::Kind kind);

  /// Takes the steps a read of `device` reaches (see the rules at the top of this file).
  /// `controls` is given by reads of the program's controls only.
  void settle(Device device, Controls* controls, std::string_view who);
  void apply(const ScriptStep& s);
  void finish();
  void progressed();
  /// A read that does not block: stops the run when the program polls without progress.
  void checkStall(std::string_view who, std::string_view what);
  /// A blocking read found nothing more, or a step it cannot take.
  [[noreturn]] void exhaustedError(std::string_view who) const;
  [[noreturn]] void mismatchError(std::string_view who, std::string_view wanted) const;
  std::string where(const ScriptStep& s) const;
  /// The current step's wait ends: the clock jumps to its end.
  void jumpOverWait();

  InputScript script_;
  double& clock_;
  Controls* controls_ = nullptr;
  InputRules rules_;
  bool modal_ = false;    ///< a message box or an input prompt is up: controls take nothing
  bool absorbed_ = false; ///< the current step went to a button or an edit box
  size_t next_ = 0;       ///< the current step
  bool applied_ = false;  ///< the current step has taken effect
  bool seen_ = false;     ///< a read of its kind has seen it
  double appliedAt_ = 0;
  int64_t key_ = 0;  ///< the key held down now
  MouseState mouse_;
  uint64_t presses_ = 0;       ///< mouse buttons that went down so far
  uint64_t pressesTaken_ = 0;  ///< presses_ when waitClick last returned
  double quietSince_ = 0;      ///< virtual time of the last progress
  uint64_t quietReads_ = 0;    ///< reads since the last progress
};

}  // namespace rb
