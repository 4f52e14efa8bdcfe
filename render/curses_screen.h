#pragma once
// The terminal, through ncurses: the one place rb talks to curses (this header does not include
// it). It opens and restores the terminal, turns key and mouse reports into events with rb's key
// codes (core/input/input.h), and draws text and arena frames in the best colours the terminal has.
// The live view's logic (tui/tui_*) uses only this interface.

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <utility>

#include "arena_view.h"
#include "term_input.h"

namespace rb::render {

/// How text is drawn: the terminal's default colours unless `colour` is set.
struct TermStyle {
  bool colour = false;
  uint32_t fg = 0xFFFFFF, bg = 0x000000;
  bool bold = false, reverse = false, underline = false, dim = false;
};

class CursesScreen {
 public:
  /// Opens the terminal for the live view; nullptr with `error` set when there is none.
  static std::unique_ptr<CursesScreen> open(std::string& error);
  /// Restores the terminal.
  ~CursesScreen();
  CursesScreen(const CursesScreen&) = delete;
  CursesScreen& operator=(const CursesScreen&) = delete;

  int cols() const;
  int rows() const;
  /// The terminal shows colours.
  bool colour() const { return colours_ > 0; }
  /// Characters beyond ASCII (half blocks, braille) show as one cell each: a UTF-8 locale and an
  /// ncurses built for wide characters.
  bool unicode() const { return unicode_; }
  /// The terminal speaks the kitty keyboard protocol: read() reports key releases too.
  bool reportsKeyReleases() const { return kitty_; }
  /// The terminal shows sixel images (it says so in its device attributes).
  bool sixel() const { return sixel_; }
  /// Writes bytes straight to the terminal after the next present(), with the cursor at a cell
  /// (an image over the arena); "" writes nothing.
  void overlayAt(int col, int row, std::string bytes);
  /// The terminal's cell size in pixels, when it tells (0 x 0 otherwise).
  std::pair<int, int> cellPixels() const;

  /// The next event, waiting up to `timeoutMs` (0: do not wait).
  TermEvent read(int timeoutMs);

  /// Starts a new picture (nothing shows until present()).
  void beginFrame();
  /// Text at a cell, cut at the right edge of the terminal.
  void drawText(int col, int row, std::string_view s, const TermStyle& style = {});
  /// A frame's cells with their top-left corner at (col, row).
  void drawArena(const ArenaFrame& frame, int col, int row);
  /// A box outline with an optional title in its top edge.
  void drawBox(int col, int row, int width, int height, std::string_view title = {});
  /// Shows the picture.
  void present();
  /// Draws every cell again at the next present() (after something else wrote on the terminal).
  void redrawAll();

 private:
  CursesScreen() = default;
  /// The colour pair for a foreground and background, allocated on first use.
  int pair(uint32_t fg, uint32_t bg);
  int terminalColour(uint32_t rgb) const;

  void* screen_ = nullptr;  ///< the curses SCREEN
  int colours_ = 0;         ///< 0 (none), 8, 16 or 256
  int maxPairs_ = 0;
  bool unicode_ = false;
  bool utf8_ = false;   ///< the locale's character set is UTF-8: key bytes are decoded
  bool kitty_ = false;  ///< the kitty keyboard protocol is on: keys are decoded by kitty_input_
  bool sixel_ = false;
  KittyInput kittyInput_;
  std::string overlay_;
  int overlayCol_ = 0, overlayRow_ = 0;
  /// Reads a key of the ncurses path (keypad decoding), a UTF-8 character decoded.
  TermEvent readCurses(int timeoutMs);
  TermEvent readKitty(int timeoutMs);
  struct PairCache;
  std::unique_ptr<PairCache> pairs_;
};

}  // namespace rb::render
