#include "input/input_script.h"

#include <catch2/catch.hpp>
#include <functional>

#include "machine/test_support.h"

using namespace rb;

namespace {

InputScript script(std::string_view events) {
  InputScript s;
  s.given = true;
  s.origin = "the --events script";
  s.eventsFile = "ev.txt";
  s.steps = parseEventScript(events);
  return s;
}

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const RuntimeError& e) {
    return e.what();
  }
  return "";
}

/// A test host whose keyboard, mouse and dialogs play a script on its clock.
class ScriptHost : public test::TestHost {
 public:
  explicit ScriptHost(InputScript s) : player(std::move(s), clock) {}
  int64_t heldKey(std::string_view who) override { return player.heldKey(who); }
  int64_t waitKey(std::string_view who) override { return player.waitKey(who); }
  MouseState mouse(std::string_view who) override { return player.mouse(who); }
  MouseState waitClick(std::string_view who) override { return player.waitClick(who); }
  void updateControls(Controls& c, std::string_view who) override { player.updateControls(c, who); }
  void messageBox(std::string_view text, std::string_view title) override {
    boxes += std::string(title) + ": " + std::string(text) + "\n";
    player.messageBox("MsgBox");
  }
  std::optional<std::string> inputLine(std::string_view prompt) override {
    out += prompt;
    return player.inputLine("input");
  }
  ScriptedInput player;
  std::string boxes;
};

struct Run {
  std::string out, error, boxes;
};

/// Runs a program with scripted input in-process.
Run runWith(const std::string& program, std::string_view events) {
  DiagnosticList diags;
  test::MemoryReader reader;
  reader.files["test.bas"] = program;
  auto loaded = loadProgram("test.bas", program, reader, standardBuiltins(), {}, diags);
  auto compiled = compileProgram(*loaded, {}, diags);
  Run r;
  if (!compiled) {
    for (const Diagnostic& d : diags.all()) r.error += formatDiagnostic(loaded->sources, d);
    return r;
  }
  ScriptHost host(script(events));
  Machine machine(host, 1);
  host.player.useControls(&machine.controls);
  Interpreter interp(*compiled, machine);
  RunResult result = interp.run({});
  r.out = host.out;
  r.boxes = host.boxes;
  if (result.error) r.error = result.error->message;
  return r;
}

}  // namespace

TEST_CASE("the events format: every step", "[input]") {
  auto steps = parseEventScript(
      "# a comment\n"
      "\n"
      "key h\n"
      "  key {up}\r\n"
      "key F5\n"
      "hold w 250\n"
      "press H\n"
      "release\n"
      "mouse 10 20\n"
      "mouse 10 20 left+right\n"
      "click 5 6\n"
      "click 5 6 right\n"
      "button Start game\n"
      "edit Name  Bob Smith \n"
      "edit \"Full name\" \"  padded \"\n"
      "msgbox ok\n"
      "input 42\n"
      "wait 1.5\n"
      "keys a{enter}  # a comment after a step\n"
      "key \"#\"\n");
  REQUIRE(steps.size() == 19);
  CHECK(steps[0].kind == ScriptStep::Key);
  CHECK(steps[0].key == 'h');
  CHECK(steps[0].line == 3);
  CHECK(steps[1].key == keys::kUp);
  CHECK(steps[2].key == keys::kF1 + 4);
  CHECK(steps[3].kind == ScriptStep::Hold);
  CHECK(steps[3].ms == 250);
  CHECK(steps[4].kind == ScriptStep::Press);
  CHECK(steps[4].key == 'H');
  CHECK(steps[5].kind == ScriptStep::Release);
  CHECK(steps[6].mouse.buttons == 0);
  CHECK(steps[7].mouse.buttons == (mouse::kLeft | mouse::kRight));
  CHECK(steps[8].kind == ScriptStep::Click);
  CHECK(steps[8].mouse.buttons == mouse::kLeft);
  CHECK(steps[9].mouse.buttons == mouse::kRight);
  CHECK(steps[10].name == "Start game");
  CHECK(steps[11].name == "Name");
  CHECK(steps[11].text == "Bob Smith");
  CHECK(steps[12].name == "Full name");
  CHECK(steps[12].text == "  padded ");
  CHECK(steps[13].kind == ScriptStep::MsgBox);
  CHECK(steps[14].text == "42");
  CHECK(steps[15].ms == 1.5);
  CHECK(steps[16].key == 'a');
  CHECK(steps[17].key == keys::kEnter);
  CHECK(steps[17].line == 19);
  CHECK(steps[18].key == '#');
  CHECK(describeStep(steps[7]) == "mouse 10 20 left+right");
  CHECK(describeStep(steps[3]) == "hold w 250");
  CHECK(describeStep(steps[1]) == "key up");
}

