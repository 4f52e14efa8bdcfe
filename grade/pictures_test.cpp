#include "pictures.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

using namespace rb::grade;
using rb::record::P2;
using rb::record::Region;
using rb::render::RgbImage;

namespace {

constexpr uint32_t kWhite = 0xFFFFFF;

/// An 800 x 600 screen of one colour.
RgbImage solid(uint32_t colour) {
  RgbImage img;
  img.width = 800;
  img.height = 600;
  img.rgb.resize(800 * 600 * 3);
  for (int y = 0; y < 600; ++y)
    for (int x = 0; x < 800; ++x) img.set(x, y, colour);
  return img;
}

/// A colour faded as the picture fades a screen: three quarters of the way to white.
uint32_t faded(uint32_t c) {
  auto f = [](uint32_t v) { return 255 - (255 - v) / 4; };
  return f(c >> 16 & 0xFF) << 16 | f(c >> 8 & 0xFF) << 8 | f(c & 0xFF);
}

/// How many pixels of rows y0..y1, columns x0..x1 have the colour exactly.
int count(const RgbImage& img, uint32_t colour, int x0, int y0, int x1, int y1) {
  int n = 0;
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) n += img.pixel(x, y) == colour ? 1 : 0;
  return n;
}
int countAll(const RgbImage& img, uint32_t colour) { return count(img, colour, 0, 0, img.width - 1, img.height - 1); }
int countLegend(const RgbImage& img, uint32_t colour) {
  return count(img, colour, 0, kArenaHeight, img.width - 1, img.height - 1);
}

/// Pixels of the box that differ between two pictures.
int differences(const RgbImage& a, const RgbImage& b, int x0, int y0, int x1, int y1) {
  int n = 0;
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) n += a.pixel(x, y) != b.pixel(x, y) ? 1 : 0;
  return n;
}

Region rect(double x1, double y1, double x2, double y2) {
  Region r;
  r.kind = Region::Rect;
  r.x1 = x1, r.y1 = y1, r.x2 = x2, r.y2 = y2;
  return r;
}
Region circle(double cx, double cy, double radius) {
  Region r;
  r.kind = Region::Circle;
  r.cx = cx, r.cy = cy, r.r = radius;
  return r;
}
Region polygon(std::vector<P2> points) {
  Region r;
  r.kind = Region::Polygon;
  r.points = std::move(points);
  return r;
}

const uint32_t kBackground = 0x000080, kStudentScreen = 0x800000;

/// Everything a picture can show: a square the solution drew, three sides of it by the student.
PictureInput everything() {
  PictureInput in;
  in.reference = {{{300, 400}, {300, 200}, {500, 200}, {500, 400}, {300, 400}}};
  in.student = {{{300, 400}, {300, 200}, {500, 200}, {500, 400}}};
  in.background = std::make_shared<const RgbImage>(solid(kBackground));
  in.studentScreen = std::make_shared<const RgbImage>(solid(kStudentScreen));
  in.referenceEnd = P2{300, 400};
  in.studentEnd = P2{500, 400};
  in.waypoints = {{300, 400}, {300, 200}, {500, 200}, {500, 400}, {300, 400}};
  in.regions = {{PictureRegion::Goal, rect(260, 360, 340, 440), "back home"},
                {PictureRegion::Avoid, circle(650, 300, 60), "the lamp"}};
  in.title = "class/off_by_one.bas";
  return in;
}

}  // namespace

TEST_CASE("pictures: the arena above a legend strip", "[grade][pictures]") {
  CHECK(kPictureWidth == 800);
  CHECK(kArenaHeight == 600);
  CHECK(kLegendHeight >= 50);
  CHECK(kLegendHeight <= 90);
  CHECK(kPictureHeight == kArenaHeight + kLegendHeight);
  for (bool studentView : {false, true}) {
    PictureInput in = everything();
    in.studentView = studentView;
    RgbImage img = feedbackPicture(in);
    CHECK(img.width == kPictureWidth);
    CHECK(img.height == kPictureHeight);
    CHECK(img.rgb.size() == static_cast<size_t>(kPictureWidth) * kPictureHeight * 3);
  }
  SECTION("nothing to show: a white arena and an empty legend") {
    RgbImage img = feedbackPicture(PictureInput{});
    CHECK(img.height == kPictureHeight);
    CHECK(count(img, kWhite, 0, 0, 799, kArenaHeight - 1) == 800 * kArenaHeight);
    CHECK(legendEntries(PictureInput{}).empty());
  }
}

