#include <catch2/catch.hpp>

#include <cstdlib>
#include <string>
#include <vector>

#include "screen/canvas.h"
#include "screen/font.h"

using namespace rb;

TEST_CASE("fonts: the print font is Courier New's twin at 10 points, 8 x 15 pixels", "[font]") {
  FontRenderer f;
  const FontKey print;
  CHECK(print.face == Typeface::Mono);
  CHECK(print.pixelSize == 13);
  const FontMetrics& m = f.metrics(print);
  CHECK(m.ascent == 11);
  CHECK(m.descent == 4);
  CHECK(m.lineHeight == 15);
  // Every Latin-1 character advances 8 pixels, bold, italic or not (a monospaced face).
  for (bool bold : {false, true})
    for (bool italic : {false, true}) {
      FontKey k = print;
      k.bold = bold;
      k.italic = italic;
      for (int c = 32; c < 256; ++c) {
        INFO("character " << c << " bold " << bold << " italic " << italic);
        CHECK(f.glyph(k, static_cast<unsigned char>(c)).advance == 8);
      }
    }
  CHECK(f.width(print, "Hello, World") == 96);
}

TEST_CASE("fonts: a text's width stops at kMaxTextWidth, however long the text", "[font]") {
  FontRenderer f;
  FontKey big;
  big.pixelSize = pixelSizeForPoints(200);
  // 60 million characters of about 150 pixels each would be 9e9 pixels, past int's limit.
  const std::string text(60'000'000, 'W');
  std::vector<const Glyph*> kept;
  CHECK(f.glyphs(big, text, kept, 8) == FontRenderer::kMaxTextWidth);
  REQUIRE(kept.size() == 8);
  for (const Glyph* g : kept) CHECK(g == &f.glyph(big, 'W'));
  const FontKey print;
  CHECK(f.width(print, std::string(FontRenderer::kMaxTextWidth / 8 - 1, 'a')) == FontRenderer::kMaxTextWidth - 8);
}

TEST_CASE("fonts: glyphs are monochrome bitmaps on the baseline", "[font]") {
  FontRenderer f;
  const FontKey k;
  const Glyph& i = f.glyph(k, 'I');
  REQUIRE(i.width > 0);
  REQUIRE(i.height > 0);
  // A capital stands on the baseline and reaches about the cap height (0.66 em of 13 pixels).
  CHECK(i.top - i.height == 0);
  CHECK(i.top >= 8);
  CHECK(i.top <= 10);
  for (uint8_t b : i.bits) CHECK((b == 0 || b == 1));
  // A space draws nothing; 'g' descends below the baseline.
  const Glyph& space = f.glyph(k, ' ');
  for (uint8_t b : space.bits) CHECK(b == 0);
  CHECK(f.glyph(k, 'g').top - f.glyph(k, 'g').height < 0);
  // A character the font lacks (a C1 control code) is drawn as '?'.
  const Glyph& q = f.glyph(k, '?');
  const Glyph& missing = f.glyph(k, 0x85);
  CHECK(missing.bits == q.bits);
}

TEST_CASE("fonts: the same text gives the same pixels, whatever FREETYPE_PROPERTIES says", "[font]") {
  // Every Latin-1 glyph of the print font and of Arial's twin, as numbers.
  auto snapshot = [](FontRenderer& f) {
    std::vector<int> out;
    for (Typeface face : {Typeface::Mono, Typeface::Sans}) {
      FontKey k;
      k.face = face;
      for (int c = 32; c < 256; ++c) {
        const Glyph& g = f.glyph(k, static_cast<unsigned char>(c));
        out.insert(out.end(), {g.left, g.top, g.width, g.height, g.advance});
        out.insert(out.end(), g.bits.begin(), g.bits.end());
      }
    }
    return out;
  };
  FontRenderer a;
  const std::vector<int> first = snapshot(a);
  FontRenderer again;
  CHECK(snapshot(again) == first);
  // An environment that asks FreeType for its older bytecode interpreter (which hints these
  // fonts differently) changes nothing: rb chooses the interpreter itself.
  const char* old = std::getenv("FREETYPE_PROPERTIES");
  std::string saved = old ? old : "";
  setenv("FREETYPE_PROPERTIES", "truetype:interpreter-version=35", 1);
  FontRenderer b;
  const std::vector<int> withEnvironment = snapshot(b);
  if (old) setenv("FREETYPE_PROPERTIES", saved.c_str(), 1);
  else unsetenv("FREETYPE_PROPERTIES");
  CHECK(withEnvironment == first);
}