TEST_CASE("the events format: errors name the line", "[input]") {
  auto lineOf = [](std::string_view text) {
    try {
      parseEventScript(text);
    } catch (const ScriptError& e) {
      return std::to_string(e.line) + ": " + e.what();
    }
    return std::string("no error");
  };
  CHECK(lineOf("key h\njump 3\n").rfind("2: unknown event 'jump'", 0) == 0);
  CHECK(lineOf("key hello").rfind("1: unknown key 'hello'", 0) == 0);
  CHECK(lineOf("key").rfind("1: expected a key", 0) == 0);
  CHECK(lineOf("hold w").rfind("1: expected a duration", 0) == 0);
  CHECK(lineOf("wait -5").rfind("1: expected a duration in milliseconds, not '-5'", 0) == 0);
  CHECK(lineOf("mouse 1.5 2").rfind("1: x must be a whole number", 0) == 0);
  CHECK(lineOf("click 1 2 thumb").rfind("1: unknown mouse button 'thumb'", 0) == 0);
  CHECK(lineOf("click 1 2 none").rfind("1: click: which button?", 0) == 0);
  CHECK(lineOf("key h h").rfind("1: unexpected 'h' after key", 0) == 0);
  CHECK(lineOf("msgbox cancel").rfind("1: msgbox: the only answer is ok", 0) == 0);
  CHECK(lineOf("button").rfind("1: button: expected the name", 0) == 0);
  // A script holds at most kMaxScriptSteps steps, on one `keys` line or over many lines.
  CHECK(lineOf("wait 1\nkeys " + std::string(kMaxScriptSteps + 1, 'a')).rfind("2: more than 100000 steps", 0) == 0);
  CHECK(parseEventScript("keys " + std::string(kMaxScriptSteps, 'a')).size() == kMaxScriptSteps);
  std::string lines;
  for (size_t i = 0; i <= kMaxScriptSteps; ++i) lines += "key a\n";
  CHECK(lineOf(lines).rfind("100001: more than 100000 steps", 0) == 0);
}

TEST_CASE("keys text: characters, named keys, steps in braces", "[input]") {
  auto steps = parseKeyText("hQ{up}{{}{wait 200}{Enter}");
  REQUIRE(steps.size() == 7);
  CHECK(steps[0].key == 'h');
  CHECK(steps[1].key == 'Q');
  CHECK(steps[2].key == keys::kUp);
  CHECK(steps[3].key == '{');
  CHECK(steps[4].key == '}');
  CHECK(steps[5].kind == ScriptStep::Wait);
  CHECK(steps[5].ms == 200);
  CHECK(steps[6].key == keys::kEnter);
  CHECK_THROWS_AS(parseKeyText("{up"), ScriptError);
  CHECK_THROWS_AS(parseKeyText("{}"), ScriptError);
  CHECK_THROWS_AS(parseKeyText("{fly 3}"), ScriptError);
  CHECK(parseKeyText("\xC3\xA9")[0].key == 0xE9);  // é, as its Latin-1 code
}

TEST_CASE("a tapped key is seen by one keyboard read, then goes up", "[input]") {
  double clock = 0;
  ScriptedInput in(script("key h\nkey h\nkey q\n"), clock);
  CHECK(in.heldKey("getKey") == 'h');
  CHECK(in.heldKey("getKey") == 0);  // released: a second tap of h is a new press
  CHECK(in.heldKey("getKey") == 'h');
  CHECK(in.heldKey("getKey") == 0);
  CHECK(in.heldKey("getKey") == 'q');
  CHECK(in.heldKey("getKey") == 0);
  CHECK(in.exhausted());
  CHECK(clock == 6);  // each read takes a virtual millisecond
}

TEST_CASE("waitKey takes one tap per call and jumps over waits", "[input]") {
  double clock = 0;
  ScriptedInput in(script("key a\nwait 500\nkey b\n"), clock);
  CHECK(in.waitKey("waitKey") == 'a');
  CHECK(in.waitKey("waitKey") == 'b');
  CHECK(clock >= 500);
  CHECK(errorOf([&] { in.waitKey("waitKey"); }) ==
        "waitKey: no more scripted input (the --events script is exhausted)");
}

TEST_CASE("a held key stays down for its virtual time", "[input]") {
  double clock = 0;
  ScriptedInput in(script("hold w 100\nkey q\n"), clock);
  int held = 0;
  while (in.heldKey("getKey") == 'w') ++held;
  CHECK(held == 100);
  CHECK(in.heldKey("getKey") == 'q');
  // waitKey returns at once while a key is held.
  double c2 = 0;
  ScriptedInput in2(script("hold w 10\n"), c2);
  CHECK(in2.waitKey("waitKey") == 'w');
  CHECK(in2.waitKey("waitKey") == 'w');
}