TEST_CASE("pictures: the student's picture never shows the solution", "[grade][pictures]") {
  PictureInput in = everything();
  in.studentView = true;
  RgbImage img = feedbackPicture(in);
  // Neither the solution's trail nor its end circle, in the arena or the legend.
  CHECK(countAll(img, kReferenceColour) == 0);
  // Not the solution's screen: the student's own, faded.
  CHECK(countAll(img, faded(kBackground)) == 0);
  CHECK(img.pixel(700, 500) == faded(kStudentScreen));
  CHECK(count(img, faded(kStudentScreen), 0, 0, 799, kArenaHeight - 1) > 800 * 600 / 2);
  // The student's trail where the solution's side is missing: nothing but their screen there.
  CHECK(img.pixel(400, 400) == faded(kStudentScreen));
  for (const std::string& e : legendEntries(in)) CHECK(e.find("solution") == std::string::npos);

  SECTION("without the student's screen the ground is white") {
    in.studentScreen.reset();
    RgbImage white = feedbackPicture(in);
    CHECK(white.pixel(700, 500) == kWhite);
    CHECK(countAll(white, kReferenceColour) == 0);
    CHECK(countAll(white, faded(kBackground)) == 0);
  }
  SECTION("a solution with nothing of the student's: an empty arena") {
    PictureInput only;
    only.studentView = true;
    only.reference = in.reference;
    only.referenceEnd = in.referenceEnd;
    only.background = in.background;
    RgbImage none = feedbackPicture(only);
    CHECK(count(none, kWhite, 0, 0, 799, kArenaHeight - 1) == 800 * kArenaHeight);
    CHECK(legendEntries(only).empty());
  }
}

TEST_CASE("pictures: the teacher's picture shows the solution under the student's work", "[grade][pictures]") {
  PictureInput in = everything();
  RgbImage img = feedbackPicture(in);
  CHECK(img.pixel(700, 500) == faded(kBackground));
  CHECK(countAll(img, faded(kStudentScreen)) == 0);
  // The solution's band, with the student's line on top where they drew the same side.
  CHECK(img.pixel(400, 400) == kReferenceColour);   // the side the student missed
  CHECK(img.pixel(400, 403) == kReferenceColour);   // the band is wide
  CHECK(img.pixel(400, 200) == kStudentColour);
  CHECK(img.pixel(400, 203) == kReferenceColour);
  // The robots' end circles.
  CHECK(img.pixel(500 + 20, 400) == kStudentColour);
  PictureInput ends;
  ends.referenceEnd = P2{100, 100};
  ends.studentEnd = P2{200, 100};
  RgbImage circles = feedbackPicture(ends);
  CHECK(circles.pixel(100, 100 - 20) == kReferenceColour);
  CHECK(circles.pixel(200 - 20, 100) == kStudentColour);
  CHECK(circles.pixel(100, 100) == kWhite);
  CHECK(countLegend(img, kReferenceColour) > 0);
  CHECK(legendEntries(in) == std::vector<std::string>{"your trail", "where your robot ended", "the solution's trail",
                                                      "where the solution's robot ended", "waypoints, in order",
                                                      "reach: back home", "keep out: the lamp"});
}

