#include "term_input.h"

#include <catch2/catch.hpp>
#include <vector>

#include "input/input.h"

using namespace rb;
using namespace rb::render;

namespace {
std::vector<TermEvent> decode(std::string_view bytes) {
  KittyInput in;
  in.feed(bytes);
  std::vector<TermEvent> out;
  for (TermEvent e = in.next(); e.kind != TermEvent::None; e = in.next()) out.push_back(e);
  return out;
}

std::string keysOf(std::string_view bytes) {
  std::string s;
  for (const TermEvent& e : decode(bytes)) {
    if (e.kind != TermEvent::Key) continue;
    s += e.release ? '-' : '+';
    s += describeKey(e.key);
    s += ' ';
  }
  return s;
}
}  // namespace

TEST_CASE("kitty keys: presses, repeats and releases of letters", "[term]") {
  CHECK(keysOf("\x1b[97u\x1b[97;1:2u\x1b[97;1:3u") == "+a +a -a ");
  // Shift: the shifted character the terminal reports, else the upper-case letter.
  CHECK(keysOf("\x1b[97:65;2u\x1b[104;2u") == "+A +H ");
  // Ctrl+letter is its control character.
  CHECK(decode("\x1b[99;5u")[0].key == 3);
  CHECK(keysOf("\x1b[13u\x1b[27u\x1b[9u\x1b[127u\x1b[32u") == "+enter +esc +tab +backspace +space ");
  // Modifier keys alone and F13+ have no code.
  CHECK(keysOf("\x1b[57441u\x1b[57376u") == "");
  // The keypad.
  CHECK(keysOf("\x1b[57400u\x1b[57414u\x1b[57419u") == "+1 +enter +up ");
}

TEST_CASE("kitty keys: arrows, function keys, editing keys", "[term]") {
  CHECK(keysOf("\x1b[A\x1b[1;1:3A\x1bOB\x1b[C\x1b[1;5D") == "+up -up +down +right +left ");
  CHECK(keysOf("\x1bOP\x1b[1;1:3Q\x1b[13~\x1b[15;1:3~\x1b[21~\x1b[24~") ==
        "+f1 -f2 +f3 -f5 +f10 +f12 ");
  CHECK(keysOf("\x1b[2~\x1b[3~\x1b[5~\x1b[6~\x1b[H\x1b[F") ==
        "+insert +delete +pgup +pgdn +home +end ");
}

TEST_CASE("kitty input: text, UTF-8, mouse reports, replies", "[term]") {
  CHECK(keysOf("hi\r") == "+h +i +enter ");
  CHECK(decode("\xc3\xa9")[0].key == 0xE9);  // é, a Latin-1 code
  CHECK(decode("\xe2\x82\xac").empty());     // € has no key code
  auto m = decode("\x1b[<0;12;5M\x1b[<32;13;5M\x1b[<0;13;5m\x1b[<2;1;1M");
  REQUIRE(m.size() == 4);
  CHECK(m[0].kind == TermEvent::Mouse);
  CHECK(m[0].col == 11);
  CHECK(m[0].row == 4);
  CHECK(m[0].pressed == mouse::kLeft);
  CHECK(m[1].pressed == 0);  // a drag: the pointer moves
  CHECK(m[1].col == 12);
  CHECK(m[2].released == mouse::kLeft);
  CHECK(m[3].pressed == mouse::kRight);
  // Replies to rb's queries are not keys.
  CHECK(decode("\x1b[?15u\x1b[?62;4c").empty());
}

TEST_CASE("kitty input: unfinished sequences wait for more bytes", "[term]") {
  KittyInput in;
  in.feed("\x1b[9");
  CHECK(in.next().kind == TermEvent::None);
  CHECK(in.pending());
  in.feed("7;1:3u");
  TermEvent e = in.next();
  CHECK(e.key == 'a');
  CHECK(e.release);
  in.feed("\x1b");
  CHECK(in.next().kind == TermEvent::None);
  in.flush();  // nothing followed: the Esc key
  CHECK(in.next().key == keys::kEsc);
  in.feed("\x1b[123456789012345678901234567890123456789012345678901234567890123456789");
  CHECK(in.next().kind == TermEvent::None);
  CHECK_FALSE(in.pending());  // too long for any terminal: dropped
}