TEST_CASE("a step of one kind waits for a read of its kind", "[input]") {
  double clock = 0;
  ScriptedInput in(script("click 10 20\nkey q\n"), clock);
  CHECK(in.heldKey("getKey") == 0);  // the click is not a key: it waits for the mouse
  MouseState m = in.mouse("readMouse");
  CHECK(m.x == 10);
  CHECK(m.y == 20);
  CHECK(m.buttons == mouse::kLeft);
  CHECK(in.heldKey("getKey") == 'q');  // ends the click and takes the key
  CHECK(in.mouse("readMouse").buttons == 0);
}

TEST_CASE("mouse drags: the buttons stay down across moves", "[input]") {
  double clock = 0;
  ScriptedInput in(
      script("mouse 100 100 left\nmouse 200 100 left\nmouse 200 100\nclick 5 5 right\n"), clock);
  std::vector<int> seen;
  for (int i = 0; i < 5; ++i) {
    MouseState m = in.mouse("readMouse");
    seen.insert(seen.end(), {m.x, m.y, m.buttons});
  }
  CHECK(seen == std::vector<int>{100, 100, 1, 200, 100, 1, 200, 100, 0, 5, 5, 2, 5, 5, 0});
  CHECK(errorOf([&] { in.waitClick("waitClick"); }) ==
        "waitClick: no more scripted input (the --events script is exhausted)");
}

TEST_CASE("blocking reads stop on a step they cannot take", "[input]") {
  double clock = 0;
  ScriptedInput in(script("key a\nclick 1 2\n"), clock);
  CHECK(in.waitKey("waitKey") == 'a');
  CHECK(errorOf([&] { in.waitKey("waitKey"); }) ==
        "waitKey: waiting for a key, but the next scripted event is 'click 1 2 left' (ev.txt line "
        "2)");
}

TEST_CASE("a program that keeps polling after the script ends is stopped", "[input]") {
  double clock = 0;
  ScriptedInput in(script("key q\n"), clock);
  CHECK(in.heldKey("getKey") == 'q');
  std::string err = errorOf([&] {
    for (int i = 0; i < 200000; ++i) in.heldKey("getKey");
  });
  CHECK(err ==
        "getKey: no more scripted input (the --events script is exhausted, and the program kept "
        "polling for 60 s of virtual time)");
  CHECK(clock >= 60000);
  CHECK(clock < 60010);

  double c2 = 0;
  ScriptedInput none(InputScript{}, c2);
  err = errorOf([&] {
    for (int i = 0; i < 200000; ++i) none.mouse("readMouse");
  });
  CHECK(err.rfind("readMouse: no input (this headless run has no scripted input", 0) == 0);
  CHECK(errorOf([&] {
          none.waitKey("waitKey");
        }).rfind("waitKey: no scripted input to wait for", 0) == 0);
}

TEST_CASE("polling the wrong device is reported as a stuck script", "[input]") {
  double clock = 0;
  ScriptedInput in(script("click 3 4\n"), clock);
  std::string err = errorOf([&] {
    for (int i = 0; i < 200000; ++i) in.heldKey("getKey");
  });
  CHECK(err ==
        "getKey: the --events script is stuck at 'click 3 4 left' (ev.txt line 1): the program "
        "kept polling for 60 s of virtual time without reading the mouse (it read the keyboard)");
}

TEST_CASE("a few slow polls are not a stall", "[input]") {
  double clock = 0;
  ScriptedInput in(script("key q\n"), clock);
  in.heldKey("getKey");
  for (int i = 0; i < 100; ++i) {
    clock += 10000;  // the program moves the robot slowly between reads
    CHECK(in.heldKey("getKey") == 0);
  }
}

TEST_CASE("buttons, edit boxes and message boxes", "[input]") {
  double clock = 0;
  ScriptedInput in(script("edit Name Bob\nbutton OK\nmsgbox\nkey {enter}\n"), clock);
  Controls c;
  c.buttons.push_back({"OK", 0, 0, 40, 24});
  c.edits.push_back({"Name", 0, 30, 100, 24, ""});
  in.updateControls(c, "GetButton");
  CHECK(c.edits[0].text == "Bob");
  CHECK(c.pressed == "OK");
  c.pressed.clear();
  in.messageBox("MsgBox");  // answered by msgbox
  in.messageBox("MsgBox");  // answered by the enter key
  CHECK(in.exhausted());

  double c2 = 0;
  ScriptedInput bad(script("button Go\n"), c2);
  CHECK(
      errorOf([&] { bad.updateControls(c, "GetButton"); }) ==
      "GetButton: the --events script presses button 'Go' (ev.txt line 1), but the program has no "
      "button of that name (its buttons: OK)");
}