TEST_CASE("pictures: the legend lists only what is drawn", "[grade][pictures]") {
  using Entries = std::vector<std::string>;
  PictureInput in;
  in.student = {{{100, 100}, {200, 100}}};
  CHECK(legendEntries(in) == Entries{"your trail"});
  RgbImage img = feedbackPicture(in);
  CHECK(countLegend(img, kStudentColour) > 0);
  CHECK(countLegend(img, kReferenceColour) == 0);
  CHECK(countLegend(img, kWaypointColour) == 0);
  CHECK(countLegend(img, kGoalColour) == 0);
  CHECK(countLegend(img, kAvoidColour) == 0);

  in.referenceEnd = P2{100, 100};
  CHECK(legendEntries(in) == Entries{"your trail", "where the solution's robot ended"});
  CHECK(countLegend(feedbackPicture(in), kReferenceColour) > 0);
  in.studentView = true;
  CHECK(legendEntries(in) == Entries{"your trail"});
  CHECK(countLegend(feedbackPicture(in), kReferenceColour) == 0);

  PictureInput marks;
  marks.waypoints = {{100, 100}};
  CHECK(legendEntries(marks) == Entries{"waypoint"});
  marks.waypoints.push_back({200, 200});
  marks.regions = {{PictureRegion::Avoid, circle(400, 300, 40), "puddle"}};
  CHECK(legendEntries(marks) == Entries{"waypoints, in order", "keep out: puddle"});
  img = feedbackPicture(marks);
  CHECK(countLegend(img, kWaypointColour) > 0);
  CHECK(countLegend(img, kAvoidColour) > 0);
  CHECK(countLegend(img, kGoalColour) == 0);
  CHECK(countLegend(img, kStudentColour) == 0);
  CHECK(countLegend(img, kReferenceColour) == 0);

  SECTION("regions without a label are named by their role, each role once") {
    PictureInput r;
    r.regions = {{PictureRegion::Goal, rect(10, 10, 50, 50), ""},
                 {PictureRegion::Goal, rect(100, 10, 150, 50), ""},
                 {PictureRegion::Avoid, circle(300, 300, 30), ""}};
    CHECK(legendEntries(r) == Entries{"goal regions", "area to avoid"});
    img = feedbackPicture(r);
    CHECK(countLegend(img, kGoalColour) > 0);
    CHECK(countLegend(img, kAvoidColour) > 0);
  }
  SECTION("the same label and role once") {
    PictureInput r;
    r.regions = {{PictureRegion::Goal, rect(10, 10, 50, 50), "dock"},
                 {PictureRegion::Goal, rect(100, 10, 150, 50), "dock"},
                 {PictureRegion::Avoid, rect(200, 10, 250, 50), "dock"}};
    CHECK(legendEntries(r) == Entries{"reach: dock", "keep out: dock"});
  }
  SECTION("too many named regions for the strip: named by their role only") {
    PictureInput r = everything();
    for (int k = 0; k < 8; ++k)
      r.regions.push_back({k % 2 ? PictureRegion::Avoid : PictureRegion::Goal,
                           rect(20 + 90 * k, 480, 90 + 90 * k, 560), "a rather long region name " + std::to_string(k)});
    Entries e = legendEntries(r);
    CHECK(e == Entries{"your trail", "where your robot ended", "the solution's trail",
                       "where the solution's robot ended", "waypoints, in order", "goal regions", "areas to avoid"});
    img = feedbackPicture(r);
    CHECK(countLegend(img, kGoalColour) > 0);
    CHECK(countLegend(img, kAvoidColour) > 0);
  }
  SECTION("labels are UTF-8 in and out") {
    PictureInput r;
    r.regions = {{PictureRegion::Avoid, circle(300, 300, 30), "caf\xC3\xA9"}};
    CHECK(legendEntries(r) == Entries{"keep out: caf\xC3\xA9"});
    r.regions[0].label = "caf\xE9";  // Latin-1 from a Windows file
    CHECK(legendEntries(r) == Entries{"keep out: caf\xC3\xA9"});
    r.regions[0].label = "5 \xE2\x82\xAC";  // beyond Latin-1: the fonts have no euro sign
    CHECK(legendEntries(r) == Entries{"keep out: 5 ?"});
  }
  SECTION("a long label is shortened") {
    PictureInput r;
    r.regions = {{PictureRegion::Goal, circle(300, 300, 30), std::string(5000, 'x')}};
    Entries e = legendEntries(r);
    REQUIRE(e.size() == 1);
    CHECK(e[0].rfind("reach: xxx", 0) == 0);
    CHECK(e[0].size() < 100);
    CHECK(e[0].substr(e[0].size() - 3) == "...");
    CHECK(feedbackPicture(r).height == kPictureHeight);
  }
}

TEST_CASE("pictures: legend text is written in the strip", "[grade][pictures]") {
  PictureInput in;
  in.student = {{{100, 100}, {200, 100}}};
  RgbImage one = feedbackPicture(in);
  in.studentEnd = P2{200, 100};
  RgbImage two = feedbackPicture(in);
  // Dark glyph pixels in the strip, more for two entries than for one.
  auto dark = [](const RgbImage& img) {
    int n = 0;
    for (int y = kArenaHeight + 1; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) n += (img.pixel(x, y) >> 8 & 0xFF) < 0x60 ? 1 : 0;
    return n;
  };
  CHECK(dark(one) > 100);
  CHECK(dark(two) > dark(one) + 200);
  CHECK(dark(feedbackPicture(PictureInput{})) == 0);
}

TEST_CASE("pictures: waypoints are numbered markers", "[grade][pictures]") {
  PictureInput in;
  in.waypoints = {{200, 200}, {600, 400}};
  RgbImage img = feedbackPicture(in);
  for (const P2& p : in.waypoints) {
    const int x = static_cast<int>(p.x), y = static_cast<int>(p.y);
    CHECK(img.pixel(x, y) == kWaypointColour);
    CHECK(img.pixel(x + 3, y) == kWaypointColour);
    CHECK(img.pixel(x + 12, y + 12) == kWhite);  // small: radius about 5
    // Its number beside it, in the same colour.
    const int marker = count(img, kWaypointColour, x - 6, y - 6, x + 6, y + 6);
    CHECK(count(img, kWaypointColour, x - 40, y - 40, x + 40, y + 40) > marker + 5);
  }
  CHECK(countAll(img, kWaypointColour) < 400);
  CHECK(img.pixel(400, 300) == kWhite);
}

