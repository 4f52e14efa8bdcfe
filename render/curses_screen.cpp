#include "curses_screen.h"

#include <curses.h>
#include <langinfo.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <chrono>

#include <clocale>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <unordered_map>

#include "curses_palette.h"
#include "input/input.h"

namespace rb::render {

namespace {

/// xterm's "report motion while a button is held" mode: ncurses itself asks only for presses
/// and releases, and drawing walls by dragging the mouse needs the motion in between.
constexpr const char* kDragReportsOn = "\033[?1002h";
constexpr const char* kDragReportsOff = "\033[?1002l";

int64_t translateKey(int ch) {
  switch (ch) {
    case KEY_UP: return keys::kUp;
    case KEY_DOWN: return keys::kDown;
    case KEY_LEFT: return keys::kLeft;
    case KEY_RIGHT: return keys::kRight;
    case KEY_HOME: return keys::kHome;
    case KEY_END: return keys::kEnd;
    // CSI 1~ and CSI 4~ where the terminal description names them Find and Select (VT220):
    // they are the Home and End keys, as the kitty decoder reads them too (term_input.cpp).
    case KEY_FIND: return keys::kHome;
    case KEY_SELECT: return keys::kEnd;
    case KEY_PPAGE: return keys::kPageUp;
    case KEY_NPAGE: return keys::kPageDown;
    case KEY_IC: return keys::kInsert;
    case KEY_DC: return keys::kDelete;
    case KEY_BTAB: return keys::kTab;
    case KEY_ENTER:
    case '\n':
    case '\r': return keys::kEnter;
    case KEY_BACKSPACE:
    case 127:
    case 8: return keys::kBackspace;
    default: break;
  }
  for (int i = 0; i < keys::kFunctionKeys; ++i)
    if (ch == KEY_F(i + 1)) return keys::kF1 + i;
  if (ch >= 0 && ch < 256) return ch;
  return 0;  // a key rb has no code for
}

/// Which of rb's mouse buttons the bits of a curses mouse event name.
void mouseButtons(mmask_t state, TermEvent& e) {
  struct Map {
    mmask_t pressed, released, clicked;
    int bit;
  };
  const Map maps[] = {
      {BUTTON1_PRESSED, BUTTON1_RELEASED,
       BUTTON1_CLICKED | BUTTON1_DOUBLE_CLICKED | BUTTON1_TRIPLE_CLICKED, mouse::kLeft},
      {BUTTON3_PRESSED, BUTTON3_RELEASED,
       BUTTON3_CLICKED | BUTTON3_DOUBLE_CLICKED | BUTTON3_TRIPLE_CLICKED, mouse::kRight},
      {BUTTON2_PRESSED, BUTTON2_RELEASED,
       BUTTON2_CLICKED | BUTTON2_DOUBLE_CLICKED | BUTTON2_TRIPLE_CLICKED, mouse::kMiddle},
  };
  for (const Map& m : maps) {
    if (state & m.pressed) e.pressed |= m.bit;
    if (state & m.released) e.released |= m.bit;
    // A terminal that reports only whole clicks: down and up at once.
    if (state & m.clicked) {
      e.pressed |= m.bit;
      e.released |= m.bit;
    }
  }
}

/// Whether this curses draws a UTF-8 character as one cell: true for the wide-character
/// library in a UTF-8 locale; the narrow library shows each byte on its own.
bool probeUnicode() {
  const char* codeset = nl_langinfo(CODESET);
  if (!codeset || std::strcmp(codeset, "UTF-8") != 0) return false;
  WINDOW* w = newwin(1, 8, 0, 0);
  if (!w) return false;
  waddstr(w, "\u2580");
  int x = getcurx(w);
  delwin(w);
  return x == 1;
}

/// Kitty keyboard protocol: push rb's flags / pop them again.
constexpr const char* kKittyOn = "\033[>15u";
constexpr const char* kKittyOff = "\033[<u";
/// The queries of the start: the kitty keyboard flags (a terminal that speaks the protocol
/// answers CSI ? flags u), then the primary device attributes, which every terminal answers
/// (CSI ? 62;4;... c; a 4 there means sixel graphics). The answers end with the attributes.
constexpr const char* kProbe = "\033[?u\033[c";
constexpr auto kProbeWait = std::chrono::milliseconds(400);

/// What the terminal answered to kProbe.
struct ProbeAnswer {
  bool kitty = false, sixel = false;
};

ProbeAnswer probeTerminal() {
  ProbeAnswer a;
  std::fputs(kProbe, stdout);
  std::fflush(stdout);
  std::string got;
  auto deadline = std::chrono::steady_clock::now() + kProbeWait;
  bool done = false;
  while (!done && std::chrono::steady_clock::now() < deadline) {
    wtimeout(stdscr, 20);
    int ch = wgetch(stdscr);
    if (ch == ERR || ch < 0 || ch > 255) continue;
    got += static_cast<char>(ch);
    // The device attributes end the answers: CSI ? digits;... c
    size_t at = got.rfind("\033[?");
    done = !got.empty() && got.back() == 'c' && at != std::string::npos &&
           got.find_first_not_of("0123456789;", at + 3) == got.size() - 1;
  }
  for (size_t at = got.find("\033[?"); at != std::string::npos; at = got.find("\033[?", at + 1)) {
    size_t end = got.find_first_not_of("0123456789;", at + 3);
    if (end == std::string::npos) break;
    std::string params = got.substr(at + 3, end - at - 3);
    if (got[end] == 'u') a.kitty = true;
    if (got[end] == 'c') {
      // The attributes after the first (the terminal's class) list what it can do.
      size_t i = params.find(';');
      while (i != std::string::npos) {
        size_t next = params.find(';', i + 1);
        if (params.substr(i + 1, next == std::string::npos ? std::string::npos : next - i - 1) == "4")
          a.sixel = true;
        i = next;
      }
    }
  }
  return a;
}

std::string printable(std::string_view s) {
  std::string out(s);
  for (char& c : out)
    if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) >= 127) c = '?';
  return out;
}

}  // namespace

