#include "term_input.h"

#include <vector>

#include "input/input.h"

namespace rb::render {

namespace {

/// The numbers of one parameter ("97:65" -> 97, 65); missing ones are -1.
std::vector<long> subParams(std::string_view p) {
  std::vector<long> out;
  long v = -1;
  for (char c : p) {
    if (c >= '0' && c <= '9') {
      v = (v < 0 ? 0 : v) * 10 + (c - '0');
      if (v > 10000000) v = 10000000;
    } else if (c == ':') {
      out.push_back(v);
      v = -1;
    }
  }
  out.push_back(v);
  return out;
}

/// The parameters of a CSI sequence split at ';'.
std::vector<std::string_view> params(std::string_view p) {
  std::vector<std::string_view> out;
  size_t start = 0;
  for (size_t i = 0; i <= p.size(); ++i) {
    if (i == p.size() || p[i] == ';') {
      out.push_back(p.substr(start, i - start));
      start = i + 1;
    }
  }
  return out;
}

/// Modifier bits of the protocol (the parameter is 1 + bits).
constexpr int kShift = 1, kCtrl = 4;

struct Mods {
  int bits = 0;
  int event = 1;  ///< 1 press, 2 repeat, 3 release
};

Mods modsOf(const std::vector<std::string_view>& ps, size_t index) {
  Mods m;
  if (index >= ps.size()) return m;
  std::vector<long> v = subParams(ps[index]);
  if (v[0] > 0) m.bits = static_cast<int>(v[0] - 1);
  if (v.size() > 1 && v[1] > 0) m.event = static_cast<int>(v[1]);
  return m;
}

/// rb's code of a kitty key code (Unicode, or the protocol's private-use codes), 0 for none.
int64_t keyOfCode(long code, long shifted, int mods) {
  switch (code) {
    case 13: return keys::kEnter;
    case 9: return keys::kTab;
    case 127:
    case 8: return keys::kBackspace;
    case 27: return keys::kEsc;
    default: break;
  }
  // The keypad (private-use codes).
  if (code >= 57399 && code <= 57408) return '0' + (code - 57399);
  switch (code) {
    case 57409: return '.';
    case 57410: return '/';
    case 57411: return '*';
    case 57412: return '-';
    case 57413: return '+';
    case 57414: return keys::kEnter;
    case 57415: return '=';
    case 57417: return keys::kLeft;
    case 57418: return keys::kRight;
    case 57419: return keys::kUp;
    case 57420: return keys::kDown;
    case 57421: return keys::kPageUp;
    case 57422: return keys::kPageDown;
    case 57423: return keys::kHome;
    case 57424: return keys::kEnd;
    case 57425: return keys::kInsert;
    case 57426: return keys::kDelete;
    default: break;
  }
  if (code < 32 || code > 255 || (code >= 127 && code < 160)) return 0;  // modifiers, F13+, ...
  if (mods & kCtrl) {
    if (code >= 'a' && code <= 'z') return code - 'a' + 1;
    if (code >= '@' && code <= '_') return code - '@';
  }
  if (mods & kShift) {
    if (shifted > 0 && shifted <= 255) return shifted;
    if (code >= 'a' && code <= 'z') return code - 'a' + 'A';
  }
  return code;
}

/// `CSI n ~` keys.
int64_t tildeKey(long n) {
  switch (n) {
    case 2: return keys::kInsert;
    case 3: return keys::kDelete;
    case 5: return keys::kPageUp;
    case 6: return keys::kPageDown;
    case 1:
    case 7: return keys::kHome;
    case 4:
    case 8: return keys::kEnd;
    case 11: return keys::kF1;
    case 12: return keys::kF1 + 1;
    case 13: return keys::kF1 + 2;
    case 14: return keys::kF1 + 3;
    case 15: return keys::kF1 + 4;
    case 17: return keys::kF1 + 5;
    case 18: return keys::kF1 + 6;
    case 19: return keys::kF1 + 7;
    case 20: return keys::kF1 + 8;
    case 21: return keys::kF1 + 9;
    case 23: return keys::kF1 + 10;
    case 24: return keys::kF1 + 11;
    default: return 0;
  }
}

/// `CSI 1;m X` and `SS3 X` keys.
int64_t letterKey(char c) {
  switch (c) {
    case 'A': return keys::kUp;
    case 'B': return keys::kDown;
    case 'C': return keys::kRight;
    case 'D': return keys::kLeft;
    case 'H': return keys::kHome;
    case 'F': return keys::kEnd;
    case 'P': return keys::kF1;
    case 'Q': return keys::kF1 + 1;
    case 'R': return keys::kF1 + 2;
    case 'S': return keys::kF1 + 3;
    default: return 0;
  }
}

TermEvent keyEvent(int64_t key, int event) {
  TermEvent e;
  if (key == 0) return e;
  e.kind = TermEvent::Key;
  e.key = key;
  e.release = event == 3;
  return e;
}

TermEvent mouseEvent(std::string_view p, char final) {
  TermEvent e;
  std::vector<std::string_view> ps = params(p);
  if (ps.size() != 3) return e;
  long b = subParams(ps[0])[0], x = subParams(ps[1])[0], y = subParams(ps[2])[0];
  if (b < 0 || x < 1 || y < 1) return e;
  e.kind = TermEvent::Mouse;
  e.col = static_cast<int>(x - 1);
  e.row = static_cast<int>(y - 1);
  if (b & 64) return e;  // the wheel: a pointer report without buttons
  int bit = (b & 3) == 0 ? 1 : (b & 3) == 1 ? 4 : (b & 3) == 2 ? 2 : 0;
  if (b & 32) return e;  // motion (a drag): the pointer moves
  if (final == 'M') e.pressed = bit;
  else e.released = bit;
  return e;
}

}  // namespace

TermEvent kittyKeyEvent(std::string_view p, char final) {
  std::vector<std::string_view> ps = params(p);
  Mods m = modsOf(ps, 1);
  if (final == 'u') {
    std::vector<long> codes = subParams(ps.empty() ? std::string_view() : ps[0]);
    long shifted = codes.size() > 1 ? codes[1] : -1;
    return keyEvent(keyOfCode(codes[0], shifted, m.bits), m.event);
  }
  if (final == '~') return keyEvent(tildeKey(subParams(ps.empty() ? "" : ps[0])[0]), m.event);
  return keyEvent(letterKey(final), m.event);
}

void KittyInput::feed(std::string_view bytes) { buffer_.append(bytes); }

TermEvent KittyInput::next() {
  while (ready_.empty() && !buffer_.empty()) {
    TermEvent e;
    if (!decode(e)) break;
    if (e.kind != TermEvent::None) ready_.push_back(e);
  }
  if (ready_.empty()) return {};
  TermEvent e = ready_.front();
  ready_.pop_front();
  return e;
}

void KittyInput::flush() {
  if (buffer_ == "\x1b") ready_.push_back(keyEvent(keys::kEsc, 1));
  buffer_.clear();
}

bool KittyInput::decode(TermEvent& out) {
  out = {};
  auto c0 = static_cast<unsigned char>(buffer_[0]);
  if (c0 == 0x1b) {
    if (buffer_.size() < 2) return false;
    char kind = buffer_[1];
    if (kind == 'O') {  // SS3 X
      if (buffer_.size() < 3) return false;
      out = keyEvent(letterKey(buffer_[2]), 1);
      buffer_.erase(0, 3);
      return true;
    }
    if (kind != '[') {  // Alt+key or a stray ESC: the ESC alone
      out = keyEvent(keys::kEsc, 1);
      buffer_.erase(0, 1);
      return true;
    }
    // CSI: parameters 0x30-0x3F, intermediates 0x20-0x2F, a final 0x40-0x7E.
    size_t i = 2;
    while (i < buffer_.size() && static_cast<unsigned char>(buffer_[i]) >= 0x20 &&
           static_cast<unsigned char>(buffer_[i]) <= 0x3F)
      ++i;
    if (i >= buffer_.size()) {
      if (buffer_.size() > 64) buffer_.clear();  // no terminal sends this: drop it
      return false;
    }
    char final = buffer_[i];
    std::string p = buffer_.substr(2, i - 2);
    buffer_.erase(0, i + 1);
    if (!p.empty() && p[0] == '<') {
      if (final == 'M' || final == 'm') out = mouseEvent(std::string_view(p).substr(1), final);
      return true;
    }
    if (!p.empty() && (p[0] == '?' || p[0] == '>' || p[0] == '=')) return true;  // replies
    if (final == 'u' || final == '~' || letterKey(final) != 0) out = kittyKeyEvent(p, final);
    return true;
  }
  // Plain bytes: a UTF-8 character (up to U+00FF has a key code) or a control character.
  size_t len = c0 < 0x80 ? 1 : c0 >= 0xC0 && c0 < 0xE0 ? 2 : c0 >= 0xE0 && c0 < 0xF0 ? 3
                         : c0 >= 0xF0 && c0 < 0xF8 ? 4 : 1;
  if (buffer_.size() < len) return false;
  long code = c0;
  if (len == 2) code = ((c0 & 0x1F) << 6) | (static_cast<unsigned char>(buffer_[1]) & 0x3F);
  else if (len > 2) code = -1;
  buffer_.erase(0, len);
  if (code == 13 || code == 10) out = keyEvent(keys::kEnter, 1);
  else if (code == 9) out = keyEvent(keys::kTab, 1);
  else if (code == 127 || code == 8) out = keyEvent(keys::kBackspace, 1);
  else if (code > 0 && code < 32) out = keyEvent(code, 1);
  else if (code >= 32 && code <= 255) out = keyEvent(code, 1);
  return true;
}

}  // namespace rb::render
