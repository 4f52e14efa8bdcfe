#include "input/input_rules.h"

namespace rb {

namespace {
constexpr int64_t kCtrlD = 4;
}  // namespace

bool InputRules::answersMessageBox(int64_t key) {
  return key == keys::kEnter || key == keys::kEsc || key == keys::kSpace;
}

bool InputRules::typesCharacter(int64_t key) {
  return (key >= 32 && key <= 126) || (key >= 160 && key <= 255);
}

InputRules::LineKey InputRules::editLine(std::string& text, int64_t key) {
  if (key == keys::kEnter) return LineKey::Done;
  if (key == kCtrlD && text.empty()) return LineKey::EndOfInput;
  if (key == keys::kBackspace) {
    if (text.empty()) return LineKey::Ignored;
    text.pop_back();
    return LineKey::Deleted;
  }
  if (!typesCharacter(key)) return LineKey::Ignored;
  text += static_cast<char>(static_cast<unsigned char>(key));
  return LineKey::Typed;
}

InputRules::Target InputRules::press(Controls& controls, int x, int y, int w, int h) {
  if (const Button* b = controls.buttonAt(x, y, w, h)) {
    controls.pressed = b->name;
    return Target::Button;
  }
  if (const EditBox* e = controls.editAt(x, y, w, h)) {
    focused_ = e->name;
    return Target::EditBox;
  }
  focused_.clear();
  return Target::Program;
}

bool InputRules::typeInto(Controls& controls, int64_t key) {
  if (focused_.empty()) return false;
  EditBox* e = controls.edit(focused_);
  if (!e) {  // removed by the program meanwhile
    focused_.clear();
    return false;
  }
  if (key == keys::kEnter || key == keys::kTab || key == keys::kEsc) {
    focused_.clear();
    return true;
  }
  // An edit box holds one line: Ctrl-D and Enter end nothing here.
  if (key != 4) editLine(e->text, key);
  return true;
}

}  // namespace rb