struct CursesScreen::PairCache {
  std::unordered_map<uint32_t, int> pairs;  ///< (fg index << 16 | bg index) -> pair
  int next = 1;
};

std::unique_ptr<CursesScreen> CursesScreen::open(std::string& error) {
  if (!isatty(STDIN_FILENO) || !isatty(STDOUT_FILENO)) {
    error = "standard input and output must be a terminal";
    return nullptr;
  }
  const char* term = std::getenv("TERM");
  if (!term || !*term) {
    error = "TERM is not set";
    return nullptr;
  }
  // Only the character set: numbers must keep printing with a decimal point.
  std::setlocale(LC_CTYPE, "");
  SCREEN* sp = newterm(nullptr, stdout, stdin);
  if (!sp) {
    error = std::string("cannot use the terminal type '") + term + "'";
    return nullptr;
  }
  // A terminal that cannot move its cursor (TERM=dumb, a printing terminal) cannot show a view.
  char* cup = tigetstr(const_cast<char*>("cup"));
  if (cup == nullptr || cup == reinterpret_cast<char*>(-1)) {
    endwin();
    delscreen(sp);
    error = std::string("the terminal type '") + term + "' cannot move the cursor";
    return nullptr;
  }
  std::unique_ptr<CursesScreen> s(new CursesScreen());
  s->screen_ = sp;
  s->pairs_ = std::make_unique<PairCache>();
  set_term(sp);
  raw();  // Ctrl-C, Ctrl-S and Ctrl-Q arrive as keys: the view uses them
  noecho();
  curs_set(0);
  set_escdelay(25);
  mousemask(ALL_MOUSE_EVENTS | REPORT_MOUSE_POSITION, nullptr);
  mouseinterval(0);  // presses and releases as they happen, not combined into clicks
  std::fputs(kDragReportsOn, stdout);
  std::fflush(stdout);
  if (has_colors()) {
    start_color();
    use_default_colors();
    s->colours_ = COLORS >= 256 ? 256 : COLORS >= 16 ? 16 : 8;
    s->maxPairs_ = COLOR_PAIRS < 32767 ? COLOR_PAIRS : 32767;
    if (s->maxPairs_ < 2) s->colours_ = 0;
  }
  s->unicode_ = probeUnicode();
  const char* codeset = nl_langinfo(CODESET);
  s->utf8_ = codeset && std::strcmp(codeset, "UTF-8") == 0;
  ProbeAnswer answer = probeTerminal();
  s->sixel_ = answer.sixel;
  if (answer.kitty) {
    // Every key, its repeats and its release as escape sequences, decoded by KittyInput.
    s->kitty_ = true;
    keypad(stdscr, FALSE);
    std::fputs(kKittyOn, stdout);
    std::fflush(stdout);
  } else {
    keypad(stdscr, TRUE);
    // Home and End as screen, tmux, rxvt and the Linux console send them, when the terminal
    // description (xterm's, set inside tmux) knows only its own forms: otherwise the bytes
    // arrive one by one, the first an Esc.
    for (auto [bytes, key] : {std::pair{"\033[1~", KEY_HOME}, std::pair{"\033[4~", KEY_END},
                              std::pair{"\033[7~", KEY_HOME}, std::pair{"\033[8~", KEY_END}})
      if (key_defined(bytes) == 0) define_key(bytes, key);
  }
  return s;
}