TEST_CASE("input lines come from input steps or typed keys", "[input]") {
  double clock = 0;
  ScriptedInput in(script("input 42\nkeys 7x{backspace}5{enter}\n"), clock);
  CHECK(in.inputLine("input") == "42");
  CHECK(in.inputLine("input") == "75");
  CHECK(errorOf([&] { in.inputLine("input"); }) ==
        "input: no more scripted input (the --events script is exhausted)");
}

TEST_CASE("the input built-ins read the script", "[input]") {
  Run r = runWith(
      "rLocate 400, 300\n"
      "waitKey \"go? \", k\n"
      "print k\n"
      "getKey k\n"
      "print k\n"
      "getKeyE k\n"
      "print k; keyDown(kc_Up)\n"
      "getKey k\n"
      "print k\n"
      "readMouse x, y, b\n"
      "print x, \" \", y, \" \", b\n"
      "waitClick x, y\n"
      "print x, \" \", y\n"
      "AddButton \"Start\", 10, 10\n"
      "AddEdit \"Name\", 10, 50, 100, \"?\"\n"
      "repeat\n"
      "  GetButton b\n"
      "until b <> \"\"\n"
      "print b, \" \", GetEdit(\"Name\"), \" [\", LastButton(), \"]\"\n"
      "MsgBox \"Hello\", \"Greeting\"\n"
      "input \"n? \", n\n"
      "print n * 2\n",
      "key G\nhold up 3\nmouse 7 8 middle\nclick 9 10\nedit Name Ann\nbutton Start\n"
      "msgbox\ninput 21\n");
  CHECK(r.error == "");
  CHECK(r.out == "go? 71\n0\n294\t1\n0\n7 8 4\n9 10\nStart Ann []\nn? 42\n");
  CHECK(r.boxes == "Greeting: Hello\n");
}

TEST_CASE("waitKey does not print the same prompt twice in a row", "[input]") {
  Run r = runWith(
      "for i = 1 to 3\n"
      "  waitKey \"key? \", k\n"
      "next\n"
      "print\n"
      "waitKey \"key? \", k\n",
      "keys abcd\n");
  CHECK(r.out == "key? \nkey? ");
}

TEST_CASE("controls: errors and replacing", "[input]") {
  CHECK(runWith("RemoveButton \"x\"\n", "").error == "RemoveButton: there is no button named 'x'");
  CHECK(runWith("print GetEdit(\"x\")\n", "").error == "GetEdit: there is no edit box named 'x'");
  CHECK(runWith("AddButton \"\", 1, 2\n", "").error ==
        "argument 1 (name) of AddButton must not be empty");
  Run r = runWith(
      "AddEdit \"e\", 1, 2, 30, \"a\"\n"
      "SetEdit \"e\", 12\n"
      "print GetEdit(\"e\")\n"
      "RemoveEdit \"e\"\n"
      "AddButton \"b\", 1, 2\n"
      "AddButton \"b\", 5, 5, 10, 10\n"
      "RemoveButton \"b\"\n",
      "");
  CHECK(r.error == "");
  CHECK(r.out == "12\n");
  CHECK(runWith("getKey k\nwaitKey k\n", "").error ==
        "waitKey: no more scripted input (the --events script is exhausted)");
}

TEST_CASE("scripted clicks follow the input rules: buttons, edit boxes, message boxes", "[input]") {
  // A click on a button presses it; a click on an edit box gives it the keys up to enter; a
  // left click answers a message box. None of them is a mouse click the program sees.
  Run r = runWith(
      "AddButton \"Go\", 100, 100\n"
      "AddEdit \"Name\", 100, 200, 80, \"\"\n"
      "repeat\n"
      "  GetButton b\n"
      "until b <> \"\"\n"
      "print b\n"
      "waitKey k\n"
      "print GetEdit(\"Name\"), \" \", k\n"
      "MsgBox \"hi\"\n"
      "waitClick x, y\n"
      "print x, \",\", y\n",
      "click 110 110\nclick 120 210\nkeys Al{backspace}n{enter}q\nclick 5 5\nclick 7 8\n");
  CHECK(r.error == "");
  CHECK(r.out == "Go\nAn 113\n7,8\n");
}

TEST_CASE("a key Ctrl-D on an empty input line ends the input", "[input]") {
  std::vector<ScriptStep> steps = parseKeyText("\x04");
  REQUIRE(steps.size() == 1);
  InputScript s;
  s.given = true;
  s.steps = steps;
  double clock = 0;
  ScriptedInput eof(std::move(s), clock);
  CHECK(eof.inputLine("input") == std::nullopt);
}
