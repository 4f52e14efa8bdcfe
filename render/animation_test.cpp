// Replays of a recorded run: every frame is the picture rb render writes for the run stopped at
// that statement; the GIF decoded back with giflib shows those frames with their delays, looping,
// in the RobotBASIC palette; frame sampling; the SVG's images put together give the last frame;
// the HTML page carries its data; errors.

#include "animation.h"

#include <catch2/catch.hpp>
#include <gif_lib.h>
#include <png.h>

#include <cstring>
#include <regex>

#include "render_test_support.h"

namespace rb::render {
namespace {

/// A host that feeds a recording as rb render's does, or stops the run before a statement.
class ReplayHost : public rb::test::TestHost {
 public:
  void onLine(SourceLoc loc) override {
    if (stopBefore && seen == *stopBefore) {
      requestStop();
      return;
    }
    ++seen;
    if (rec) rec->statement(loc, *machine);
  }
  void output(std::string_view text) override {
    TestHost::output(text);
    if (rec) rec->output(text);
  }
  std::optional<std::string> inputLine(std::string_view prompt) override {
    std::optional<std::string> line = TestHost::inputLine(prompt);
    if (line && rec) rec->input(*line);
    return line;
  }
  Recording* rec = nullptr;
  Machine* machine = nullptr;
  std::optional<uint64_t> stopBefore;
  uint64_t seen = 0;
};

class SensorFeed : public RobotObserver {
 public:
  explicit SensorFeed(Recording& r) : rec(r) {}
  void robotEvent(const RobotEvent& e) override { rec.robotEvent(e); }
  Recording& rec;
};

/// Runs `text` compiled with line tracing (as rb render --animate does) on `host`; returns the
/// machine after the run.
std::unique_ptr<Machine> runOn(const std::string& text, ReplayHost& host, RunLimits limits, RunResult& result,
                               RobotObserver* observer = nullptr) {
  rb::test::MemoryReader reader;
  reader.files["test.bas"] = text;
  DiagnosticList diags;
  auto loaded = loadProgram("test.bas", text, reader, standardBuiltins(), {}, diags);
  CompileOptions compile;
  compile.lineTracing = true;
  auto program = compileProgram(*loaded, compile, diags);
  REQUIRE(program);
  auto machine = std::make_unique<Machine>(host, 1);
  host.machine = machine.get();
  machine->setObserver(observer);
  Interpreter interp(*program, *machine);
  result = interp.run(limits);
  return machine;
}

std::unique_ptr<Recording> record(const std::string& text, RunLimits limits = {},
                                  size_t budget = Recording::kDefaultBudget) {
  auto rec = std::make_unique<Recording>(budget);
  ReplayHost host;
  host.rec = rec.get();
  SensorFeed feed(*rec);
  RunResult result;
  auto machine = runOn(text, host, limits, result, &feed);
  rec->finish(*machine, result);
  return rec;
}

/// The picture rb render writes (composeImage of the shown screen and the robot) for the run
/// stopped just before statement `stopBefore` (0-based), or at its end.
RgbImage pictureAt(const std::string& text, std::optional<uint64_t> stopBefore, int scale = 1, RunLimits limits = {}) {
  ReplayHost host;
  host.stopBefore = stopBefore;
  RunResult result;
  auto machine = runOn(text, host, limits, result);
  return composeImage(machine->shownScreen(), robotView(*machine), scale);
}

/// Where two images differ first ("" when they are the same).
std::string difference(const RgbImage& a, const RgbImage& b) {
  if (a.width != b.width || a.height != b.height)
    return "sizes " + std::to_string(a.width) + "x" + std::to_string(a.height) + " and " +
           std::to_string(b.width) + "x" + std::to_string(b.height);
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      if (a.pixel(x, y) != b.pixel(x, y)) {
        char buf[96];
        std::snprintf(buf, sizeof buf, "pixel (%d, %d): %06x and %06x", x, y, a.pixel(x, y), b.pixel(x, y));
        return buf;
      }
  return "";
}

struct DecodedGif {
  int width = 0, height = 0;
  std::vector<uint32_t> map;      ///< the global colour map, 0xRRGGBB
  std::vector<RgbImage> frames;   ///< the picture after each image
  std::vector<int> delays;        ///< hundredths of a second
  std::vector<PixelBox> boxes;    ///< each image's rectangle
  bool loops = false;             ///< NETSCAPE2.0, looping for ever
  bool gif89 = false;
};

/// Decodes a GIF with giflib (DGifSlurp) and puts its images together as a viewer does.
DecodedGif decodeGif(const std::vector<uint8_t>& bytes) {
  struct Source {
    const std::vector<uint8_t>* bytes;
    size_t at = 0;
  } source{&bytes};
  auto read = [](GifFileType* gif, GifByteType* out, int n) -> int {
    auto* s = static_cast<Source*>(gif->UserData);
    const size_t take = std::min(static_cast<size_t>(n), s->bytes->size() - s->at);
    std::memcpy(out, s->bytes->data() + s->at, take);
    s->at += take;
    return static_cast<int>(take);
  };
  int error = 0;
  GifFileType* gif = DGifOpen(&source, read, &error);
  REQUIRE(gif);
  REQUIRE(DGifSlurp(gif) == GIF_OK);
  DecodedGif out;
  out.width = gif->SWidth;
  out.height = gif->SHeight;
  out.gif89 = std::string(DGifGetGifVersion(gif)) == "89a";
  REQUIRE(gif->SColorMap);
  for (int i = 0; i < gif->SColorMap->ColorCount; ++i) {
    const GifColorType& c = gif->SColorMap->Colors[i];
    out.map.push_back(static_cast<uint32_t>(c.Red) << 16 | static_cast<uint32_t>(c.Green) << 8 | c.Blue);
  }
  RgbImage picture;
  picture.width = out.width;
  picture.height = out.height;
  picture.rgb.assign(static_cast<size_t>(out.width) * static_cast<size_t>(out.height) * 3, 0);
  for (int i = 0; i < gif->ImageCount; ++i) {
    const SavedImage& image = gif->SavedImages[i];
    for (int k = 0; k + 1 < image.ExtensionBlockCount; ++k) {
      const ExtensionBlock& e = image.ExtensionBlocks[k];
      if (e.Function == APPLICATION_EXT_FUNC_CODE && e.ByteCount == 11 && std::memcmp(e.Bytes, "NETSCAPE2.0", 11) == 0) {
        const ExtensionBlock& sub = image.ExtensionBlocks[k + 1];
        out.loops = sub.ByteCount == 3 && sub.Bytes[0] == 1 && sub.Bytes[1] == 0 && sub.Bytes[2] == 0;
      }
    }
    GraphicsControlBlock gcb{};
    REQUIRE(DGifSavedExtensionToGCB(gif, i, &gcb) == GIF_OK);
    CHECK(gcb.DisposalMode == DISPOSE_DO_NOT);
    CHECK(image.ImageDesc.ColorMap == nullptr);  // the global map only
    const GifImageDesc& d = image.ImageDesc;
    REQUIRE(d.Left + d.Width <= out.width);
    REQUIRE(d.Top + d.Height <= out.height);
    for (int y = 0; y < d.Height; ++y)
      for (int x = 0; x < d.Width; ++x) {
        const int index = image.RasterBits[y * d.Width + x];
        if (index == gcb.TransparentColor) continue;
        REQUIRE(index < static_cast<int>(out.map.size()));
        picture.set(d.Left + x, d.Top + y, out.map[static_cast<size_t>(index)]);
      }
    out.frames.push_back(picture);
    out.delays.push_back(gcb.DelayTime);
    out.boxes.push_back(PixelBox{d.Left, d.Top, d.Left + d.Width - 1, d.Top + d.Height - 1});
  }
  DGifCloseFile(gif, &error);
  return out;
}

/// Checks that the GIF shows frame k of `times` from its time on: each decoded image is the
/// frame whose time is its start (a frame that changed nothing added its time to the one before;
/// one too short to show came with the next). Every `sample`-th image is compared whole.
void checkGifTimes(const DecodedGif& gif, const Recording& rec, const FrameTimes& times, int scale, size_t sample) {
  long start = 0;
  size_t j = 0;
  for (size_t k = 0; k < gif.frames.size(); ++k) {
    while (j < times.steps.size() && std::lround(times.seconds[j] * 100) < start) ++j;
    INFO("image " << k << " from " << start << "/100 s");
    REQUIRE(j < times.steps.size());
    CHECK(std::lround(times.seconds[j] * 100) == start);
    if (k % sample == 0 || k + 1 == gif.frames.size()) {
      INFO("step " << times.steps[j] << ", part " << times.part[j] << " of " << times.parts[j]);
      CHECK(difference(gif.frames[k], glideImage(rec, times.steps[j], times.part[j], times.parts[j], scale)) == "");
    }
    start += gif.delays[k];
  }
}

std::string figure17() {
  std::string text = test::readText(test::sourceRoot() / "examples" / "fig_1_7.bas");
  REQUIRE_FALSE(text.empty());
  return text;
}

// A robot that roams: turns of 77 degrees and moves of 3 pixels put it off whole pixels.
const char* kRoam =
    "rLocate 400, 300\nrInvisible RED\nrPen DOWN\nfor i = 1 to 120\n"
    "  if rFeel() then rTurn 77 else rForward 3\n  if i % 40 = 0 then rTurn 33.3\nnext\n";

// flip on: the screen shown is the one at the last flip.
const char* kFlip =
    "flip on\nrLocate 100, 100\nrPen DOWN\nfor i = 1 to 4\n  clearScr\n  rectangle i * 50, 50, i * 50 + 40, 90, BLUE, "
    "RED\n  rForward 10\n  flip\nnext\n";

// Ends in a runtime error: the robot runs into the wall.
const char* kCrash = "rLocate 400, 60\nrPen DOWN\nLineWidth 3\nfor i = 1 to 20\n  rForward 10\nnext\n";

}  // namespace

TEST_CASE("a replay's frame is rb render's picture of the run stopped at that statement", "[render][animation]") {
  for (const std::string& text : {figure17(), std::string(kRoam), std::string(kFlip), std::string(kCrash)}) {
    auto rec = record(text);
    REQUIRE(rec->stepStride() == 1);
    const auto& steps = rec->steps();
    REQUIRE(steps.size() > 5);
    // Every step of the short ones; a spread of the roam's.
    const size_t every = steps.size() > 100 ? 7 : 1;
    for (size_t i = 0; i < steps.size(); i += every) {
      INFO(text.substr(0, 30) << "... step " << i << " (statement " << steps[i].step << ")");
      const bool end = i + 1 == steps.size();
      CHECK(difference(frameImage(*rec, i), pictureAt(text, end ? std::nullopt : std::optional(steps[i].step))) == "");
    }
    INFO(text.substr(0, 30));
    CHECK(difference(frameImage(*rec, steps.size() - 1), pictureAt(text, std::nullopt)) == "");
  }
  // Scaled.
  auto rec = record(kRoam);
  for (size_t i : {size_t{3}, rec->steps().size() / 2, rec->steps().size() - 1}) {
    INFO("step " << i);
    const bool end = i + 1 == rec->steps().size();
    CHECK(difference(frameImage(*rec, i, 3), pictureAt(kRoam, end ? std::nullopt : std::optional(rec->steps()[i].step), 3)) == "");
  }
}

TEST_CASE("frames: one per visible change, every N statements, or spread over a duration", "[render][animation]") {
  auto rec = record(figure17());
  const auto& steps = rec->steps();
  REQUIRE(steps.size() == 18);  // 17 statements and the end
  AnimationOptions options;
  options.glide = false;  // the glides: their own test case below
  std::vector<size_t> frames = animationFrames(*rec, options);
  // The blank screen, the robot placed, then after each of the 4 moves and 4 turns, and the
  // end; rInvisible, the pen and the line width change nothing that shows, nor do `next` and
  // the loop's start.
  CHECK(frames == std::vector<size_t>{0, 1, 6, 7, 9, 10, 12, 13, 15, 16, 17});
  for (size_t k = 1; k + 1 < frames.size(); ++k) {
    INFO("frame " << k);
    CHECK(difference(frameImage(*rec, frames[k]), frameImage(*rec, frames[k - 1])) != "");
  }
  FrameTimes times = animationTimes(*rec, options);
  REQUIRE(times.seconds.size() == frames.size());
  for (size_t k = 0; k < frames.size(); ++k) CHECK(times.seconds[k] == Approx(k / 10.0));

  SECTION("--every") {
    options.every = 4;
    CHECK(animationFrames(*rec, options) == std::vector<size_t>{0, 4, 8, 12, 16, 17});
    options.every = 1;
    CHECK(animationFrames(*rec, options).size() == 18);
    options.every = 1000;
    CHECK(animationFrames(*rec, options) == std::vector<size_t>{0, 17});
  }
  SECTION("--duration") {
    options.duration = 0.4;  // 5 frames at 10 a second over 17 statements: the step reached by each
    times = animationTimes(*rec, options);
    CHECK(times.steps == std::vector<size_t>{0, 4, 8, 12, 17});
    REQUIRE(times.seconds.size() == 5);
    CHECK(times.seconds.back() == Approx(0.4));
    options.duration = 10;  // more frames than statements: each step once, at its time
    times = animationTimes(*rec, options);
    CHECK(times.steps.size() == 18);
    CHECK(times.seconds.back() == Approx(10));
    CHECK(times.seconds[1] == Approx(0.6));  // step 1 shows once 1/17 of the time has passed
  }
  SECTION("capped at maxFrames, evenly, first and last kept") {
    auto roam = record(kRoam);
    AnimationOptions few;
    few.maxFrames = 25;
    std::vector<size_t> f = animationFrames(*roam, few);
    REQUIRE(f.size() == 25);
    CHECK(f.front() == 0);
    CHECK(f.back() == roam->steps().size() - 1);
    CHECK(std::is_sorted(f.begin(), f.end()));
    CHECK(std::adjacent_find(f.begin(), f.end()) == f.end());
    few.every = 1;
    f = animationFrames(*roam, few);
    REQUIRE(f.size() == 25);
    const size_t n = roam->steps().size() - 1;
    for (size_t k = 0; k < f.size(); ++k) CHECK(f[k] == (k * n + 12) / 24);
  }
  SECTION("a thinned recording: the kept steps") {
    auto big = record("x = 0\nfor i = 1 to 200000\n  x = x + 1\nnext\nrLocate 400, 300\n", {}, size_t{1} << 20);
    INFO("statements " << big->totalSteps() << ", bytes " << big->bytes());
    REQUIRE(big->stepStride() > 1);
    options.every = 1;
    options.maxFrames = 1000000;
    CHECK(animationFrames(*big, options).size() == big->steps().size());
    options.every = big->stepStride() * 10;
    std::vector<size_t> f = animationFrames(*big, options);
    for (size_t k = 0; k + 1 < f.size(); ++k) CHECK(big->steps()[f[k]].step % (big->stepStride() * 10) == 0);
  }
}

TEST_CASE("glides: long moves and turns in frames of their own, within the frames' limit", "[render][animation]") {
  auto rec = record(figure17());
  AnimationOptions options;
  const FrameTimes times = animationTimes(*rec, options);
  // Each step's own frame as without gliding, in order; before each side's end (step 6, 9..)
  // 11 frames of the 120-pixel move (10 pixels apart), before each turn's (step 7..) 5 of it.
  std::vector<size_t> own, want = {0, 1, 6, 7, 9, 10, 12, 13, 15, 16, 17};
  for (size_t k = 0; k < times.steps.size(); ++k)
    if (times.part[k] == 0) own.push_back(times.steps[k]);
  CHECK(own == want);
  CHECK(times.steps.size() == want.size() + 4 * 11 + 4 * 5);
  REQUIRE(times.part.size() == times.steps.size());
  REQUIRE(times.parts.size() == times.steps.size());
  size_t k = 0;
  while (times.steps[k] != 5) ++k;
  for (uint32_t j = 1; j < 12; ++j, ++k) {
    CHECK(times.steps[k] == 5);
    CHECK(times.part[k] == j);
    CHECK(times.parts[k] == 12);
  }
  CHECK(times.steps[k] == 6);  // the move's end: the step's own frame
  CHECK(times.part[k] == 0);
  bool turn = true;
  CHECK(glideExtent(*rec, 5, &turn) == Approx(120));
  CHECK_FALSE(turn);
  CHECK(glideExtent(*rec, 6, &turn) == Approx(90));
  CHECK(turn);
  CHECK(glideExtent(*rec, 2) == 0);  // LineWidth: nothing moves

  SECTION("the poses: on the move's segment, or turned part of the way") {
    for (uint32_t j = 1; j < 12; ++j) {
      const GlidePose p = glidePose(*rec, 5, j, 12);
      CHECK(p.x == 400);
      CHECK(p.y == Approx(300 - 10.0 * j));
      CHECK(p.dx == Approx(0).margin(1e-12));
      CHECK(p.dy == Approx(-1));
      CHECK(p.radius == 20);
    }
    for (uint32_t j = 1; j < 6; ++j) {
      const GlidePose p = glidePose(*rec, 6, j, 6);
      CHECK(p.x == 400);
      CHECK(p.y == 180);
      const double h = 15.0 * j * 3.141592653589793 / 180;
      CHECK(p.dx == Approx(std::sin(h)).margin(1e-12));
      CHECK(p.dy == Approx(-std::cos(h)).margin(1e-12));
    }
    // The short way round: from 270 to 0 turns +90, from 0 to 270 turns -90.
    auto left = record("rLocate 400, 300, 270\nrTurn 90\nrTurn -90\n");
    CHECK(glidePose(*left, 1, 1, 2).dx == Approx(-std::sqrt(0.5)));
    CHECK(glidePose(*left, 1, 1, 2).dy == Approx(-std::sqrt(0.5)));
    CHECK(glidePose(*left, 2, 1, 2).dx == Approx(-std::sqrt(0.5)));
  }
  SECTION("the pictures: the ends are the steps', the trail drawn up to the robot") {
    CHECK(difference(glideImage(*rec, 5, 0, 12), frameImage(*rec, 5)) == "");
    CHECK(difference(glideImage(*rec, 5, 12, 12), frameImage(*rec, 6)) == "");
    const RgbImage half = glideImage(*rec, 5, 6, 12);  // the robot at (400, 240)
    auto at = [](const RgbImage& im, int x, int y) {
      const size_t i = (static_cast<size_t>(y) * static_cast<size_t>(im.width) + static_cast<size_t>(x)) * 3;
      return static_cast<uint32_t>(im.rgb[i]) << 16 | static_cast<uint32_t>(im.rgb[i + 1]) << 8 | im.rgb[i + 2];
    };
    const uint32_t green = colourToRgb(colours::kGreen), white = 0xFFFFFF, blue = colourToRgb(colours::kBlue);
    CHECK(at(half, 400, 290) == green);  // behind the robot: drawn
    CHECK(at(half, 401, 265) == green);
    CHECK(at(half, 400, 210) == white);  // ahead of it: not yet
    CHECK(at(frameImage(*rec, 6), 400, 210) == green);
    CHECK(at(half, 400, 240 + 19) == blue);  // the robot's rim, where it is now
    CHECK(at(half, 400, 300 + 19) == white);  // ... not where it was
    // Every pixel is the step's, the next step's or the robot's.
    const RgbImage a = frameImage(*rec, 5), b = frameImage(*rec, 6);
    for (size_t i = 0; i < half.rgb.size(); i += 3) {
      const uint32_t v = at(half, static_cast<int>(i / 3 % 800), static_cast<int>(i / 3 / 800));
      const uint32_t va = at(a, static_cast<int>(i / 3 % 800), static_cast<int>(i / 3 / 800));
      const uint32_t vb = at(b, static_cast<int>(i / 3 % 800), static_cast<int>(i / 3 / 800));
      if (v != va && v != vb && v != blue) FAIL("pixel " << i / 3 << " is " << v);
    }
    // At a scale, the same picture made larger.
    const RgbImage big = glideImage(*rec, 5, 6, 12, 2);
    CHECK(big.width == 1600);
    CHECK(at(big, 800, 580) == green);
    CHECK(at(big, 800, 420) == white);
  }
  SECTION("--no-glide, --every and --duration do not glide") {
    options.glide = false;
    CHECK(animationTimes(*rec, options).steps.size() == want.size());
    options.glide = true;
    options.every = 1;
    for (uint32_t part : animationTimes(*rec, options).part) CHECK(part == 0);
    options.every.reset();
    options.duration = 5;
    for (uint32_t part : animationTimes(*rec, options).part) CHECK(part == 0);
  }
  SECTION("within maxFrames: the glides' steps doubled until they fit, or none") {
    // 300 laps of a 100-pixel move and a half turn: 600 frames of their own, 6600 with glides of
    // 10 pixels and 15 degrees, 3300 of 20 and 30, 1800 of 40 and 60.
    auto laps = record("rLocate 400, 300\nfor i = 1 to 300\n  rForward 100\n  rTurn 180\nnext\n");
    AnimationOptions plain;
    plain.glide = false;
    const size_t base = animationTimes(*laps, plain).steps.size();
    CHECK(base == 603);  // the start, the robot placed, 600 moves and turns, the end
    const FrameTimes t = animationTimes(*laps, AnimationOptions{});
    CHECK(t.steps.size() == base + 300 * 2 + 300 * 2);
    CHECK(t.steps.size() <= 2000);
    for (size_t q = 0; q < t.steps.size(); ++q)
      if (t.part[q]) CHECK(t.parts[q] == 3);
    // Frames that fill maxFrames without glides: the same frames as without them.
    AnimationOptions tight;
    tight.maxFrames = base;
    plain.maxFrames = base;
    CHECK(animationTimes(*laps, tight).steps == animationTimes(*laps, plain).steps);
    tight.maxFrames = plain.maxFrames = 100;
    CHECK(animationTimes(*laps, tight).steps == animationTimes(*laps, plain).steps);
    for (uint32_t part : animationTimes(*laps, tight).part) CHECK(part == 0);
    // The GIF holds the frames' limit too.
    tight.maxFrames = 1300;  // glides of 80 pixels and 120 degrees: 1203 frames
    const FrameTimes few = animationTimes(*laps, tight);
    CHECK(few.steps.size() == 1203);
    CHECK(few.steps.size() > base);
    CHECK(decodeGif(encodeGif(*laps, tight)).frames.size() <= 1300);
  }
}

TEST_CASE("the GIF decoded with giflib: the frames, their delays, looping, the palette", "[render][animation]") {
  auto rec = record(figure17());
  AnimationOptions options;
  const std::vector<uint8_t> bytes = encodeGif(*rec, options);
  CHECK(bytes.size() < 200 * 1024);
  const DecodedGif gif = decodeGif(bytes);
  CHECK(std::string(bytes.begin(), bytes.begin() + 6) == "GIF89a");
  CHECK(gif.loops);
  CHECK(gif.width == 800);
  CHECK(gif.height == 600);
  REQUIRE(gif.map.size() >= 17);
  for (Colour c = 0; c < 16; ++c) CHECK(gif.map[c] == colourToRgb(c));
  const FrameTimes times = animationTimes(*rec, options);
  const std::vector<size_t>& frames = times.steps;
  // The end shows what the last turn left: the frame before it is held.
  REQUIRE(gif.frames.size() == frames.size() - 1);
  for (size_t k = 0; k < gif.frames.size(); ++k) {
    INFO("frame " << k << ", step " << frames[k] << ", part " << times.part[k] << " of " << times.parts[k]);
    // A step's frame is its picture; a glide's, glideImage's.
    CHECK(difference(gif.frames[k], times.part[k] ? glideImage(*rec, frames[k], times.part[k], times.parts[k])
                                                   : frameImage(*rec, frames[k])) == "");
    CHECK(gif.delays[k] == (k + 1 < gif.frames.size() ? 10 : 200));  // 10 a second; the last held 2 s
  }
  // After the first, each image is only the rectangle that changed.
  CHECK(gif.boxes[0].area() == 800L * 600);
  for (size_t k = 1; k < gif.boxes.size(); ++k) CHECK(gif.boxes[k].area() < 200L * 200);
  CHECK(difference(gif.frames.back(), pictureAt(figure17(), std::nullopt)) == "");

  SECTION("another fps, a scale, a hold") {
    auto roam = record(kRoam);
    options.fps = 30;  // 3 or 4 hundredths a frame
    options.hold = 0.5;
    options.scale = 2;
    const DecodedGif g = decodeGif(encodeGif(*roam, options));
    const FrameTimes roamTimes = animationTimes(*roam, options);
    CHECK(g.width == 1600);
    checkGifTimes(g, *roam, roamTimes, 2, 5);
    for (size_t k = 0; k + 1 < g.delays.size(); ++k) CHECK(g.delays[k] >= 3);
    CHECK(g.delays.back() == 50);
    CHECK(difference(g.frames.back(), pictureAt(kRoam, std::nullopt, 2)) == "");
  }
  SECTION("100 frames a second: none shorter than 2/100 s, the last frame the end") {
    auto roam = record(kRoam);
    options.fps = 100;
    const DecodedGif g = decodeGif(encodeGif(*roam, options));
    for (size_t k = 0; k + 1 < g.delays.size(); ++k) CHECK(g.delays[k] >= 2);
    checkGifTimes(g, *roam, animationTimes(*roam, options), 1, 7);
    CHECK(difference(g.frames.back(), pictureAt(kRoam, std::nullopt)) == "");
  }
  SECTION("a run that ends in an error ends on that picture") {
    auto crash = record(kCrash);
    REQUIRE(crash->status() == RunStatus::RuntimeError);
    const DecodedGif g = decodeGif(encodeGif(*crash, options));
    CHECK(difference(g.frames.back(), pictureAt(kCrash, std::nullopt)) == "");
  }
}

TEST_CASE("a GIF of more than 255 colours shows the others as the nearest in its map", "[render][animation]") {
  // 400 shades of red: the palette, the 239 most used others, then the nearest.
  auto rec = record("for i = 0 to 399\n  c = RGB(i % 256, i / 2, 0)\n  rectangle (i % 40) * 20, (i / 40) * 20, "
                    "(i % 40) * 20 + 20, (i / 40) * 20 + 20, c, c\nnext\n");
  AnimationOptions options;
  const DecodedGif gif = decodeGif(encodeGif(*rec, options));
  REQUIRE(gif.map.size() == 256);
  for (Colour c = 0; c < 16; ++c) CHECK(gif.map[c] == colourToRgb(c));
  const RgbImage exact = frameImage(*rec, rec->steps().size() - 1);
  const RgbImage& shown = gif.frames.back();
  auto distance = [](uint32_t a, uint32_t b) {
    long d = 0;
    for (int s : {16, 8, 0}) {
      const long e = static_cast<long>((a >> s) & 255) - static_cast<long>((b >> s) & 255);
      d += e * e;
    }
    return d;
  };
  const std::vector<uint32_t> colours(gif.map.begin(), gif.map.begin() + 255);  // the last is transparent
  int off = 0;
  for (int y = 0; y < 200; y += 5)
    for (int x = 0; x < 800; x += 5) {
      const uint32_t want = exact.pixel(x, y), got = shown.pixel(x, y);
      if (want == got) continue;
      ++off;
      INFO("pixel " << x << ", " << y);
      for (uint32_t c : colours) REQUIRE(distance(want, c) >= distance(want, got));
    }
  CHECK(off > 0);
}

TEST_CASE("the animated SVG: the first frame whole, then the parts that changed, the last frame stays",
          "[render][animation]") {
  auto rec = record(kRoam);
  AnimationOptions options;
  options.maxFrames = 40;
  const std::string svg = animatedSvg(*rec, options);
  CHECK(svg.rfind("<?xml", 0) == 0);
  CHECK(svg.find("<script") == std::string::npos);
  CHECK(svg.find("@keyframes") != std::string::npos);
  // Well-formed XML: a comment holds no "--".
  for (size_t at = svg.find("<!--"); at != std::string::npos; at = svg.find("<!--", at + 4))
    CHECK(svg.substr(at + 4, svg.find("-->", at) - at - 4).find("--") == std::string::npos);
  // Put the images together in order, as a browser shows them once all have appeared: each
  // after the first at a later time, its opaque pixels over what is there.
  const std::regex image(R"re(<image( class="f" style="animation-delay:([0-9.]+)s")? x="(\d+)" y="(\d+)" width="(\d+)" height="(\d+)" xlink:href="data:image/png;base64,([A-Za-z0-9+/=]+)"/>)re");
  RgbImage picture;
  picture.width = 800;
  picture.height = 600;
  picture.rgb.assign(800 * 600 * 3, 0);
  int count = 0;
  double lastDelay = -1;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), image); it != std::sregex_iterator(); ++it) {
    const std::smatch& m = *it;
    CHECK(m[1].matched == (count > 0));
    if (count > 0) {
      const double delay = std::stod(m[2].str());
      CHECK(delay > lastDelay);
      lastDelay = delay;
    }
    std::vector<uint8_t> bytes;
    uint32_t acc = 0;
    int bits = 0;
    for (char c : m[7].str()) {
      if (c == '=') break;
      const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
      acc = acc << 6 | static_cast<uint32_t>(std::strchr(digits, c) - digits);
      bits += 6;
      if (bits >= 8) {
        bits -= 8;
        bytes.push_back(static_cast<uint8_t>(acc >> bits));
      }
    }
    png_image png;
    std::memset(&png, 0, sizeof png);
    png.version = PNG_IMAGE_VERSION;
    REQUIRE(png_image_begin_read_from_memory(&png, bytes.data(), bytes.size()));
    png.format = PNG_FORMAT_RGBA;
    std::vector<uint8_t> rgba(PNG_IMAGE_SIZE(png));
    REQUIRE(png_image_finish_read(&png, nullptr, rgba.data(), 0, nullptr));
    const int x0 = std::stoi(m[3].str()), y0 = std::stoi(m[4].str());
    REQUIRE(static_cast<int>(png.width) == std::stoi(m[5].str()));
    REQUIRE(static_cast<int>(png.height) == std::stoi(m[6].str()));
    for (int y = 0; y < static_cast<int>(png.height); ++y)
      for (int x = 0; x < static_cast<int>(png.width); ++x) {
        const uint8_t* p = rgba.data() + (static_cast<size_t>(y) * png.width + static_cast<size_t>(x)) * 4;
        REQUIRE((p[3] == 0 || p[3] == 255));  // nothing half transparent: the pixels stay exact
        if (p[3] == 255) picture.set(x0 + x, y0 + y, static_cast<uint32_t>(p[0]) << 16 | static_cast<uint32_t>(p[1]) << 8 | p[2]);
      }
    ++count;
  }
  CHECK(count > 10);
  CHECK(count <= 40);
  CHECK(difference(picture, pictureAt(kRoam, std::nullopt)) == "");
  CHECK(lastDelay == Approx((animationFrames(*rec, options).size() - 1) / 10.0));
}