CursesScreen::~CursesScreen() {
  if (kitty_) std::fputs(kKittyOff, stdout);
  std::fputs(kDragReportsOff, stdout);
  std::fflush(stdout);
  endwin();
  delscreen(static_cast<SCREEN*>(screen_));
}

int CursesScreen::cols() const { return COLS; }
int CursesScreen::rows() const { return LINES; }

TermEvent CursesScreen::read(int timeoutMs) {
  return kitty_ ? readKitty(timeoutMs) : readCurses(timeoutMs);
}

TermEvent CursesScreen::readCurses(int timeoutMs) {
  TermEvent e;
  wtimeout(stdscr, timeoutMs);
  int ch = wgetch(stdscr);
  if (ch == ERR) return e;
  if (ch == KEY_RESIZE) {
    e.kind = TermEvent::Resize;
    return e;
  }
  if (ch == KEY_MOUSE) {
    MEVENT me;
    if (getmouse(&me) != OK) return e;
    e.kind = TermEvent::Mouse;
    e.col = me.x;
    e.row = me.y;
    mouseButtons(me.bstate, e);
    return e;
  }
  if (utf8_ && ch >= 0xC0 && ch < 0xF8) {
    // A UTF-8 character arrives a byte at a time: characters up to U+00FF read as their Latin-1
    // code (as Windows reports them), longer ones have no key code.
    int more = ch < 0xE0 ? 1 : ch < 0xF0 ? 2 : 3;
    int code = ch & (0x3F >> more);
    wtimeout(stdscr, 20);
    for (int i = 0; i < more; ++i) {
      int next = wgetch(stdscr);
      if (next == ERR || (next & 0xC0) != 0x80) return e;
      code = (code << 6) | (next & 0x3F);
    }
    if (code >= 0xA0 && code <= 0xFF) {
      e.kind = TermEvent::Key;
      e.key = code;
    }
    return e;
  }
  e.key = translateKey(ch);
  if (e.key != 0) e.kind = TermEvent::Key;
  return e;
}

TermEvent CursesScreen::readKitty(int timeoutMs) {
  TermEvent e = kittyInput_.next();
  if (e.kind != TermEvent::None) return e;
  wtimeout(stdscr, timeoutMs);
  for (int ch = wgetch(stdscr); ch != ERR; ch = wgetch(stdscr)) {
    if (ch == KEY_RESIZE) {
      e.kind = TermEvent::Resize;
      return e;
    }
    if (ch >= 0 && ch < 256) kittyInput_.feed(std::string(1, static_cast<char>(ch)));
    e = kittyInput_.next();
    if (e.kind != TermEvent::None) return e;
    wtimeout(stdscr, kittyInput_.pending() ? 25 : 0);
  }
  // Nothing more came: what is left of an unfinished sequence is a lone Esc, or nothing.
  if (kittyInput_.pending()) {
    kittyInput_.flush();
    return kittyInput_.next();
  }
  return e;
}

void CursesScreen::beginFrame() { werase(stdscr); }

int CursesScreen::terminalColour(uint32_t rgb) const {
  if (colours_ >= 256) return nearestXterm256(rgb);
  return nearestAnsi(rgb, colours_ >= 16 ? 16 : 8);
}

int CursesScreen::pair(uint32_t fg, uint32_t bg) {
  if (colours_ == 0) return 0;
  int f = terminalColour(fg), b = terminalColour(bg);
  uint32_t key = static_cast<uint32_t>(f) << 16 | static_cast<uint32_t>(b);
  auto it = pairs_->pairs.find(key);
  if (it != pairs_->pairs.end()) return it->second;
  if (pairs_->next >= maxPairs_) {
    // Out of pairs: start over. Every frame redraws every cell, so cells drawn with a pair
    // that gets a new meaning are drawn again with the right one.
    pairs_->pairs.clear();
    pairs_->next = 1;
  }
  int p = pairs_->next++;
  init_pair(static_cast<short>(p), static_cast<short>(f), static_cast<short>(b));
  pairs_->pairs.emplace(key, p);
  return p;
}

