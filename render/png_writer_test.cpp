// The PNG picture: the seed's Figure 1.7 decoded back from a written file, the robot on top,
// scaling, determinism and write errors.

#include <catch2/catch.hpp>

#include "png_writer.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include "render_test_support.h"

namespace rb::render {
namespace {

constexpr uint32_t kGreenRgb = 0x008000;  // colour 2, the pen of Figure 1.7
constexpr uint32_t kBlueRgb = 0x0000FF;   // colour 1, the robot's default colour
constexpr uint32_t kWhiteRgb = 0xFFFFFF;

std::unique_ptr<test::PictureRun> runFigure17() {
  std::string text = test::readText(test::sourceRoot() / "examples" / "fig_1_7.bas");
  REQUIRE_FALSE(text.empty());
  auto run = test::runForPicture(text);
  INFO(run->diagnostics);
  REQUIRE(run->loaded);
  REQUIRE(run->result.status == RunStatus::Finished);
  return run;
}

/// Checks the square of Figure 1.7 in an image of the screen at scale 1. `robotOnTop`: the
/// robot sits on the corner (400, 300), so that corner is checked beside the robot's lines.
void checkSquare(const RgbImage& img, bool robotOnTop) {
  REQUIRE(img.width == 800);
  REQUIRE(img.height == 600);
  // The four corners.
  if (!robotOnTop) CHECK(img.pixel(400, 300) == kGreenRgb);
  CHECK(img.pixel(398, 300) == kGreenRgb);  // the same corner's round brush, off the robot's lines
  CHECK(img.pixel(400, 180) == kGreenRgb);
  CHECK(img.pixel(520, 180) == kGreenRgb);
  CHECK(img.pixel(520, 300) == kGreenRgb);
  // Along the sides (the robot's outline crosses the sides 20 pixels from its centre).
  for (int t = 190; t <= 270; t += 10) {
    INFO("t = " << t);
    CHECK(img.pixel(400, t) == kGreenRgb);        // left side
    CHECK(img.pixel(520, t) == kGreenRgb);        // right side
    CHECK(img.pixel(t + 220, 180) == kGreenRgb);  // top side
    CHECK(img.pixel(t + 240, 300) == kGreenRgb);  // bottom side
  }
  // The lines are 4 pixels wide: the brush covers x - 2 .. x + 1.
  for (int x = 398; x <= 401; ++x) CHECK(img.pixel(x, 240) == kGreenRgb);
  CHECK(img.pixel(397, 240) == kWhiteRgb);
  CHECK(img.pixel(402, 240) == kWhiteRgb);
  for (int x = 518; x <= 521; ++x) CHECK(img.pixel(x, 240) == kGreenRgb);
  CHECK(img.pixel(517, 240) == kWhiteRgb);
  CHECK(img.pixel(522, 240) == kWhiteRgb);
  for (int y = 178; y <= 181; ++y) CHECK(img.pixel(460, y) == kGreenRgb);
  CHECK(img.pixel(460, 177) == kWhiteRgb);
  CHECK(img.pixel(460, 182) == kWhiteRgb);
  // Inside and outside the square: the background.
  CHECK(img.pixel(460, 240) == kWhiteRgb);
  CHECK(img.pixel(100, 100) == kWhiteRgb);
  CHECK(img.pixel(600, 400) == kWhiteRgb);
}

TEST_CASE("png: Figure 1.7 draws a green square with 4-pixel sides", "[render][png]") {
  auto run = runFigure17();
  SECTION("the screen's pixels, through a file") {
    RgbImage screen = screenImage(run->canvas().pixels(), 1);
    checkSquare(screen, false);
    test::TempFile file("fig_1_7_screen.png");
    std::string error;
    REQUIRE(writePngFile(file.str(), screen, error));
    std::optional<RgbImage> decoded = readPngFile(file.str(), error);
    INFO(error);
    REQUIRE(decoded);
    checkSquare(*decoded, false);
  }
  SECTION("the written file, decoded, with the robot on top") {
    RgbImage composed = composeImage(run->canvas().pixels(), run->robot(), 1);
    test::TempFile file("fig_1_7.png");
    std::string error;
    REQUIRE(writePngFile(file.str(), composed, error));
    std::optional<RgbImage> decoded = readPngFile(file.str(), error);
    INFO(error);
    REQUIRE(decoded);
    CHECK(decoded->rgb == composed.rgb);
    checkSquare(*decoded, true);
    // The robot ends where it started, at (400, 300) heading up, radius 20, blue: its heading
    // line runs up from the centre, 3 pixels wide (x 399..401); its outline is the ring of
    // pixels 17 to 20 pixels from the centre (3 pixels: 18, 19, 20 on the axes).
    CHECK(decoded->pixel(400, 300) == kBlueRgb);
    CHECK(decoded->pixel(400, 290) == kBlueRgb);
    CHECK(decoded->pixel(399, 290) == kBlueRgb);
    CHECK(decoded->pixel(401, 290) == kBlueRgb);
    CHECK(decoded->pixel(402, 290) == kWhiteRgb);  // beside the heading line (x 398 is the square's side)
    CHECK(decoded->pixel(400, 281) == kBlueRgb);
    for (int d = 18; d <= 20; ++d) {
      INFO("d = " << d);
      CHECK(decoded->pixel(400 - d, 300) == kBlueRgb);
      CHECK(decoded->pixel(400, 300 + d) == kBlueRgb);
      CHECK(decoded->pixel(400 + d, 300) == kBlueRgb);
    }
    CHECK(decoded->pixel(383, 300) == kWhiteRgb);  // inside the ring, off the heading line
    CHECK(decoded->pixel(379, 300) == kWhiteRgb);  // outside the rim
    CHECK(decoded->pixel(400, 316) == kWhiteRgb);
    CHECK(decoded->pixel(400, 321) == kWhiteRgb);
    CHECK(decoded->pixel(390, 300) == kWhiteRgb);
    CHECK(decoded->pixel(410, 310) == kWhiteRgb);
  }
}

TEST_CASE("png: the robot's heading line follows headingVector (0 up, clockwise)", "[render][png]") {
  Pixels screen(static_cast<size_t>(Canvas::kWidth) * Canvas::kHeight, colours::kWhite);
  RobotView robot;
  robot.visible = true;
  robot.x = 200;
  robot.y = 200;
  robot.radius = 30;
  robot.colour = colours::kRed;
  robot.heading = 90;  // right
  RgbImage img = composeImage(screen, robot, 1);
  CHECK(img.pixel(215, 200) == 0xFF0000);
  CHECK(img.pixel(215, 199) == 0xFF0000);  // 3 pixels wide
  CHECK(img.pixel(215, 201) == 0xFF0000);
  CHECK(img.pixel(215, 202) == kWhiteRgb);
  CHECK(img.pixel(200, 185) == kWhiteRgb);
  robot.heading = 225;  // down-left
  img = composeImage(screen, robot, 1);
  CHECK(img.pixel(190, 210) == 0xFF0000);
  CHECK(img.pixel(215, 200) == kWhiteRgb);
  robot.visible = false;
  img = composeImage(screen, robot, 1);
  CHECK(img.pixel(190, 210) == kWhiteRgb);
  CHECK(img.pixel(170, 200) == kWhiteRgb);
}

TEST_CASE("png: --scale 2 doubles the picture, nearest neighbour", "[render][png]") {
  auto run = runFigure17();
  const Pixels& pixels = run->canvas().pixels();
  RgbImage one = screenImage(pixels, 1);
  RgbImage two = screenImage(pixels, 2);
  REQUIRE(two.width == 1600);
  REQUIRE(two.height == 1200);
  size_t mismatches = 0;
  for (int y = 0; y < two.height; ++y)
    for (int x = 0; x < two.width; ++x) mismatches += two.pixel(x, y) != one.pixel(x / 2, y / 2);
  CHECK(mismatches == 0);

  RgbImage composed = composeImage(pixels, run->robot(), 2);
  test::TempFile file("scale2.png");
  std::string error;
  REQUIRE(writePngFile(file.str(), composed, error));
  auto decoded = readPngFile(file.str(), error);
  REQUIRE(decoded);
  CHECK(decoded->width == 1600);
  CHECK(decoded->height == 1200);
  // The 4-pixel side is 8 pixels wide now; the robot's outline is still 3 screen pixels (6
  // image pixels) thick: screen x 380..383 minus the ring's inner edge, image x 761..766.
  for (int x = 796; x <= 803; ++x) CHECK(decoded->pixel(x, 480) == kGreenRgb);
  CHECK(decoded->pixel(795, 480) == kWhiteRgb);
  CHECK(decoded->pixel(804, 480) == kWhiteRgb);
  for (int x = 761; x <= 766; ++x) CHECK(decoded->pixel(x, 601) == kBlueRgb);
  CHECK(decoded->pixel(760, 601) == kWhiteRgb);
  CHECK(decoded->pixel(767, 601) == kWhiteRgb);
}

TEST_CASE("png: the same screen always encodes to the same bytes", "[render][png]") {
  auto run = runFigure17();
  RgbImage img = composeImage(run->canvas().pixels(), run->robot(), 1);
  std::vector<uint8_t> a = encodePng(img), b = encodePng(img);
  REQUIRE(a.size() > 8);
  CHECK(a == b);
  const uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  CHECK(std::equal(signature, signature + 8, a.begin()));
  // A screen full of different colours needs more than the first guess of the buffer size.
  Pixels noise(static_cast<size_t>(Canvas::kWidth) * Canvas::kHeight);
  uint32_t state = 12345;
  for (Colour& c : noise) {
    state = state * 1664525u + 1013904223u;
    c = state >> 8;
  }
  RgbImage noisy = screenImage(noise, 1);
  test::TempFile file("noise.png");
  std::string error;
  REQUIRE(writePngFile(file.str(), noisy, error));
  auto decoded = readPngFile(file.str(), error);
  REQUIRE(decoded);
  CHECK(decoded->rgb == noisy.rgb);
}

namespace {

/// The colour type and bit depth an encoded PNG declares (its IHDR chunk comes first).
std::pair<int, int> typeAndDepth(const std::vector<uint8_t>& png) {
  REQUIRE(png.size() > 33);
  return {png[25], png[24]};
}

/// Encodes `img`, writes it, decodes it with libpng and checks every pixel.
std::vector<uint8_t> roundTrip(const RgbImage& img) {
  std::vector<uint8_t> bytes = encodePng(img);
  test::TempFile file("roundtrip.png");
  std::string error;
  REQUIRE(writePngFile(file.str(), img, error));
  std::optional<RgbImage> decoded = readPngFile(file.str(), error);
  INFO(error);
  REQUIRE(decoded);
  CHECK(decoded->width == img.width);
  CHECK(decoded->height == img.height);
  CHECK(decoded->rgb == img.rgb);
  return bytes;
}

/// A width x height image of `colours` different colours (each used at least once when there
/// are pixels enough), in runs of random lengths as a screen has them, or scattered.
RgbImage imageOfColours(int width, int height, size_t colours, bool runs, uint32_t seed) {
  RgbImage img;
  img.width = width;
  img.height = height;
  img.rgb.resize(static_cast<size_t>(width) * static_cast<size_t>(height) * 3);
  uint32_t state = seed;
  auto next = [&state] { return state = state * 1664525u + 1013904223u; };
  std::vector<uint32_t> palette;  // distinct: an odd multiplier is one-to-one modulo 2^24
  for (uint32_t i = 0; i < colours; ++i) palette.push_back(((i + seed) * 0x9E3779B1u) & 0xFFFFFF);
  size_t n = static_cast<size_t>(width) * static_cast<size_t>(height), left = 0;
  uint32_t c = palette[0];
  for (size_t i = 0; i < n; ++i) {
    if (i < palette.size()) c = palette[i];  // every colour once, first
    else if (!runs || left-- == 0) c = palette[next() % palette.size()], left = next() % 40;
    img.set(static_cast<int>(i % static_cast<size_t>(width)), static_cast<int>(i / static_cast<size_t>(width)), c);
  }
  return img;
}

}  // namespace

TEST_CASE("png: up to 256 colours as a palette of as few bits as hold them, more as RGB; the same pixels", "[render][png]") {
  constexpr int kPalette = 3, kRgb = 2;
  struct Case {
    size_t colours;
    int type, depth;
  };
  for (Case k : {Case{1, kPalette, 1}, Case{2, kPalette, 1}, Case{3, kPalette, 2}, Case{4, kPalette, 2},
                 Case{5, kPalette, 4}, Case{16, kPalette, 4}, Case{17, kPalette, 8}, Case{255, kPalette, 8},
                 Case{256, kPalette, 8}, Case{257, kRgb, 8}, Case{5000, kRgb, 8}}) {
    for (bool runs : {true, false})
      for (auto [w, h] : {std::pair{200, 150}, std::pair{37, 29}, std::pair{1, 300}, std::pair{300, 1}}) {
        if (static_cast<size_t>(w) * static_cast<size_t>(h) < k.colours) continue;
        INFO(k.colours << " colours, " << w << " x " << h << (runs ? ", in runs" : ", scattered"));
        const RgbImage img = imageOfColours(w, h, k.colours, runs, static_cast<uint32_t>(k.colours * 7 + w));
        const std::vector<uint8_t> png = roundTrip(img);
        CHECK(typeAndDepth(png) == std::pair{k.type, k.depth});
      }
  }
  SECTION("Figure 1.7 with the robot on top (white, green, blue): a palette of 2 bits") {
    auto run = runFigure17();
    const std::vector<uint8_t> png = roundTrip(composeImage(run->canvas().pixels(), run->robot(), 1));
    CHECK(typeAndDepth(png) == std::pair{kPalette, 2});  // white, green, blue
  }
  SECTION("a screen of a million colours, scaled: RGB") {
    Pixels noise(static_cast<size_t>(Canvas::kWidth) * Canvas::kHeight);
    uint32_t state = 99;
    for (Colour& c : noise) c = (state = state * 1664525u + 1013904223u) >> 12;
    const std::vector<uint8_t> png = roundTrip(screenImage(noise, 2));
    CHECK(typeAndDepth(png) == std::pair{kRgb, 8});
  }
}

TEST_CASE("png: an image without pixels is an error, not a crash", "[render][png]") {
  RgbImage empty;
  CHECK_THROWS_AS(encodePng(empty), std::runtime_error);
  RgbImage shortImage;
  shortImage.width = 10;
  shortImage.height = 10;
  shortImage.rgb.resize(20);
  CHECK_THROWS_AS(encodePng(shortImage), std::runtime_error);
}

TEST_CASE("png: write and read errors name the file", "[render][png]") {
  RgbImage img = screenImage(Pixels(static_cast<size_t>(Canvas::kWidth) * Canvas::kHeight, 0), 1);
  std::string error;
  CHECK_FALSE(writePngFile("/nonexistent-rb-dir/out.png", img, error));
  CHECK_THAT(error, Catch::Contains("/nonexistent-rb-dir/out.png"));
  error.clear();
  CHECK_FALSE(readPngFile("/nonexistent-rb-dir/in.png", error));
  CHECK_THAT(error, Catch::Contains("/nonexistent-rb-dir/in.png"));
  test::TempFile notPng("not_png.png");
  REQUIRE(writeFileBytes(notPng.str(), "hello", 5, error));
  error.clear();
  CHECK_FALSE(readPngFile(notPng.str(), error));
  CHECK_FALSE(error.empty());
}

}  // namespace
TEST_CASE("png: the screen as runs of one colour is composeImage's picture", "[render][png]") {
  for (const char* program : {"rLocate 400,300\nrInvisible GREEN\nLineWidth 4\nrPen DOWN\nfor n = 1 to 4\n"
                              "rForward 120\nrTurn 90\nnext\n",
                              "rLocate 20, 20, 45\nCircle 300, 300, 500, 400, RED, BLUE\nprint \"hello\"\n",
                              "rLocate 780, 580, 200, 20, RED\n", "print 1\n"}) {
    auto run = test::runForPicture(program);
    RgbImage image = composeImage(run->canvas().pixels(), run->robot(), 1);
    std::vector<ColourRun> runs = composeRuns(run->canvas().pixels(), run->robot());
    size_t total = 0;
    for (const ColourRun& r : runs) total += r.count;
    CHECK(total == 800u * 600u);
    RgbImage back = imageFromRuns(runs, 800, 600);
    CHECK(back.rgb == image.rgb);
  }
}

TEST_CASE("png: devices and FIFOs are written to, never replaced; links to files are replaced", "[render][png]") {
  test::TempFile target("written_target.txt");
  test::TempFile link("written_link.txt");
  std::string error;
  REQUIRE(writeFileBytes(target.str(), "old text", 8, error));
  // A link to a file is replaced, its target kept.
  REQUIRE(::symlink(target.str().c_str(), link.str().c_str()) == 0);
  REQUIRE(writeFileBytes(link.str(), "new", 3, error));
  struct stat st;
  REQUIRE(::lstat(link.str().c_str(), &st) == 0);
  CHECK(S_ISREG(st.st_mode));
  std::ifstream in(target.str());
  std::string text((std::istreambuf_iterator<char>(in)), {});
  CHECK(text == "old text");
  // A link to a device is written through and stays.
  ::unlink(link.str().c_str());
  REQUIRE(::symlink("/dev/null", link.str().c_str()) == 0);
  REQUIRE(writeFileBytes(link.str(), "x", 1, error));
  REQUIRE(::lstat(link.str().c_str(), &st) == 0);
  CHECK(S_ISLNK(st.st_mode));
  // A device: /dev/null takes the bytes and stays a device.
  REQUIRE(writeFileBytes("/dev/null", "x", 1, error));
  REQUIRE(::stat("/dev/null", &st) == 0);
  CHECK(S_ISCHR(st.st_mode));
  // A folder is refused.
  CHECK_FALSE(writeFileBytes("/tmp", "x", 1, error));
  CHECK(error.find("it is a folder") != std::string::npos);
  ::unlink(link.str().c_str());
}

}  // namespace rb::render

