// The SVG picture: vector elements from the display list, Figure 1.7's trail as one polyline,
// the raster fallback after floodFill, scaling and determinism.

#include <catch2/catch.hpp>

#include <cctype>
#include <iterator>
#include <set>
#include <sstream>

#include "png_writer.h"
#include "render_test_support.h"
#include "svg_writer.h"

namespace rb::render {
namespace {

std::string svgOf(const std::string& program, int scale = 1) {
  auto run = test::runForPicture(program);
  INFO(run->diagnostics);
  REQUIRE(run->loaded);
  REQUIRE(run->result.status == RunStatus::Finished);
  return renderSvg(run->canvas(), run->robot(), scale);
}

/// The elements named `tag` in the document, as their whole text. Scanned by hand: std::regex
/// recurses once per character and overflows the stack on an embedded picture's base64.
std::vector<std::string> elements(const std::string& svg, const std::string& tag) {
  std::vector<std::string> found;
  const std::string open = "<" + tag;
  for (size_t at = svg.find(open); at != std::string::npos; at = svg.find(open, at + 1)) {
    const size_t after = at + open.size();
    if (after < svg.size() && (std::isalnum(static_cast<unsigned char>(svg[after])) || svg[after] == '_'))
      continue;  // a longer name that starts with tag
    const size_t end = svg.find('>', after);
    if (end == std::string::npos) break;
    found.push_back(svg.substr(at, end - at + 1));
  }
  return found;
}

/// The value of attribute `name` in an element's text, or "" without one.
std::string attribute(const std::string& element, const std::string& name) {
  const std::string key = name + "=\"";
  for (size_t at = element.find(key); at != std::string::npos; at = element.find(key, at + 1)) {
    if (at == 0 || !std::isspace(static_cast<unsigned char>(element[at - 1]))) continue;
    const size_t from = at + key.size();
    const size_t end = element.find('"', from);
    if (end == std::string::npos) return {};
    return element.substr(from, end - from);
  }
  return {};
}

std::vector<uint8_t> base64Decode(const std::string& text) {
  auto value = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
  };
  std::vector<uint8_t> out;
  uint32_t acc = 0;
  int bits = 0;
  for (char c : text) {
    int v = value(c);
    if (v < 0) continue;
    acc = acc << 6 | static_cast<uint32_t>(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<uint8_t>(acc >> bits));
    }
  }
  return out;
}

