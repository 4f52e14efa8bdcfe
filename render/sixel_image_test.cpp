#include "sixel_image.h"

#include <catch2/catch.hpp>

using namespace rb::render;

TEST_CASE("sixel: the screen as a sixel image", "[sixel]") {
  RgbImage image;
  image.width = 8;
  image.height = 6;
  image.rgb.assign(8 * 6 * 3, 0xFF);
  image.set(0, 0, 0xFF0000);
  std::string s = sixelImage(image, 16, 12);
  // A device control string: ESC P ... q (sixel data) ... ESC backslash.
  REQUIRE(s.size() > 10);
  CHECK(s.rfind("\x1bP", 0) == 0);
  CHECK(s.find('q') != std::string::npos);
  CHECK(s.substr(s.size() - 2) == "\x1b\\");
  // The size travels in the raster attributes: "1;1;16;12.
  CHECK(s.find("\"1;1;16;12") != std::string::npos);
  // Two colour registers (RGB percentages): the red corner and the white rest.
  CHECK(s.find("#0;2;") != std::string::npos);
  CHECK(s.find("#1;2;") != std::string::npos);
  CHECK(s.find("#2;2;") == std::string::npos);
  CHECK(sixelImage(image, 0, 12).empty());
}
