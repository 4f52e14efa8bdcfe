#include "similarity.h"

#include <unistd.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <algorithm>
#include <map>

using namespace rb::grade;
namespace fs = std::filesystem;

namespace {

/// A folder of its own for a test, removed with everything in it at the end of the test.
struct Scratch {
  fs::path dir;
  Scratch() {
    static int count = 0;
    dir = fs::temp_directory_path() /
          ("rb_similarity_test_" + std::to_string(getpid()) + "_" + std::to_string(++count));
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  ~Scratch() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
  Scratch(const Scratch&) = delete;
  Scratch& operator=(const Scratch&) = delete;
};

std::string write(const fs::path& dir, const std::string& name, const std::string& text) {
  fs::path p = dir / name;
  std::ofstream(p, std::ios::binary) << text;
  return p.string();
}

/// A student's square: lines 2-16 are code, line 17 is blank.
const char* kSquare =
    "// Square by Ana, lesson 3\n"       // 1
    "rLocate 400, 300\n"                 // 2
    "rInvisible GREEN\n"                 // 3
    "LineWidth 4\n"                      // 4
    "rPen DOWN\n"                        // 5
    "side = 120\n"                       // 6
    "for n = 1 to 4\n"                   // 7
    "  gosub DrawSide\n"                 // 8
    "next\n"                             // 9
    "print \"perimeter \" + 4 * side\n"  // 10
    "end\n"                              // 11
    "\n"                                 // 12
    "DrawSide:\n"                        // 13
    "  rForward side\n"                  // 14
    "  rTurn 90\n"                       // 15
    "return\n";                          // 16

/// The same program renamed, renumbered, re-indented and re-commented, keywords and built-ins in
/// another case: its code is on lines 4-21.
const char* kSquareDisguised =
    "' My own square\n"                 // 1
    "' by Ben\n"                        // 2
    "\n"                                // 3
    "RLOCATE 200,200   ' start here\n"  // 4
    "rinvisible green\n"                // 5
    "\n"                                // 6
    "linewidth 2 // thick\n"            // 7
    "rpen down\n"                       // 8
    "length = 90\n"                     // 9
    "FOR i = 0 TO 3\n"                  // 10
    "gosub Edge\n"                      // 11
    "NEXT\n"                            // 12
    "print \"total\" + 4 * length\n"    // 13
    "END\n"                             // 14
    "/* the side\n"                     // 15
    "   of the square */\n"             // 16
    "Edge:\n"                           // 17
    "      rForward length\n"           // 18
    "\n"                                // 19
    "      rTurn 45\n"                  // 20
    "RETURN\n";                         // 21

/// Nothing like a square: a guessing game.
const char* kGuess =
    "// guess the number\n"
    "secret = random(100)\n"
    "tries = 0\n"
    "repeat\n"
    "  input \"your guess? \", g\n"
    "  tries = tries + 1\n"
    "  if g < secret then print \"higher\"\n"
    "  if g > secret then print \"lower\"\n"
    "until g = secret\n"
    "print \"found in \"; tries; \" tries\"\n"
    "while tries > 0\n"
    "  tries--\n"
    "  xyText 10, 10 + tries * 20, \"*\"\n"
    "wend\n"
    "end\n";

/// Maria's house, with three subroutines.
const char* kMaria =
    "// Assignment 5: a house with a door\n"
    "// Maria, 9B\n"
    "\n"
    "rLocate 300, 400\n"
    "rInvisible BLUE\n"
    "LineWidth 3\n"
    "rPen DOWN\n"
    "\n"
    "wall = 150\n"
    "gosub DrawWalls\n"
    "gosub DrawRoof\n"
    "gosub DrawDoor\n"
    "rPen UP\n"
    "print \"perimeter of the walls: \"; 4 * wall\n"
    "end\n"
    "\n"
    "// the four walls, turning right each time\n"
    "DrawWalls:\n"
    "  for side = 1 to 4\n"
    "    rForward wall\n"
    "    rTurn 90\n"
    "  next\n"
    "return\n"
    "\n"
    "// the roof: the two slopes of a triangle\n"
    "DrawRoof:\n"
    "  rTurn 30\n"
    "  rForward wall\n"
    "  rTurn 120\n"
    "  rForward wall\n"
    "  rTurn 210\n"
    "return\n"
    "\n"
    "// the door, a third of the wall high\n"
    "DrawDoor:\n"
    "  rPen UP\n"
    "  rTurn 90\n"
    "  rForward wall / 3\n"
    "  rTurn -90\n"
    "  rPen DOWN\n"
    "  for side = 1 to 2\n"
    "    rForward wall / 3\n"
    "    rTurn -90\n"
    "    rForward wall / 5\n"
    "    rTurn -90\n"
    "  next\n"
    "return\n";

/// Tom's copy: names, numbers, colours, comments and layout changed, the subroutines moved.
const char* kTom =
    "' House - Tom\n"
    "rLocate 250,350\n"
    "rInvisible RED\n"
    "LineWidth 2\n"
    "rPen DOWN\n"
    "size = 120\n"
    "gosub Walls\n"
    "gosub Roof\n"
    "gosub Door\n"
    "rPen UP\n"
    "print \"my walls are \"; 4 * size\n"
    "end\n"
    "\n"
    "Door:\n"
    "   rPen UP\n"
    "   rTurn 90\n"
    "   rForward size / 3   ' move to the door\n"
    "   rTurn -90\n"
    "   rPen DOWN\n"
    "   for k = 1 to 2\n"
    "      rForward size / 3\n"
    "      rTurn -90\n"
    "      rForward size / 4\n"
    "      rTurn -90\n"
    "   next\n"
    "return\n"
    "\n"
    "Walls:\n"
    "   for k = 1 to 4\n"
    "      rForward size\n"
    "      rTurn 90\n"
    "   next\n"
    "return\n"
    "\n"
    "Roof:\n"
    "   rTurn 30\n"
    "   rForward size\n"
    "   rTurn 120\n"
    "   rForward size\n"
    "   rTurn 210\n"
    "return\n";

const SimilarPair* findPair(const SimilarityReport& r, const std::string& a, const std::string& b) {
  for (const SimilarPair& p : r.pairs)
    if ((p.a == a && p.b == b) || (p.a == b && p.b == a)) return &p;
  return nullptr;
}

}  // namespace

TEST_CASE("a renamed, renumbered, re-indented and re-commented copy scores 1", "[grade][similarity]") {
  Scratch scratch;
  const fs::path& dir = scratch.dir;
  std::string ana = write(dir, "ana.bas", kSquare);
  std::string ben = write(dir, "ben.bas", kSquareDisguised);
  SimilarityReport r = findSimilar({ana, ben});
  CHECK(r.programs == 2);
  CHECK(r.skipped == 0);
  CHECK(r.notes.empty());
  REQUIRE(r.pairs.size() == 1);
  const SimilarPair& p = r.pairs[0];
  CHECK(p.a == ana);
  CHECK(p.b == ben);
  CHECK(p.score == 1.0);
  CHECK(p.shareA == 1.0);
  CHECK(p.shareB == 1.0);
  CHECK(p.shared > 0);
  CHECK(p.shared == p.fingerprintsA);
  // One block: the whole program, from its first line of code to its last, in both.
  REQUIRE(p.blocks.size() == 1);
  const SharedBlock& b = p.blocks[0];
  CHECK(b.a.first == 2);
  CHECK(b.a.last == 16);
  CHECK(b.b.first == 4);
  CHECK(b.b.last == 21);
  CHECK(b.tokens == 36);  // every token of ana.bas
  REQUIRE(b.linesA.size() == 15);
  REQUIRE(b.linesB.size() == 18);
  CHECK(b.linesA.front() == "rLocate 400, 300");
  CHECK(b.linesB.front() == "RLOCATE 200,200   ' start here");
  CHECK(b.linesA.back() == "return");
  CHECK(b.linesB.back() == "RETURN");
  // Side by side: lines with matching code on one row, the rest next to each other or alone.
  std::vector<std::pair<uint32_t, uint32_t>> rows,
      expected = {{2, 4},   {3, 5},   {0, 6},   {4, 7},  {5, 8},   {6, 9},   {7, 10}, {8, 11},  {9, 12},
                  {10, 13}, {11, 14}, {12, 15}, {0, 16}, {13, 17}, {14, 18}, {0, 19}, {15, 20}, {16, 21}};
  for (const SharedBlock::Row& row : b.rows) rows.emplace_back(row.a, row.b);
  CHECK(rows == expected);
}

TEST_CASE("two unrelated programs score low", "[grade][similarity]") {
  Scratch scratch;
  const fs::path& dir = scratch.dir;
  std::string ana = write(dir, "ana.bas", kSquare);
  std::string cleo = write(dir, "cleo.bas", kGuess);
  SimilarityOptions all;
  all.minScore = 0;  // every pair with anything in common
  SimilarityReport r = findSimilar({ana, cleo}, all);
  CHECK(r.programs == 2);
  if (!r.pairs.empty()) CHECK(r.pairs[0].score < 0.2);
  CHECK(findSimilar({ana, cleo}).pairs.empty());  // not at the default 30%
}

TEST_CASE("swapped blocks are still matched where they went", "[grade][similarity]") {
  Scratch scratch;
  const fs::path& dir = scratch.dir;
  // Two subroutines and a main part; the copy puts them in the other order.
  std::string mainPart =
      "rLocate 400, 300\n"
      "rInvisible GREEN\n"
      "rPen DOWN\n"
      "size = 100\n"
      "gosub Square\n"
      "gosub Star\n"
      "print \"done in \"; Timer() - start; \" ms\"\n"
      "end\n";
  std::string square =
      "Square:\n"
      "  LineWidth 3\n"
      "  for n = 1 to 4\n"
      "    rForward size\n"
      "    rTurn 90\n"
      "    print \"side \"; n; \" of \"; size\n"
      "  next\n"
      "return\n";
  std::string star =
      "Star:\n"
      "  k = 0\n"
      "  while k < 5\n"
      "    rForward size * Sin(dtor(36)) / 2\n"
      "    rTurn 144\n"
      "    k = k + 1\n"
      "  wend\n"
      "return\n";
  std::string a = write(dir, "a.bas", mainPart + square + star);  // square 9-16, star 17-24
  std::string b = write(dir, "b.bas", star + square + mainPart);  // star 1-8, square 9-16
  SimilarityReport r = findSimilar({a, b});
  REQUIRE(r.pairs.size() == 1);
  const SimilarPair& p = r.pairs[0];
  // The k-grams across the seams are lost, and with them about half the fingerprints of parts
  // this short: the score falls, the blocks stay.
  CHECK(p.score >= 0.3);
  REQUIRE(p.blocks.size() == 3);
  bool mainFound = false, starFound = false, squareFound = false;
  for (const SharedBlock& blk : p.blocks) {
    // Each block maps a part of a to the same part of b, line for line.
    if (blk.a.first == 1) {
      mainFound = true;
      CHECK(blk.a.last == 8);
      CHECK(blk.b.first == 17);
      CHECK(blk.b.last == 24);
    } else if (blk.a.first == 9) {
      squareFound = true;
      CHECK(blk.a.last == 16);
      CHECK(blk.b.first == 9);
      CHECK(blk.b.last == 16);
    } else if (blk.a.first == 17) {
      starFound = true;
      CHECK(blk.a.last == 24);
      CHECK(blk.b.first == 1);
      CHECK(blk.b.last == 8);
    }
    CHECK(blk.rows.size() == 8);
    for (const SharedBlock::Row& row : blk.rows) CHECK(row.b == row.a + blk.b.first - blk.a.first);
  }
  CHECK(mainFound);
  CHECK(starFound);
  CHECK(squareFound);
  // Blocks come longest first.
  for (size_t i = 1; i < p.blocks.size(); ++i) CHECK(p.blocks[i - 1].tokens >= p.blocks[i].tokens);
}

TEST_CASE("blocks that meet at a line share it out", "[grade][similarity]") {
  // Tom's copy of Maria's house puts her subroutines in another order: the main part's end and
  // the door's label meet in both, and each block keeps what it can.
  Scratch scratch;
  const fs::path& dir = scratch.dir;
  std::string maria = write(dir, "maria.bas", kMaria);
  std::string tom = write(dir, "tom.bas", kTom);
  SimilarityReport r = findSimilar({maria, tom});
  REQUIRE(r.pairs.size() == 1);
  std::vector<std::vector<uint32_t>> blocks;
  std::vector<std::vector<uint32_t>> expected = {{35, 47, 14, 26},   // the door
                                                 {4, 15, 2, 12},     // the main part, up to `end`
                                                 {18, 32, 28, 41}};  // the walls and the roof
  for (const SharedBlock& b : r.pairs[0].blocks) blocks.push_back({b.a.first, b.a.last, b.b.first, b.b.last});
  CHECK(blocks == expected);
}

TEST_CASE("code from the teacher's template does not count", "[grade][similarity]") {
  Scratch scratch;
  const fs::path& dir = scratch.dir;
  std::string templ =
      "// Assignment 4: draw your initials. Do not change the set-up.\n"
      "rLocate 400, 300\n"
      "rInvisible GREEN\n"
      "LineWidth 4\n"
      "rPen DOWN\n"
      "gosub Initials\n"
      "rPen UP\n"
      "xyText 10, 10, \"done\", \"Arial\", 12\n"
      "end\n";
  std::string t = write(dir, "template.bas", templ);
  // Three students fill it in, each in their own way; the fourth copies the third.
  std::string s1 =
      write(dir, "s1.bas",
            templ +
                "Initials:\n  for i = 1 to 3\n    rForward 50\n    rTurn 120\n  next\n  rSpeed 5\n"
                "  print \"I\"; i\n  rForward -50\nreturn\n");
  std::string s2 =
      write(dir, "s2.bas",
            templ +
                "Initials:\n  x = 0\n  while x < 200\n    rForward 10 * Sqrt(x)\n    rTurn Abs(x - 100)\n"
                "    x = x + 25\n  wend\nreturn\n");
  std::string s3 =
      write(dir, "s3.bas",
            templ +
                "Initials:\n  if rBumper() then rTurn 180 else rForward 40\n  repeat\n    rTurn 10\n"
                "    c = c + 1\n  until c >= 36 or rFeel() > 0\nreturn\n");
  std::string s4 =
      write(dir, "s4.bas",
            templ +
                "Initials:\n  if rBumper() then rTurn 90 else rForward 20\n  repeat\n    rTurn 5\n"
                "    count = count + 2\n  until count >= 72 or rFeel() > 0\nreturn\n");

  // Without the template, everyone looks like everyone.
  SimilarityReport plain = findSimilar({s1, s2, s3, s4});
  CHECK(findPair(plain, s1, s2) != nullptr);
  CHECK(findPair(plain, s1, s3) != nullptr);

  SimilarityOptions options;
  options.ignore = {t};
  SimilarityReport r = findSimilar({s1, s2, s3, s4, t}, options);
  CHECK(r.programs == 4);
  CHECK(r.skipped == 1);  // the template itself, among the programs
  CHECK(findPair(r, s1, s2) == nullptr);
  CHECK(findPair(r, s1, s3) == nullptr);
  CHECK(findPair(r, s2, s3) == nullptr);
  // The copy is still found, and its blocks are the students' own code, not the template's.
  const SimilarPair* copy = findPair(r, s3, s4);
  REQUIRE(copy != nullptr);
  CHECK(copy->score == 1.0);
  REQUIRE(!copy->blocks.empty());
  for (const SharedBlock& b : copy->blocks) {
    CHECK(b.a.first >= 10);  // "Initials:", the line after the template's
    CHECK(b.b.first >= 10);
  }

  SimilarityOptions missing;
  missing.ignore = {(dir / "nowhere.bas").string()};
  SimilarityReport m = findSimilar({s1, s2}, missing);
  REQUIRE(!m.notes.empty());
  CHECK(m.notes[0].find("nowhere.bas: not used as a template") != std::string::npos);
}

TEST_CASE("code most of the class has is boilerplate", "[grade][similarity]") {
  Scratch scratch;
  const fs::path& dir = scratch.dir;
  std::string common =
      "rLocate 400, 300\nrInvisible GREEN\nLineWidth 4\nrPen DOWN\n"
      "for side = 1 to 4\n  rForward 100\n  rTurn 90\nnext\n"
      "rPen UP\nrForward 20\nrTurn 45\nxyText 10, 10, \"Square\", \"Arial\", 12\n";
  const char* functions[] = {"abs",  "sqrt", "sin", "cos", "tan", "asin",
                             "acos", "atan", "exp", "ln",  "log", "int"};
  std::vector<std::string> programs;
  for (int i = 0; i < 12; ++i) {
    // Each student's own part uses a function nobody else uses, so it shares nothing.
    std::string f = functions[i];
    std::string own = "a = " + f + "(b) + " + f + "(c) * 2\nrForward " + f + "(a)\nrTurn " + f + "(a - b)\n" +
                      "print " + f + "(a), " + f + "(b), " + f + "(c)\n";
    programs.push_back(write(dir, "s" + std::to_string(i) + ".bas", common + own));
  }
  SimilarityReport r = findSimilar(programs);
  CHECK(r.programs == 12);
  CHECK(r.common > 0);
  CHECK(r.pairs.empty());

  SimilarityOptions keepAll;
  keepAll.commonShare = 1;
  SimilarityReport all = findSimilar(programs, keepAll);
  CHECK(all.common == 0);
  CHECK(all.pairs.size() == 50);  // 66 pairs, all alike through the common part
  CHECK(all.matching == 66);

  // In a small class, two copies are not boilerplate.
  SimilarityReport small = findSimilar({programs[0], programs[1], programs[2]});
  CHECK(small.common == 0);
  CHECK(small.pairs.size() == 3);
}

TEST_CASE("pairs are ranked by score, then shared fingerprints, then names", "[grade][similarity]") {
  Scratch scratch;
  const fs::path& dir = scratch.dir;
  std::string own =
      "x = 0\n"
      "while x < 360\n"
      "  rForward 2 * Sin(dtor(x))\n"
      "  rTurn 1\n"
      "  x = x + 1\n"
      "  if rBumper() & 4 then rTurn 180 else xyText 10, 10, \"going \" + x, \"Arial\", 10\n"
      "wend\n"
      "repeat\n"
      "  rTurn 5\n"
      "  steps = steps + 1\n"
      "until rFeel() = 0 or steps > 72\n"
      "print \"done after \"; steps; \" turns\"\n";
  std::string longer = std::string(kSquare) + own;
  // y and z: a long program and its copy. c: all of it is in y and z. d: half of it is y's own
  // part. Names alone would put c's pairs first.
  std::string y = write(dir, "y.bas", longer);
  std::string z = write(dir, "z.bas", longer);
  std::string c = write(dir, "c.bas", kSquare);
  std::string d = write(dir, "d.bas", std::string(kGuess) + own);
  SimilarityReport r = findSimilar({d, c, z, y});
  REQUIRE(r.pairs.size() >= 3);
  // z-y: score 1 with the most shared; c-y and c-z: score 1 (c is wholly in them) with fewer
  // shared, in the order of their names. A pair keeps the order its programs were given in.
  CHECK(r.pairs[0].a == z);
  CHECK(r.pairs[0].b == y);
  CHECK(r.pairs[0].score == 1.0);
  CHECK(r.pairs[1].a == c);
  CHECK(r.pairs[1].b == y);
  CHECK(r.pairs[1].score == 1.0);
  CHECK(r.pairs[1].shared < r.pairs[0].shared);
  CHECK(r.pairs[2].a == c);
  CHECK(r.pairs[2].b == z);
  CHECK(r.pairs[2].shared == r.pairs[1].shared);
  // d-y and d-z: a lower score, though more shared than c's pairs.
  REQUIRE(r.pairs.size() == 5);
  for (size_t i = 3; i < 5; ++i) {
    CHECK(r.pairs[i].a == d);
    CHECK(r.pairs[i].score < 1.0);
    CHECK(r.pairs[i].shared > r.pairs[1].shared);
  }

  SimilarityOptions two;
  two.maxPairs = 2;
  SimilarityReport cut = findSimilar({d, c, z, y}, two);
  REQUIRE(cut.pairs.size() == 2);
  CHECK(cut.pairs[0].a == z);
  CHECK(cut.pairs[1].a == c);
  CHECK(cut.pairs[1].b == y);
  CHECK(cut.matching == r.pairs.size());
}

TEST_CASE("the text shows the shared lines side by side", "[grade][similarity]") {
  Scratch scratch;
  const fs::path& dir = scratch.dir;
  std::string ana = write(dir, "ana.bas", kSquare);
  std::string ben =
      write(dir, "ben.bas",
            std::string(kSquareDisguised) +
                "print \"a long line that goes on and on and on, far past the fifty columns of a side\"\n");
  std::string text = similarityText(findSimilar({ana, ben}));
  INFO(text);
  CHECK(text.rfind("Similar code: 1 pair of the 2 programs where 30% or more of one program's code is found "
                   "in the other.\n",
                   0) == 0);
  CHECK(text.find("1. 100%  " + ana + "  and  " + ben) != std::string::npos);
  CHECK(text.find("lines 2-16 of " + ana + " and lines 4-21 of " + ben) != std::string::npos);
  // Row by row: line number and text of each, the columns 50 characters apart.
  std::string row = " 2 rLocate 400, 300";
  size_t at = text.find(row);
  REQUIRE(at != std::string::npos);
  std::string line = text.substr(at, text.find('\n', at) - at);
  CHECK(line.substr(50) == " |  4 RLOCATE 200,200   ' start here");
  CHECK(text.find("   16 return" + std::string(41, ' ') + " | 21 RETURN\n") != std::string::npos);
  CHECK(text.find("\n    4 LineWidth 4" + std::string(36, ' ') + " |  7 linewidth 2 // thick\n") !=
        std::string::npos);
  CHECK(text.find("\n   " + std::string(50, ' ') + " |  6\n") != std::string::npos);  // a line of b alone
  CHECK(text.find("never a verdict") != std::string::npos);

  // Long lines are cut to the column.
  Scratch scratch2;
  const fs::path& d2 = scratch2.dir;
  std::string longText = "x = 1\nprint \"" + std::string(200, 'y') + "\" + x + 2 * 3 + 4 * 5 + 6\nend\n";
  std::string l1 = write(d2, "l1.bas", longText);
  std::string l2 = write(d2, "l2.bas", longText);
  SimilarityOptions few;
  few.minShared = 1;  // two short programs: one fingerprint in common
  std::string t2 = similarityText(findSimilar({l1, l2}, few));
  INFO(t2);
  size_t yy = t2.find("yyyy");
  REQUIRE(yy != std::string::npos);
  std::string cutRow = t2.substr(t2.rfind('\n', yy) + 1);
  cutRow = cutRow.substr(0, cutRow.find('\n'));
  CHECK(cutRow.find("~ | ") == 3 + 49);
  CHECK(cutRow.size() == 3 + 50 + 3 + 50);

  // Percentages round to the nearest, but only a whole is 100%.
  SimilarityReport made;
  made.programs = 3;
  made.minScore = 0.3;
  made.pairs.resize(2);
  made.pairs[0] = {.a = "x.bas", .b = "y.bas", .shareA = 0.6667, .shareB = 0.996, .score = 0.996, .shared = 12,
                   .fingerprintsA = 18, .fingerprintsB = 19, .blocks = {}};
  made.pairs[1] = {.a = "x.bas", .b = "z.bas", .shareA = 0.3, .shareB = 0.004, .score = 0.3, .shared = 3,
                   .fingerprintsA = 10, .fingerprintsB = 750, .blocks = {}};
  std::string m = similarityText(made);
  INFO(m);
  CHECK(m.find("1. 99%  x.bas  and  y.bas\n   12 fingerprints in common: 67% of x.bas's 18, 99% of y.bas's 19\n") !=
        std::string::npos);
  CHECK(m.find("2. 30%  x.bas  and  z.bas\n   3 fingerprints in common: 30% of x.bas's 10, 1% of z.bas's 750\n") !=
        std::string::npos);

  SimilarityReport none;
  none.programs = 5;
  none.minScore = 0.3;
  CHECK(similarityText(none) ==
        "Similar code: no pair of the 5 programs where 30% or more of one program's code is found in the "
        "other.\n");
}

TEST_CASE("the JSON has every pair with its blocks and lines", "[grade][similarity]") {
  Scratch scratch;
  const fs::path& dir = scratch.dir;
  std::string ana = write(dir, "ana.bas", kSquare);
  std::string ben = write(dir, "ben.bas", kSquareDisguised);
  std::string cleo = write(dir, "cleo.bas", kGuess);
  nlohmann::json doc = nlohmann::json::parse(similarityJson(findSimilar({ana, ben, cleo})));
  REQUIRE(doc.is_array());
  REQUIRE(doc.size() == 1);
  const nlohmann::json& p = doc[0];
  CHECK(p["a"] == ana);
  CHECK(p["b"] == ben);
  CHECK(p["score"] == 1.0);
  CHECK(p["share_a"] == 1.0);
  CHECK(p["share_b"] == 1.0);
  CHECK(p["shared"].get<int>() > 0);
  REQUIRE(p["blocks"].is_array());
  REQUIRE(p["blocks"].size() == 1);
  const nlohmann::json& b = p["blocks"][0];
  CHECK(b["a"] == nlohmann::json::array({2, 16}));
  CHECK(b["b"] == nlohmann::json::array({4, 21}));
  CHECK(b["tokens"] == 36);
  REQUIRE(b["lines_a"].size() == 15);
  REQUIRE(b["lines_b"].size() == 18);
  CHECK(b["lines_a"][0] == "rLocate 400, 300");
  CHECK(b["lines_b"][17] == "RETURN");
  REQUIRE(b["rows"].size() == 18);
  CHECK(b["rows"][0] == nlohmann::json::array({2, 4}));
  CHECK(b["rows"][2] == nlohmann::json::array({nullptr, 6}));  // a blank line of ben's alone

  CHECK(nlohmann::json::parse(similarityJson(SimilarityReport{})) == nlohmann::json::array());
}

TEST_CASE("bad input is skipped with a note, never a crash", "[grade][similarity]") {
  Scratch scratch;
  const fs::path& dir = scratch.dir;
  std::string ana = write(dir, "ana.bas", kSquare);
  std::string ben = write(dir, "ben.bas", kSquareDisguised);
  std::string binary = write(dir, "binary.bas",
                             std::string("\x7f"
                                         "ELF\x02\x01\x01\0\0\0\0\0",
                                         12) +
                                 std::string(500, '\xff'));
  std::string empty = write(dir, "empty.bas", "");
  std::string tiny = write(dir, "tiny.bas", "print 1\n");
  std::string garbage = write(dir, "garbage.bas", std::string(5000, '@'));
  std::string missing = (dir / "missing.bas").string();
  std::string folder = (dir / "folder.bas").string();
  fs::create_directories(folder);
  SimilarityReport r = findSimilar({binary, ana, empty, tiny, garbage, missing, folder, ben});
  CHECK(r.programs == 2);
  CHECK(r.skipped == 6);
  REQUIRE(r.pairs.size() == 1);
  CHECK(r.pairs[0].score == 1.0);
  auto noted = [&](const std::string& path, const std::string& why) {
    for (const std::string& n : r.notes)
      if (n.rfind(path + ": skipped: ", 0) == 0 && n.find(why) != std::string::npos) return true;
    return false;
  };
  CHECK(noted(binary, "binary"));
  CHECK(noted(empty, "too short"));
  CHECK(noted(tiny, "too short"));
  CHECK(noted(garbage, "not RobotBASIC"));
  CHECK(noted(missing, "cannot read"));
  CHECK(noted(folder, "not a regular file"));
  CHECK(similarityText(r).find("note: " + garbage + ": skipped") != std::string::npos);

  // A few stray characters are left out and the rest compared.
  std::string stray = write(dir, "stray.bas", std::string(kSquare) + "@@ `\n");
  SimilarityReport s = findSimilar({ana, stray});
  CHECK(s.skipped == 0);
  REQUIRE(s.pairs.size() == 1);
  CHECK(s.pairs[0].score == 1.0);

  // An unterminated comment, an unterminated string: what is read is compared.
  std::string open = write(dir, "open.bas", std::string(kSquare) + "print \"no end\n/* and no end\n");
  CHECK(findSimilar({ana, open}).pairs.size() == 1);
}

TEST_CASE("big files are cut, not a burden", "[grade][similarity]") {
  Scratch scratch;
  const fs::path& dir = scratch.dir;
  std::string ana = write(dir, "ana.bas", kSquare);
  std::string big;
  while (big.size() < (1u << 20)) big += kGuess;
  big += kSquare;
  std::string bigFile = write(dir, "big.bas", big);
  std::string oneLine = write(dir, "oneline.bas", std::string(1u << 20, '('));
  std::string longLines;
  for (int i = 0; i < 40; ++i) longLines += "x = 1 + " + std::string(20000, '2') + "\n";
  std::string longFile = write(dir, "long.bas", longLines);
  auto start = std::chrono::steady_clock::now();
  SimilarityReport r = findSimilar({ana, bigFile, oneLine, longFile});
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  CHECK(seconds < 20);  // about 0.3 s; only a hang would fail
  CHECK(r.programs == 4);
  const SimilarPair* p = findPair(r, ana, bigFile);
  REQUIRE(p != nullptr);
  CHECK(p->score == 1.0);  // all of ana is at the end of big.bas
  REQUIRE(!p->blocks.empty());
  CHECK(p->blocks[0].linesB.back() == "return");
  bool cutNoted = false;
  for (const std::string& n : r.notes)
    cutNoted = cutNoted || n == oneLine + ": lines longer than 16 KiB are cut";
  CHECK(cutNoted);
}

TEST_CASE("winnowing options: k and the window", "[grade][similarity]") {
  Scratch scratch;
  const fs::path& dir = scratch.dir;
  std::string ana = write(dir, "ana.bas", kSquare);
  std::string ben = write(dir, "ben.bas", kSquareDisguised);
  SimilarityOptions small;
  small.k = 0;       // counts as 1
  small.window = 0;  // counts as 1: every k-gram is a fingerprint
  SimilarityReport r = findSimilar({ana, ben}, small);
  REQUIRE(r.pairs.size() == 1);
  CHECK(r.pairs[0].score == 1.0);
  SimilarityOptions large;
  large.k = 1000;  // longer than either program
  SimilarityReport l = findSimilar({ana, ben}, large);
  CHECK(l.programs == 0);
  CHECK(l.skipped == 2);
  CHECK(l.pairs.empty());
  // A bigger window keeps fewer fingerprints.
  SimilarityOptions w1, w8;
  w1.window = 1;
  SimilarityReport r1 = findSimilar({ana, ben}, w1), r8 = findSimilar({ana, ben}, w8);
  REQUIRE(r1.pairs.size() == 1);
  REQUIRE(r8.pairs.size() == 1);
  CHECK(r1.pairs[0].shared > r8.pairs[0].shared);
}

namespace {

/// A class of `count` programs of about 30 lines, written to `dir`: each program is its own mix
/// of statements (a small random generator picks their kinds, names and numbers) around
/// `shared` of 12 snippets every student might write for the assignment.
std::vector<std::string> generateClass(const fs::path& dir, int count, int shared, uint64_t seed) {
  auto next = [&](uint64_t n) {
    seed = seed * 6364136223846793005ull + 1442695040888963407ull;
    return (seed >> 33) % n;
  };
  auto num = [&] { return std::to_string(next(360)); };
  auto var = [&] { return std::string(1, char('a' + next(26))) + std::to_string(next(10)); };
  const char* commands[] = {"rForward", "rTurn", "rSpeed", "LineWidth", "rPen DOWN:", "rPen UP:"};
  const char* functions[] = {"abs", "sqrt", "sin", "cos", "int", "round", "random", "rRange"};
  std::vector<std::string> snippets;
  for (int i = 0; i < 12; ++i) {
    std::string s = "for " + std::string(1, char('i' + i % 3)) + " = 1 to " + std::to_string(3 + i) + "\n";
    for (int j = 0; j <= i % 4; ++j)
      s += std::string(commands[(i + j) % 4]) + " " + std::to_string(10 * (i + j)) + "\n";
    s += i % 2 ? "next\n" : "  if rBumper() & 4 then rTurn 90\nnext\n";
    snippets.push_back(s);
  }
  std::vector<std::string> paths;
  for (int p = 0; p < count; ++p) {
    std::string text = "// program " + std::to_string(p) + "\nrLocate 400, 300\nrInvisible GREEN\n";
    int lines = 0;
    while (lines < 30) {
      switch (next(9)) {
        case 0: {
          std::string c = commands[next(6)];
          text += c.back() == ':' ? c.substr(0, c.size() - 1) + "\n" : c + " " + num() + "\n";
          lines += 1;
          break;
        }
        case 1:
          text +=
              var() + " = " + functions[next(8)] + "(" + var() + ") " + "+-*/"[next(4)] + " " + num() + "\n";
          lines += 1;
          break;
        case 2:
          text += "for " + var() + " = 1 to " + num() + "\n  rForward " + var() + "\n  rTurn " + num() +
                  "\nnext\n";
          lines += 4;
          break;
        case 3:
          text += "if rBumper() & " + num() + " then rTurn " + num() + " else rForward " + var() + "\n";
          lines += 1;
          break;
        case 4:
          text +=
              "while " + var() + " < " + num() + "\n  " + var() + " = " + var() + " + " + num() + "\nwend\n";
          lines += 3;
          break;
        case 5:
          text += "print \"step \"; " + var() + "\n";
          lines += 1;
          break;
        case 6:
          text += "xyText " + num() + ", " + num() + ", \"" + var() + "\", \"Arial\", " + num() + "\n";
          lines += 1;
          break;
        case 7:
          text += "repeat\n  rTurn " + num() + "\nuntil rFeel() > " + num() + "\n";
          lines += 3;
          break;
        default:
          if (shared > 0) text += snippets[next(12)], lines += 4;
          break;
      }
    }
    for (int i = 0; i < shared; ++i) text += snippets[next(12)];
    paths.push_back(write(dir, "p" + std::to_string(p) + ".bas", text));
  }
  return paths;
}

}  // namespace

// Not run by default: `rb_grade_tests "[perf]"` times classes of 1,000 generated programs.
TEST_CASE("a class of 1,000 programs", "[.perf]") {
  for (int shared : {0, 3}) {
    Scratch scratch;
    const fs::path& dir = scratch.dir;
    std::vector<std::string> programs = generateClass(dir, 1000, shared, 12345 + uint64_t(shared));
    // Ten pairs of copies.
    for (size_t i = 0; i < 10; ++i)
      fs::copy_file(programs[i], programs[500 + i], fs::copy_options::overwrite_existing);
    auto start = std::chrono::steady_clock::now();
    SimilarityReport r = findSimilar(programs);
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    WARN("1,000 programs (" << shared << " shared snippets each) compared in " << seconds << " s; "
                            << r.matching << " pairs from 30%, " << r.common << " common fingerprints");
    CHECK(seconds < 5);
    CHECK(r.programs == 1000);
    REQUIRE(r.pairs.size() >= 10);
    for (size_t i = 0; i < 10; ++i) {
      CHECK(r.pairs[i].score == 1.0);
      CHECK(r.pairs[i].b == programs[500 + std::stoul(r.pairs[i].a.substr(r.pairs[i].a.rfind('p') + 1))]);
    }
  }
}

TEST_CASE("one or two shared fingerprints are no evidence", "[grade][similarity]") {
  Scratch scratch;
  std::string text = "x = 1\nprint \"a\" + x + 2 * 3 + 4 * 5 + 6\nend\n";
  std::string a = write(scratch.dir, "a.bas", text), b = write(scratch.dir, "b.bas", text);
  SimilarityOptions one;
  one.minShared = 1;
  REQUIRE(findSimilar({a, b}, one).pairs.size() == 1);
  CHECK(findSimilar({a, b}, one).pairs[0].shared < 3);
  CHECK(findSimilar({a, b}).pairs.empty());  // the default asks for 3
}

TEST_CASE("the quick scan reads programs as rb's lexer does", "[grade][similarity]") {
  // Every program of the repository, and texts made of the pieces programs are made of (with
  // what the quick scan leaves to the lexer among them), in both readings.
  std::vector<std::string> texts;
  const fs::path root = fs::path(__FILE__).parent_path().parent_path();
  for (const char* folder : {"examples", "testdata", "lib"})
    for (const auto& e : fs::recursive_directory_iterator(root / folder))
      if (e.is_regular_file() && e.path().extension() == ".bas") {
        std::ifstream in(e.path(), std::ios::binary);
        texts.emplace_back(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
      }
  const std::vector<std::string> pieces = {
      "x", "X1", "_y$", "rem", "REM see", "Rem", "remark", "gosub", "GoSub", "Sub", "call", "then", "else",
      "rForward", "RFORWARD", "rfeel", "GREEN", "Green", "print", "length", "length(", "abc:", "a:", "if",
      "aVeryLongNameOf16", "aVeryLongNameOf16x", "1", "2.5", ".5", "5.", "1.2.3", "2e", "2e5", "1E+3", "0x1F",
      "0xg", "0%101", "0%2", "12345678901234567890123", "\"str\"", "\"open", "\"\"", "// note", "' note",
      "/* c */", "/*", "*/", "+", "++", "+=", "-", "--", "-=", "*", "*=", "/", "/=", "%", "^", "~", "&", "&&",
      "|", "||", "!", "!=", "=", "==", "<", "<>", "<=", "<<", ">", ">=", ">>", "(", ")", "[", "]", ",", ";",
      ":", "#", "@", "?", "`", "\\", "{", "}", "$x", ".", "\t", " ", "  ", "\r", "\f", "\v", "\n", "\n",
      "\n", "\r\n", "\xC3\xA9", "\xE2\x82\xAC", "\x01", "\x7F"};
  const size_t files = texts.size();
  REQUIRE(files > 100);
  uint64_t state = 42;
  auto next = [&state](size_t n) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<size_t>((state >> 33) % n);
  };
  for (int t = 0; t < 3000; ++t) {
    std::string text;
    for (size_t i = 0, n = 1 + next(40); i < n; ++i) {
      text += pieces[next(pieces.size())];
      if (next(3)) text += next(4) ? " " : "\n";
    }
    texts.push_back(text);
  }
  size_t quick = 0, quickFiles = 0;
  for (size_t i = 0; i < texts.size(); ++i) {
    const std::string& text = texts[i];
    std::optional<std::vector<uint32_t>> fast = detail::normalisedCodes(text, true);
    if (!fast) continue;
    ++quick;
    quickFiles += i < files ? 1 : 0;
    INFO(text);
    std::optional<std::vector<uint32_t>> slow = detail::normalisedCodes(text, false);
    REQUIRE(slow);
    CHECK(*fast == *slow);
  }
  CHECK(quickFiles > files * 3 / 4);  // the quick scan does read most programs
  CHECK(quick > 500);                  // and many of the made-up texts
}

TEST_CASE("winnowing selects each window's rightmost minimum once", "[grade][similarity]") {
  uint64_t state = 7;
  auto next = [&state](uint64_t n) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return (state >> 33) % n;
  };
  for (int t = 0; t < 2000; ++t) {
    std::vector<uint64_t> h(next(60));
    const uint64_t range = t % 3 == 0 ? 3 : t % 3 == 1 ? 20 : 1000000;  // many ties, some, none
    for (uint64_t& v : h) v = next(range);
    const size_t w = 1 + next(12);
    // The definition, window by window.
    std::vector<uint32_t> expected;
    const size_t ww = std::min(w, h.size());
    for (size_t s = 0; ww > 0 && s + ww <= h.size(); ++s) {
      size_t m = s;
      for (size_t i = s; i < s + ww; ++i)
        if (h[i] <= h[m]) m = i;
      if (expected.empty() || expected.back() != m) expected.push_back(static_cast<uint32_t>(m));
    }
    INFO("n = " << h.size() << ", w = " << w);
    CHECK(detail::winnowed(h, w) == expected);
  }
}