TEST_CASE("pictures: regions outlined in their role's colour", "[grade][pictures]") {
  PictureInput in;
  in.regions = {{PictureRegion::Goal, rect(100, 100, 260, 200), ""},
                {PictureRegion::Avoid, circle(500, 300, 60), ""},
                {PictureRegion::Avoid, polygon({{300, 400}, {420, 420}, {340, 540}}), ""}};
  RgbImage img = feedbackPicture(in);
  // Outlines on the edges.
  CHECK(img.pixel(180, 100) == kGoalColour);
  CHECK(img.pixel(100, 150) == kGoalColour);
  CHECK(img.pixel(260, 150) == kGoalColour);
  CHECK(img.pixel(180, 200) == kGoalColour);
  CHECK(img.pixel(560, 300) == kAvoidColour);
  CHECK(img.pixel(500, 240) == kAvoidColour);
  CHECK(img.pixel(360, 410) == kAvoidColour);  // the polygon's edges
  CHECK(img.pixel(380, 480) == kAvoidColour);
  CHECK(img.pixel(320, 470) == kAvoidColour);
  // A goal lightly tinted inside; an area to avoid tinted and hatched; white around them.
  auto greenish = [](uint32_t c) { return c != kWhite && (c >> 8 & 0xFF) > (c >> 16 & 0xFF); };
  CHECK(greenish(img.pixel(150, 150)));
  auto orange = [&](int cx, int cy, int r) {
    int tint = 0, hatch = 0;
    for (int y = cy - r; y <= cy + r; ++y)
      for (int x = cx - r; x <= cx + r; ++x) {
        uint32_t c = img.pixel(x, y);
        bool warm = c != kWhite && (c >> 16 & 0xFF) > (c & 0xFF);
        tint += warm ? 1 : 0;
        hatch += warm && (c & 0xFF) < 0xC0 ? 1 : 0;  // much stronger than the tint
      }
    return std::pair{tint, hatch};
  };
  auto [circleTint, circleHatch] = orange(500, 300, 30);
  CHECK(circleTint == 61 * 61);
  CHECK(circleHatch > 61 * 61 / 20);
  CHECK(circleHatch < 61 * 61 / 3);
  auto [polyTint, polyHatch] = orange(350, 450, 8);
  CHECK(polyTint == 17 * 17);
  CHECK(polyHatch > 0);
  for (auto [x, y] : {std::pair{50, 50}, {300, 150}, {500, 380}, {300, 480}, {440, 420}, {700, 550}})
    CHECK(img.pixel(x, y) == kWhite);
  // Nothing of the regions in the legend beyond its swatches: goal and avoid, once each.
  CHECK(legendEntries(in) == std::vector<std::string>{"goal region", "areas to avoid"});
}

TEST_CASE("pictures: region labels and the title are written in the arena", "[grade][pictures]") {
  PictureInput plain;
  plain.regions = {{PictureRegion::Goal, rect(100, 100, 300, 220), ""},
                   {PictureRegion::Avoid, circle(550, 350, 80), ""}};
  PictureInput named = plain;
  named.regions[0].label = "parking";
  named.regions[1].label = "pond";
  RgbImage a = feedbackPicture(plain), b = feedbackPicture(named);
  // Each label inside its region, near its middle.
  CHECK(differences(a, b, 150, 140, 250, 180) > 30);
  CHECK(differences(a, b, 500, 330, 600, 370) > 30);
  CHECK(differences(a, b, 0, 0, 799, 99) == 0);
  CHECK(differences(a, b, 0, 400, 799, kArenaHeight - 1) == 0);

  PictureInput titled = plain;
  titled.title = "class/alice.bas";
  RgbImage t = feedbackPicture(titled);
  CHECK(differences(a, t, 0, 0, 200, 40) > 50);  // at the top left when nothing is there
  CHECK(differences(a, t, 0, 41, 799, kPictureHeight - 1) == 0);
  CHECK(t.pixel(5, 5) == kWhite);

  // Not over what the program printed at the top left: the next corner free of drawing.
  RgbImage printedScreen = solid(kWhite);
  for (int y = 0; y < 15; ++y)
    for (int x = 0; x < 120; ++x) printedScreen.set(x, y, 0x000000);
  titled.background = std::make_shared<const RgbImage>(std::move(printedScreen));
  PictureInput untitled = titled;
  untitled.title.clear();
  RgbImage printed = feedbackPicture(titled), bare = feedbackPicture(untitled);
  CHECK(differences(printed, bare, 0, 0, 399, 99) == 0);
  CHECK(differences(printed, bare, 600, 0, 799, 40) > 50);
}

