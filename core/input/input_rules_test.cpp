#include "input/input_rules.h"

#include <catch2/catch.hpp>

using namespace rb;

TEST_CASE("input rules: keys that answer a message box", "[input]") {
  CHECK(InputRules::answersMessageBox(keys::kEnter));
  CHECK(InputRules::answersMessageBox(keys::kEsc));
  CHECK(InputRules::answersMessageBox(keys::kSpace));
  CHECK_FALSE(InputRules::answersMessageBox('y'));
  CHECK_FALSE(InputRules::answersMessageBox(keys::kF1));
  CHECK(InputRules::clickAnswersMessageBox(mouse::kLeft));
  CHECK(InputRules::clickAnswersMessageBox(mouse::kLeft | mouse::kRight));
  CHECK_FALSE(InputRules::clickAnswersMessageBox(mouse::kRight));
  CHECK_FALSE(InputRules::clickAnswersMessageBox(0));
}

TEST_CASE("input rules: the characters a key types are printable Latin-1", "[input]") {
  CHECK(InputRules::typesCharacter(' '));
  CHECK(InputRules::typesCharacter('~'));
  CHECK(InputRules::typesCharacter(0xE9));  // é
  CHECK(InputRules::typesCharacter(0xA0));
  CHECK(InputRules::typesCharacter(0xFF));
  CHECK_FALSE(InputRules::typesCharacter(31));
  CHECK_FALSE(InputRules::typesCharacter(127));
  CHECK_FALSE(InputRules::typesCharacter(0x85));  // a C1 control
  CHECK_FALSE(InputRules::typesCharacter(keys::kLeft));
  CHECK_FALSE(InputRules::typesCharacter(keys::kEnter));
}

TEST_CASE("input rules: typing a line", "[input]") {
  using LK = InputRules::LineKey;
  std::string t;
  CHECK(InputRules::editLine(t, 4) == LK::EndOfInput);  // Ctrl-D on an empty line
  CHECK(InputRules::editLine(t, keys::kBackspace) == LK::Ignored);
  CHECK(InputRules::editLine(t, 'a') == LK::Typed);
  CHECK(InputRules::editLine(t, 0xE9) == LK::Typed);
  CHECK(InputRules::editLine(t, 4) == LK::Ignored);  // not on a line with text
  CHECK(InputRules::editLine(t, keys::kUp) == LK::Ignored);
  CHECK(t == "a\xE9");
  CHECK(InputRules::editLine(t, keys::kBackspace) == LK::Deleted);
  CHECK(t == "a");
  CHECK(InputRules::editLine(t, keys::kEnter) == LK::Done);
  CHECK(t == "a");
}

TEST_CASE("input rules: presses hit the topmost control in screen pixels", "[input]") {
  Controls c;
  c.buttons.push_back({"Under", 100, 100, 60, 24});
  c.buttons.push_back({"Over", 140, 110, 60, 24});
  c.edits.push_back({"Name", 300, 100, 100, 24, "x"});
  InputRules rules;
  using T = InputRules::Target;

  CHECK(rules.press(c, 150, 115) == T::Button);
  CHECK(c.pressed == "Over");  // the last added is on top
  CHECK(rules.press(c, 105, 105) == T::Button);
  CHECK(c.pressed == "Under");
  c.pressed.clear();
  // An area (the pixels of one terminal cell) hits what it overlaps.
  CHECK(rules.press(c, 90, 90, 12, 12) == T::Button);
  CHECK(c.pressed == "Under");
  CHECK(rules.press(c, 90, 90, 10, 10) == T::Program);  // ends at 99: just misses

  CHECK(rules.press(c, 350, 110) == T::EditBox);
  CHECK(rules.focusedEdit() == "Name");
  CHECK(rules.typeInto(c, 'y'));
  CHECK(rules.typeInto(c, keys::kBackspace));
  CHECK(rules.typeInto(c, 'z'));
  CHECK(c.edits[0].text == "xz");
  CHECK(rules.typeInto(c, keys::kTab));  // gives the keyboard back
  CHECK(rules.focusedEdit().empty());
  CHECK_FALSE(rules.typeInto(c, 'q'));
  CHECK(c.edits[0].text == "xz");

  CHECK(rules.press(c, 350, 110) == T::EditBox);
  CHECK(rules.press(c, 10, 10) == T::Program);  // a press elsewhere takes the focus away
  CHECK(rules.focusedEdit().empty());

  CHECK(rules.press(c, 350, 110) == T::EditBox);
  c.edits.clear();  // the program removed it
  CHECK_FALSE(rules.typeInto(c, 'q'));
  CHECK(rules.focusedEdit().empty());
}