TEST_CASE("svg: Figure 1.7's trail is one green polyline through the square's corners", "[render][svg]") {
  std::string program = test::readText(test::sourceRoot() / "examples" / "fig_1_7.bas");
  REQUIRE_FALSE(program.empty());
  std::string svg = svgOf(program);
  CHECK(svg.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg ", 0) == 0);
  CHECK_THAT(svg, Catch::Contains("version=\"1.1\" width=\"800\" height=\"600\" viewBox=\"0 0 800 600\""));
  CHECK_THAT(svg, Catch::EndsWith("</svg>\n"));
  std::vector<std::string> lines = elements(svg, "polyline");
  REQUIRE(lines.size() == 1);
  const std::string& trail = lines[0];
  // Even widths centre the brush on the pixel's corner, so the corners are whole numbers.
  CHECK(attribute(trail, "points") == "400,300 400,180 520,180 520,300 400,300");
  CHECK(attribute(trail, "stroke") == "#008000");
  CHECK(attribute(trail, "stroke-width") == "4");
  CHECK(attribute(trail, "fill") == "none");
  // The white background first, the robot last: a circle and its heading line, in blue, 3 pixels
  // wide inside its rim (radius 20: the stroke covers 17 to 20 from the centre).
  std::vector<std::string> rects = elements(svg, "rect");
  REQUIRE_FALSE(rects.empty());
  CHECK(rects[0] == "<rect x=\"0\" y=\"0\" width=\"800\" height=\"600\" fill=\"#ffffff\"/>");
  std::vector<std::string> circles = elements(svg, "circle");
  REQUIRE(circles.size() == 1);
  CHECK(circles[0] ==
        "<circle cx=\"400.5\" cy=\"300.5\" r=\"18.5\" fill=\"none\" stroke=\"#0000ff\" stroke-width=\"3\"/>");
  CHECK(svg.find("<circle") > svg.find("<polyline"));
  CHECK_THAT(svg, Catch::Contains("<line x1=\"400.5\" y1=\"300.5\" x2=\"400.5\" y2=\"282\" stroke=\"#0000ff\" "
                                  "stroke-width=\"3\"/>"));
  CHECK(svg.find("<image") == std::string::npos);
}

TEST_CASE("svg: a trail broken by other drawing is polylines that join end to end", "[render][svg]") {
  // Status text between the moves: the trail goes on after each text in a new polyline that
  // starts where the last one ended, so the picture shows one continuous line.
  std::string svg = svgOf(
      "rLocate 400, 300\nrInvisible GREEN\nLineWidth 4\nrPen DOWN\n"
      "for i = 1 to 30\n  xyString 10, 10, i\n  rForward 2\nnext\n"
      "rTurn 90\nfor i = 1 to 20\n  xyString 10, 10, i\n  rForward 3\nnext\n");
  std::vector<std::string> lines = elements(svg, "polyline");
  REQUIRE(lines.size() == 50);
  auto ends = [](const std::string& points) {
    return std::make_pair(points.substr(0, points.find(' ')), points.substr(points.rfind(' ') + 1));
  };
  CHECK(ends(attribute(lines.front(), "points")).first == "400,300");
  CHECK(ends(attribute(lines.back(), "points")).second == "460,240");
  for (size_t i = 1; i < lines.size(); ++i) {
    INFO("polyline " << i);
    CHECK(ends(attribute(lines[i], "points")).first == ends(attribute(lines[i - 1], "points")).second);
    CHECK(attribute(lines[i], "stroke") == attribute(lines[0], "stroke"));
    CHECK(attribute(lines[i], "stroke-width") == "4");
  }
}

TEST_CASE("svg: a square driven 1000 times round is about the size of one lap", "[render][svg]") {
  auto program = [](int laps) {
    return "rLocate 400, 300\nrInvisible GREEN\nLineWidth 3\nrPen DOWN\nfor i = 1 to " +
           std::to_string(laps) + "\n  for s = 1 to 4\n    rForward 150\n    rTurn 90\n  next\nnext\n";
  };
  auto one = test::runForPicture(program(1));
  auto many = test::runForPicture(program(1000));
  REQUIRE(one->result.status == RunStatus::Finished);
  REQUIRE(many->result.status == RunStatus::Finished);
  const std::string svgOne = renderSvg(one->canvas(), one->robot(), 1);
  const std::string svgMany = renderSvg(many->canvas(), many->robot(), 1);
  CHECK(svgMany.size() < svgOne.size() + 200);
  // The polylines stroke the same segments (round caps and joins: the same picture), and the
  // pixels are the same.
  auto segments = [](const std::string& svg) {
    std::set<std::string> out;
    for (const std::string& line : elements(svg, "polyline")) {
      CHECK(attribute(line, "stroke-width") == "3");
      std::istringstream in(attribute(line, "points"));
      std::vector<std::string> pts{std::istream_iterator<std::string>(in), {}};
      for (size_t i = 0; i + 1 < pts.size(); ++i) out.insert(std::min(pts[i], pts[i + 1]) + " " + std::max(pts[i], pts[i + 1]));
    }
    return out;
  };
  CHECK(segments(svgMany) == segments(svgOne));
  CHECK(segments(svgOne).size() == 4);
  CHECK(many->canvas().pixels() == one->canvas().pixels());
}

TEST_CASE("svg: the same program and seed give byte-identical SVG", "[render][svg]") {
  std::string program = test::readText(test::sourceRoot() / "examples" / "fig_1_7.bas") +
                        "circle 10, 10, 90, 50, RED, YELLOW\nxyText 100, 500, \"same\", \"Arial\", 20\n"
                        "rLocate 600, 100, 30\nrForward 37\nrTurn 45\nrForward 21\n";
  CHECK(svgOf(program) == svgOf(program));
}

TEST_CASE("svg: shapes keep the canvas's pixel geometry", "[render][svg]") {
  SECTION("a rectangle's outline lies inside its box") {
    std::string svg = svgOf("rectangle 10, 10, 50, 30\nlineWidth 4\nrectangle 100, 100, 199, 149, RED, YELLOW\n");
    CHECK_THAT(svg, Catch::Contains("<rect x=\"10.5\" y=\"10.5\" width=\"40\" height=\"20\" fill=\"none\" "
                                    "stroke=\"#000000\" stroke-width=\"1\"/>"));
    CHECK_THAT(svg, Catch::Contains("<rect x=\"102\" y=\"102\" width=\"96\" height=\"46\" fill=\"#ffff00\" "
                                    "stroke=\"#ff0000\" stroke-width=\"4\"/>"));
  }
  SECTION("a filled rectangle, and one whose outline is as wide as the box") {
    std::string svg = svgOf("rectangle 5, 6, 14, 25, GREEN, GREEN\nlineWidth 6\nrectangle 25, 6, 34, 25\n");
    CHECK_THAT(svg, Catch::Contains("<rect x=\"5.5\" y=\"6.5\" width=\"9\" height=\"19\" fill=\"#008000\" "
                                    "stroke=\"#008000\" stroke-width=\"1\"/>"));
    CHECK_THAT(svg, Catch::Contains("<rect x=\"25\" y=\"6\" width=\"10\" height=\"20\" fill=\"#000000\"/>"));
  }
  SECTION("an ellipse, a line, a pixel") {
    std::string svg = svgOf("circle 100, 100, 200, 150, BLUE\nline 0, 0, 10, 20, 3, RED\nsetPixel 7, 8, CYAN\n");
    CHECK_THAT(svg, Catch::Contains("<ellipse cx=\"150.5\" cy=\"125.5\" rx=\"50\" ry=\"25\" fill=\"none\" "
                                    "stroke=\"#0000ff\" stroke-width=\"1\"/>"));
    CHECK_THAT(svg, Catch::Contains("<line x1=\"0.5\" y1=\"0.5\" x2=\"10.5\" y2=\"20.5\" stroke=\"#ff0000\" "
                                    "stroke-width=\"3\""));
    CHECK_THAT(svg, Catch::Contains("<rect x=\"7\" y=\"8\" width=\"1\" height=\"1\" fill=\"#008080\"/>"));
  }
  SECTION("text: the named face, escaped, Latin-1 as Unicode, with its background") {
    std::string svg = svgOf("xyText 10, 20, \"a<b & \" + char(233), \"Courier\", 12, \"u\", RED, YELLOW\n"
                            "xyText 10, 100, \"Hi\", \"Times New Roman\", 10, fs_Bold + fs_Italic + fs_StrikeOut\n");
    std::vector<std::string> texts = elements(svg, "text");
    REQUIRE(texts.size() == 2);
    CHECK(attribute(texts[0], "font-family") == "'Courier New', 'Liberation Mono', monospace");
    // 12 points are 16 pixels; Courier's cell is then 10 x 18 pixels, the baseline 13 down.
    CHECK(attribute(texts[0], "font-size") == "16");
    CHECK(attribute(texts[0], "x") == "10");
    CHECK(attribute(texts[0], "y") == "33");
    CHECK(attribute(texts[0], "textLength") == "70");
    CHECK(attribute(texts[0], "fill") == "#ff0000");
    CHECK(attribute(texts[0], "text-decoration") == "underline");
    CHECK_THAT(svg, Catch::Contains(">a&lt;b &amp; &#233;</text>"));
    // The yellow box behind the text comes first, as large as its cells.
    CHECK_THAT(svg, Catch::Contains("<rect x=\"10\" y=\"20\" width=\"70\" height=\"18\" fill=\"#ffff00\"/>"));
    CHECK(svg.find("fill=\"#ffff00\"") < svg.find("<text"));
    CHECK(attribute(texts[1], "font-family") == "'Times New Roman', 'Liberation Serif', serif");
    CHECK(attribute(texts[1], "font-size") == "13");
    CHECK(attribute(texts[1], "font-weight") == "bold");
    CHECK(attribute(texts[1], "font-style") == "italic");
    CHECK(attribute(texts[1], "text-decoration") == "line-through");
  }
  SECTION("RGB colours") {
    std::string svg = svgOf("line 1, 1, 100, 1, 1, RGB(18, 52, 86)\n");
    CHECK_THAT(svg, Catch::Contains("stroke=\"#123456\""));
  }
  SECTION("clearScr starts the picture over in its colour") {
    std::string svg = svgOf("line 1, 1, 100, 1\nclearScr GRAY\nline 5, 5, 9, 9, 1, RED\n");
    std::vector<std::string> rects = elements(svg, "rect");
    REQUIRE(rects.size() == 1);
    CHECK(attribute(rects[0], "fill") == "#c0c0c0");
    REQUIRE(elements(svg, "line").size() == 1);
  }
}

TEST_CASE("svg: after floodFill the picture is the embedded raster", "[render][svg]") {
  auto run = test::runForPicture("rectangle 100, 100, 300, 200\nfloodFill 150, 150, RED\nrLocate 600, 400\n");
  REQUIRE(run->loaded);
  std::string svg = renderSvg(run->canvas(), run->robot(), 1);
  CHECK_THAT(svg, Catch::Contains("<!-- The screen was changed in a way that has no vector form"));
  std::vector<std::string> images = elements(svg, "image");
  REQUIRE(images.size() == 1);
  CHECK(attribute(images[0], "width") == "800");
  CHECK(attribute(images[0], "height") == "600");
  // No vector shapes: the rectangle is in the image.
  CHECK(elements(svg, "rect").empty());
  // The robot stays a vector, above the image.
  REQUIRE(elements(svg, "circle").size() == 1);
  CHECK(svg.find("<circle") > svg.find("<image"));

  // The embedded PNG is the screen: decode it and look.
  std::string href = attribute(images[0], "xlink:href");
  const std::string prefix = "data:image/png;base64,";
  REQUIRE(href.rfind(prefix, 0) == 0);
  std::vector<uint8_t> png = base64Decode(href.substr(prefix.size()));
  test::TempFile file("embedded.png");
  std::string error;
  REQUIRE(writeFileBytes(file.str(), png.data(), png.size(), error));
  auto decoded = readPngFile(file.str(), error);
  INFO(error);
  REQUIRE(decoded);
  CHECK(decoded->width == 800);
  CHECK(decoded->pixel(150, 150) == 0xFF0000);
  CHECK(decoded->pixel(100, 150) == 0x000000);
  CHECK(decoded->pixel(50, 50) == 0xFFFFFF);
  // The robot is not in the raster.
  CHECK(decoded->pixel(600, 380) == 0xFFFFFF);
}

TEST_CASE("svg: scrolling print text also falls back to the raster", "[render][svg]") {
  auto run = test::runForPicture("for i = 1 to 50\n  print i\nnext\n");
  REQUIRE(run->loaded);
  CHECK(needsRaster(run->canvas().displayList()));
  CHECK(elements(renderSvg(run->canvas(), run->robot(), 1), "image").size() == 1);
  auto few = test::runForPicture("print 1\nprint 2\n");
  CHECK_FALSE(needsRaster(few->canvas().displayList()));
}

TEST_CASE("svg: --scale multiplies width and height, not the coordinates", "[render][svg]") {
  std::string svg = svgOf("line 0, 0, 10, 10\n", 2);
  CHECK_THAT(svg, Catch::Contains("width=\"1600\" height=\"1200\" viewBox=\"0 0 800 600\""));
  CHECK_THAT(svg, Catch::Contains("x2=\"10.5\""));
}

TEST_CASE("svg: base64", "[render][svg]") {
  auto b64 = [](const std::string& s) { return base64Encode(std::vector<uint8_t>(s.begin(), s.end())); };
  CHECK(b64("") == "");
  CHECK(b64("f") == "Zg==");
  CHECK(b64("fo") == "Zm8=");
  CHECK(b64("foo") == "Zm9v");
  CHECK(b64("foobar") == "Zm9vYmFy");
  CHECK(base64Decode(b64("any bytes \x01\xff")) == std::vector<uint8_t>{'a', 'n', 'y', ' ', 'b', 'y', 't', 'e', 's', ' ', 1, 0xff});
}

}  // namespace
}  // namespace rb::render
