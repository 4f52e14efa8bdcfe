#include "input/input.h"

#include <cctype>

namespace rb {

const std::vector<KeyName>& keyNames() {
  static const std::vector<KeyName> names = [] {
    std::vector<KeyName> n = {
        {"up", keys::kUp},         {"down", keys::kDown},     {"left", keys::kLeft},
        {"right", keys::kRight},   {"enter", keys::kEnter},   {"esc", keys::kEsc},
        {"space", keys::kSpace},   {"tab", keys::kTab},       {"backspace", keys::kBackspace},
        {"delete", keys::kDelete}, {"insert", keys::kInsert}, {"home", keys::kHome},
        {"end", keys::kEnd},       {"pgup", keys::kPageUp},   {"pgdn", keys::kPageDown},
    };
    static const char* const kFunctionNames[keys::kFunctionKeys] = {
        "f1", "f2", "f3", "f4", "f5", "f6", "f7", "f8", "f9", "f10", "f11", "f12"};
    for (int i = 0; i < keys::kFunctionKeys; ++i) n.push_back({kFunctionNames[i], keys::kF1 + i});
    return n;
  }();
  return names;
}

std::optional<int64_t> keyCodeByName(std::string_view name) {
  std::string lower;
  for (char c : name) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  // Common spellings besides the listed names.
  if (lower == "return") lower = "enter";
  if (lower == "escape") lower = "esc";
  if (lower == "pageup") lower = "pgup";
  if (lower == "pagedown") lower = "pgdn";
  if (lower == "del") lower = "delete";
  for (const KeyName& k : keyNames())
    if (k.name == lower) return k.code;
  return std::nullopt;
}

std::string describeKey(int64_t code) {
  for (const KeyName& k : keyNames())
    if (k.code == code) return std::string(k.name);
  if (code > 32 && code < 127) return std::string(1, static_cast<char>(code));
  return "key " + std::to_string(code);
}

Button* Controls::button(std::string_view name) {
  for (Button& b : buttons)
    if (b.name == name) return &b;
  return nullptr;
}

EditBox* Controls::edit(std::string_view name) {
  for (EditBox& e : edits)
    if (e.name == name) return &e;
  return nullptr;
}

const Button* Controls::buttonAt(int x, int y, int w, int h) const {
  // The last added is drawn on top, so it wins.
  for (auto it = buttons.rbegin(); it != buttons.rend(); ++it)
    if (it->overlaps(x, y, w, h)) return &*it;
  return nullptr;
}

const EditBox* Controls::editAt(int x, int y, int w, int h) const {
  for (auto it = edits.rbegin(); it != edits.rend(); ++it)
    if (it->overlaps(x, y, w, h)) return &*it;
  return nullptr;
}

std::string Controls::buttonNames() const {
  if (buttons.empty()) return "none";
  std::string s;
  for (const Button& b : buttons) s += (s.empty() ? "" : ", ") + b.name;
  return s;
}

}  // namespace rb