void CursesScreen::drawText(int col, int row, std::string_view s, const TermStyle& style) {
  if (row < 0 || row >= LINES || col >= COLS || s.empty()) return;
  if (col < 0) {
    if (static_cast<size_t>(-col) >= s.size()) return;
    s.remove_prefix(static_cast<size_t>(-col));
    col = 0;
  }
  if (s.size() > static_cast<size_t>(COLS - col)) s = s.substr(0, static_cast<size_t>(COLS - col));
  attr_t a = A_NORMAL;
  if (style.bold) a |= A_BOLD;
  if (style.reverse) a |= A_REVERSE;
  if (style.underline) a |= A_UNDERLINE;
  if (style.dim) a |= A_DIM;
  short p = static_cast<short>(style.colour ? pair(style.fg, style.bg) : 0);
  attr_set(a, p, nullptr);
  mvaddstr(row, col, printable(s).c_str());
  attr_set(A_NORMAL, 0, nullptr);
}

void CursesScreen::drawArena(const ArenaFrame& frame, int col, int row) {
  for (int r = 0; r < frame.rows; ++r) {
    int y = row + r;
    if (y < 0 || y >= LINES) continue;
    for (int c = 0; c < frame.cols; ++c) {
      int x = col + c;
      if (x < 0 || x >= COLS) continue;
      const Cell& cell = frame.at(c, r);
      const std::string& g = cell.glyph;
      bool ascii = g.size() == 1 && static_cast<unsigned char>(g[0]) >= 32 &&
                   static_cast<unsigned char>(g[0]) < 127;
      const char* glyph = ascii || unicode_ ? g.c_str() : "#";
      attr_set(A_NORMAL, static_cast<short>(pair(cell.fg, cell.bg)), nullptr);
      mvaddstr(y, x, glyph);
    }
  }
  attr_set(A_NORMAL, 0, nullptr);
}

void CursesScreen::drawBox(int col, int row, int width, int height, std::string_view title) {
  if (width < 2 || height < 2) return;
  // Box-drawing characters where they show as one cell, else ASCII: the terminal's alternate
  // character set is not dependable in UTF-8 terminals (tmux shows its letters).
  const char* h = unicode_ ? "\u2500" : "-";
  const char* v = unicode_ ? "\u2502" : "|";
  const char* corners[4] = {"+", "+", "+", "+"};
  if (unicode_) {
    corners[0] = "\u250c";
    corners[1] = "\u2510";
    corners[2] = "\u2514";
    corners[3] = "\u2518";
  }
  int right = col + width - 1, bottom = row + height - 1;
  for (int x = col + 1; x < right; ++x) {
    mvaddstr(row, x, h);
    mvaddstr(bottom, x, h);
  }
  for (int y = row + 1; y < bottom; ++y) {
    mvaddstr(y, col, v);
    mvaddstr(y, right, v);
  }
  mvaddstr(row, col, corners[0]);
  mvaddstr(row, right, corners[1]);
  mvaddstr(bottom, col, corners[2]);
  mvaddstr(bottom, right, corners[3]);
  if (!title.empty() && width > 4) {
    std::string t(1, ' ');
    t.append(title.substr(0, static_cast<size_t>(width - 4)));
    t.push_back(' ');
    drawText(col + 1, row, t, TermStyle{false, 0, 0, true});
  }
}

void CursesScreen::present() {
  wnoutrefresh(stdscr);
  doupdate();
  if (!overlay_.empty()) {
    // Save the cursor, go to the cell, write, come back: curses keeps its idea of the screen.
    std::string seq = "\0337\033[" + std::to_string(overlayRow_ + 1) + ";" +
                      std::to_string(overlayCol_ + 1) + "H";
    std::fwrite(seq.data(), 1, seq.size(), stdout);
    std::fwrite(overlay_.data(), 1, overlay_.size(), stdout);
    std::fputs("\0338", stdout);
    std::fflush(stdout);
    overlay_.clear();
  }
}

void CursesScreen::redrawAll() { clearok(curscr, TRUE); }

void CursesScreen::overlayAt(int col, int row, std::string bytes) {
  overlayCol_ = col;
  overlayRow_ = row;
  overlay_ = std::move(bytes);
}

std::pair<int, int> CursesScreen::cellPixels() const {
  struct winsize ws {};
  if (ioctl(STDOUT_FILENO, TIOCGWINSZ, &ws) != 0 || ws.ws_col == 0 || ws.ws_row == 0) return {0, 0};
  return {ws.ws_xpixel / ws.ws_col, ws.ws_ypixel / ws.ws_row};
}

}  // namespace rb::render