TEST_CASE("the HTML player is one page with its data inline", "[render][animation]") {
  auto rec = record(std::string(kCrash) + "print \"never\"\n");
  PlayerSource source{"crash </script> & <b>.bas", "rLocate 400, 60\n...", 0};
  AnimationOptions options;
  const std::string html = htmlPlayer(*rec, source, options);
  CHECK(html.rfind("<!DOCTYPE html>", 0) == 0);
  CHECK(html.find("src=") == std::string::npos);   // nothing loaded from elsewhere
  CHECK(html.find("http") == std::string::npos);
  CHECK(html.find("<title>crash &lt;/script&gt; &amp; &lt;b&gt;.bas") != std::string::npos);
  // The metadata: the program's name escaped for <script>, how the run ended.
  const size_t meta = html.find("<script type=\"application/json\" id=\"rb-meta\">");
  REQUIRE(meta != std::string::npos);
  const std::string json = html.substr(meta, html.find("</script>", meta) - meta);
  CHECK(json.find("\"name\":\"crash \\u003c/script> & \\u003cb>.bas\"") != std::string::npos);
  CHECK(json.find("\"status\":\"runtime error\"") != std::string::npos);
  CHECK(json.find("\"error\":{\"file\":0,\"line\":5,") != std::string::npos);
  CHECK(json.find("\"steps\":" + std::to_string(rec->steps().size()) + ",") != std::string::npos);
  CHECK(json.find("\"frames\":" + std::to_string(rec->frames().size()) + ",") != std::string::npos);
  // One script element of code, the data in two that do not run.
  size_t scripts = 0;
  for (size_t at = html.find("<script"); at != std::string::npos; at = html.find("<script", at + 1)) ++scripts;
  CHECK(scripts == 3);
}