TEST_CASE("pictures: nothing of the arena spills into the legend", "[grade][pictures]") {
  PictureInput inside;
  inside.student = {{{700, 500}, {700, 590}}};
  PictureInput outside;
  outside.student = {{{700, 500}, {700, 700}}};
  outside.studentEnd = P2{650, 610};
  inside.studentEnd = P2{650, 580};
  outside.regions = {{PictureRegion::Avoid, circle(400, 640, 80), ""}};
  inside.regions = {{PictureRegion::Avoid, circle(400, 500, 80), ""}};
  RgbImage a = feedbackPicture(inside), b = feedbackPicture(outside);
  CHECK(b.pixel(700, 599) == kStudentColour);
  CHECK(differences(a, b, 0, kArenaHeight, 799, kPictureHeight - 1) == 0);
}

TEST_CASE("pictures: trails at any angle, and dots", "[grade][pictures]") {
  PictureInput in;
  in.student = {{{100, 500}, {700, 200}}, {{50, 50}}};
  in.reference = {{{100, 100}, {400, 400}}, {{600, 500}}};
  RgbImage img = feedbackPicture(in);
  for (int k = 0; k <= 300; k += 10) {
    CHECK(img.pixel(100 + 2 * k, 500 - k) == kStudentColour);
    CHECK(img.pixel(100 + 2 * k, 500 - k - 5) != kStudentColour);  // a thin line
    CHECK(img.pixel(100 + 2 * k, 500 - k + 5) != kStudentColour);
    CHECK(img.pixel(100 + k, 100 + k) == kReferenceColour);
    CHECK(img.pixel(100 + k + 3, 100 + k) == kReferenceColour);  // a wide band
    CHECK(img.pixel(100 + k + 12, 100 + k) == kWhite);
  }
  CHECK(img.pixel(50, 50) == kStudentColour);  // a trail of one point: a dot
  CHECK(img.pixel(50, 54) == kWhite);
  for (auto [x, y] : {std::pair{596, 500}, {604, 500}, {600, 496}, {600, 504}, {597, 498}})
    CHECK(img.pixel(x, y) == kReferenceColour);  // a round dot as wide as the band
  CHECK(img.pixel(594, 500) != kReferenceColour);
  CHECK(img.pixel(100 - 3, 100 - 2) == kReferenceColour);  // round caps
  CHECK(img.pixel(100 - 4, 100) == kReferenceColour);
  // Solid along its whole length: at least one pixel a pixel of length, at most two.
  const int line = count(img, kStudentColour, 0, 0, 799, kArenaHeight - 1);
  INFO(line << " pixels in the student's colour");
  CHECK(line > 670);
  CHECK(line < 2 * 670 + 50);
}

TEST_CASE("pictures: a path driven again, and a painter used again, draw the same picture", "[grade][pictures]") {
  PictureInput once = everything();
  once.student = {{{300, 400}, {300, 200}, {500, 200}, {500, 400}, {300, 400}}};  // a closed square
  once.studentPath = once.student;
  PictureInput again = once;
  // Round the square five more times, in one polyline and in pieces of their own.
  for (int lap = 0; lap < 5; ++lap) {
    again.student[0].insert(again.student[0].end(), once.student[0].begin() + 1, once.student[0].end());
    again.studentPath.push_back(once.student[0]);
  }
  const RgbImage a = feedbackPicture(once);
  CHECK(differences(feedbackPicture(again), a, 0, 0, 799, kPictureHeight - 1) == 0);
  // One painter for a class: its fonts and glyphs kept from picture to picture change nothing.
  PicturePainter painter;
  PictureInput other = everything();
  other.studentView = true;
  other.title = "class/another name with other glyphs.bas";
  const RgbImage b = feedbackPicture(other);
  CHECK(differences(painter.picture(once), a, 0, 0, 799, kPictureHeight - 1) == 0);
  CHECK(differences(painter.picture(other), b, 0, 0, 799, kPictureHeight - 1) == 0);
  CHECK(differences(painter.picture(once), a, 0, 0, 799, kPictureHeight - 1) == 0);
  CHECK(painter.legend(other) == legendEntries(other));
}