TEST_CASE("shared fingerprints are counted exactly, boilerplate left out, with any number of threads",
          "[grade][similarity]") {
  // 40 programs from a pool of lines: some lines in most programs (boilerplate), some in a few.
  Scratch scratch;
  uint64_t state = 99;
  auto next = [&state](size_t n) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<size_t>((state >> 33) % n);
  };
  std::vector<std::string> pool;
  for (int i = 0; i < 120; ++i)
    pool.push_back("x" + std::to_string(i % 7) + " = rFeel() + " + std::to_string(i) + " * y\nrTurn " +
                   std::to_string(i) + "\nif x > " + std::to_string(i) + " then gosub L" + std::to_string(i % 5) +
                   (i % 3 ? "\nprint \"a\"; x\n" : "\nrForward x * 2\n"));
  std::vector<std::string> paths, texts;
  for (int p = 0; p < 40; ++p) {
    std::string text;
    for (int block = 0; block < 12; ++block) {
      size_t which = block < 3 ? static_cast<size_t>(block) : 3 + next(block < 6 ? 10 : pool.size() - 3);
      if (block < 3 && next(10) == 0) continue;  // boilerplate most programs have
      text += pool[which];
    }
    texts.push_back(text);
    paths.push_back(write(scratch.dir, "p" + std::to_string(p) + ".bas", text));
  }
  SimilarityOptions all;
  all.minScore = 0;
  all.minShared = 1;
  all.maxPairs = 0;
  // What the counts must be: from each program's fingerprints, pair by pair.
  std::vector<std::vector<uint64_t>> prints;
  std::map<uint64_t, size_t> have;
  for (const std::string& t : texts) {
    prints.push_back(detail::fingerprintsOf(t, all.k, all.window));
    for (uint64_t h : prints.back()) ++have[h];
  }
  auto common = [&](uint64_t h) { return have[h] >= all.commonMinPrograms && have[h] > all.commonShare * 40; };
  size_t boilerplate = 0;
  for (const auto& [h, n] : have) boilerplate += common(h) ? 1 : 0;
  REQUIRE(boilerplate > 0);
  std::map<std::pair<std::string, std::string>, size_t> expected;
  std::vector<size_t> counted(40);
  for (size_t a = 0; a < 40; ++a)
    for (uint64_t h : prints[a]) counted[a] += common(h) ? 0 : 1;
  for (size_t a = 0; a < 40; ++a)
    for (size_t b = a + 1; b < 40; ++b) {
      size_t shared = 0;
      for (uint64_t h : prints[a])
        if (!common(h) && std::binary_search(prints[b].begin(), prints[b].end(), h)) ++shared;
      if (shared > 0) expected[{paths[a], paths[b]}] = shared;
    }
  std::string first;
  for (size_t threads : {1, 2, 5}) {
    all.threads = threads;
    SimilarityReport r = findSimilar(paths, all);
    INFO(threads << " threads");
    CHECK(r.common == boilerplate);
    CHECK(r.pairs.size() == expected.size());
    for (const SimilarPair& p : r.pairs) {
      auto it = expected.find({p.a, p.b});
      REQUIRE(it != expected.end());
      CHECK(p.shared == it->second);
      size_t a = static_cast<size_t>(std::stoi(fs::path(p.a).stem().string().substr(1)));
      size_t b = static_cast<size_t>(std::stoi(fs::path(p.b).stem().string().substr(1)));
      CHECK(p.fingerprintsA == counted[a]);
      CHECK(p.fingerprintsB == counted[b]);
    }
    const std::string json = similarityJson(r);
    if (first.empty()) first = json;
    CHECK(json == first);
  }
}