TEST_CASE("writeAnimation: the format from the extension, errors that name the file", "[render][animation]") {
  auto rec = record(figure17());
  PlayerSource source{"fig_1_7.bas", figure17(), 0};
  AnimationOptions options;
  std::string error;
  CHECK(animationFormat("a.GIF") == "gif");
  CHECK(animationFormat("a.Htm") == "html");
  CHECK(animationFormat("a.svg") == "svg");
  CHECK(animationFormat("a.png") == "");
  CHECK(animationFormat("gif") == "");
  CHECK_FALSE(writeAnimation("replay.mp4", *rec, source, options, error));
  CHECK(error == "cannot tell the format of 'replay.mp4': the name must end in .gif, .svg or .html");
  CHECK_FALSE(writeAnimation("/nonexistent-rb-folder/replay.gif", *rec, source, options, error));
  CHECK(error.find("cannot write '/nonexistent-rb-folder/replay.gif': ") == 0);
  for (const char* name : {"replay.gif", "replay.svg", "replay.html"}) {
    test::TempFile file(name);
    INFO(name);
    CHECK(writeAnimation(file.str(), *rec, source, options, error));
    CHECK(std::filesystem::file_size(file.str()) > 1000);
  }
  Recording empty;
  CHECK_THROWS_AS(encodeGif(empty, options), std::runtime_error);
  CHECK(animationFrames(empty, options).empty());
}

}  // namespace rb::render