TEST_CASE("fonts: xyText font names pick the face with Windows' widths", "[font]") {
  CHECK(typefaceForName("") == Typeface::Mono);
  CHECK(typefaceForName("  ") == Typeface::Mono);
  CHECK(typefaceForName("Courier New") == Typeface::Mono);
  CHECK(typefaceForName("courier") == Typeface::Mono);
  CHECK(typefaceForName("Lucida Console") == Typeface::Mono);
  CHECK(typefaceForName("Consolas") == Typeface::Mono);
  CHECK(typefaceForName("Arial") == Typeface::Sans);
  CHECK(typefaceForName("Microsoft Sans Serif") == Typeface::Sans);
  CHECK(typefaceForName("Verdana") == Typeface::Sans);
  CHECK(typefaceForName("Times New Roman") == Typeface::Serif);
  CHECK(typefaceForName("TIMES") == Typeface::Serif);
  CHECK(typefaceForName("Georgia") == Typeface::Serif);
  CHECK(typefaceForName("no such font") == Typeface::Sans);
  // Points at 96 dots per inch, rounded as Windows does.
  CHECK(pixelSizeForPoints(10) == 13);
  CHECK(pixelSizeForPoints(12) == 16);
  CHECK(pixelSizeForPoints(24) == 32);
  CHECK(pixelSizeForPoints(1) == 1);
  CHECK(pixelSizeForPoints(200) == 267);
  // Arial and Times are narrower than Courier; all three at every size the table allows.
  FontRenderer f;
  for (int px : {1, 13, 16, 267}) {
    FontKey mono, sans, serif;
    mono.pixelSize = sans.pixelSize = serif.pixelSize = px;
    sans.face = Typeface::Sans;
    serif.face = Typeface::Serif;
    INFO("pixel size " << px);
    CHECK(f.metrics(mono).lineHeight >= 1);
    if (px >= 13) {
      CHECK(f.width(sans, "Hello, World") < f.width(mono, "Hello, World"));
      CHECK(f.width(serif, "Hello, World") < f.width(mono, "Hello, World"));
    }
  }
}

TEST_CASE("fonts: text on the canvas is the glyphs' pixels, with lines and a background", "[font]") {
  Canvas c;
  c.keepDisplayList(true);
  TextStyle style;
  int w = c.text(10, 20, "AB", style, colours::kRed);
  CHECK(w == 16);
  // Every red pixel is a glyph pixel placed on the baseline (row 20 + 11).
  FontRenderer& f = c.fonts();
  size_t red = 0, glyphPixels = 0;
  for (int y = 0; y < 60; ++y)
    for (int x = 0; x < 60; ++x) red += c.at(x, y) == colours::kRed;
  for (unsigned char ch : {'A', 'B'})
    for (uint8_t b : f.glyph(style.font, ch).bits) glyphPixels += b;
  CHECK(red == glyphPixels);
  CHECK(c.displayList().back().kind == DrawOp::Text);
  CHECK(c.displayList().back().points[1] == Point{26, 35});
  CHECK(c.displayList().back().ascent == 11);

  Canvas d;
  style.underline = true;
  style.strikeout = true;
  style.background = colours::kYellow;
  d.text(100, 100, "  ", style, colours::kBlue);
  const FontMetrics& m = d.fonts().metrics(style.font);
  CHECK(d.at(100, 100 + m.underlineTop) == colours::kBlue);
  CHECK(d.at(115, 100 + m.strikeoutTop) == colours::kBlue);
  CHECK(d.at(100, 100) == colours::kYellow);
  CHECK(d.at(115, 113) == colours::kYellow);
  CHECK(d.at(116, 100) == colours::kWhite);
  CHECK(d.at(100, 115) == colours::kWhite);
  CHECK(m.underlineTop > m.strikeoutTop);
  CHECK(m.underlineTop < m.lineHeight);
}
