#include "similarity.h"

#include <unistd.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

using namespace rb::grade;
namespace fs = std::filesystem;

namespace {

fs::path scratch() {
  static int count = 0;
  fs::path dir = fs::temp_directory_path() /
                 ("rb_similarity_test_" + std::to_string(getpid()) + "_" + std::to_string(++count));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string write(const fs::path& dir, const std::string& name, const std::string& text) {
  fs::path p = dir / name;
  std::ofstream(p, std::ios::binary) << text;
  return p.string();
}

/// A student's square: lines 2-16 are code, line 17 is blank.
const char* kSquare =
    "// Square by Ana, lesson 3\n"           // 1
    "rLocate 400, 300\n"                     // 2
    "rInvisible GREEN\n"                     // 3
    "LineWidth 4\n"                          // 4
    "rPen DOWN\n"                            // 5
    "side = 120\n"                           // 6
    "for n = 1 to 4\n"                       // 7
    "  gosub DrawSide\n"                     // 8
    "next\n"                                 // 9
    "print \"perimeter \" + 4 * side\n"      // 10
    "end\n"                                  // 11
    "\n"                                     // 12
    "DrawSide:\n"                            // 13
    "  rForward side\n"                      // 14
    "  rTurn 90\n"                           // 15
    "return\n";                              // 16

/// The same program renamed, renumbered, re-indented and re-commented, keywords and built-ins in
/// another case: its code is on lines 4-21.
const char* kSquareDisguised =
    "' My own square\n"                      // 1
    "' by Ben\n"                             // 2
    "\n"                                     // 3
    "RLOCATE 200,200   ' start here\n"       // 4
    "rinvisible green\n"                     // 5
    "\n"                                     // 6
    "linewidth 2 // thick\n"                 // 7
    "rpen down\n"                            // 8
    "length = 90\n"                          // 9
    "FOR i = 0 TO 3\n"                       // 10
    "gosub Edge\n"                           // 11
    "NEXT\n"                                 // 12
    "print \"total\" + 4 * length\n"         // 13
    "END\n"                                  // 14
    "/* the side\n"                          // 15
    "   of the square */\n"                  // 16
    "Edge:\n"                                // 17
    "      rForward length\n"                // 18
    "\n"                                     // 19
    "      rTurn 45\n"                       // 20
    "RETURN\n";                              // 21

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

const SimilarPair* findPair(const SimilarityReport& r, const std::string& a, const std::string& b) {
  for (const SimilarPair& p : r.pairs)
    if ((p.a == a && p.b == b) || (p.a == b && p.b == a)) return &p;
  return nullptr;
}

}  // namespace

TEST_CASE("a renamed, renumbered, re-indented and re-commented copy scores 1", "[grade][similarity]") {
  fs::path dir = scratch();
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
  std::vector<std::pair<uint32_t, uint32_t>> rows, expected = {
      {2, 4}, {3, 5}, {0, 6}, {4, 7}, {5, 8}, {6, 9}, {7, 10}, {8, 11}, {9, 12}, {10, 13},
      {11, 14}, {12, 15}, {0, 16}, {13, 17}, {14, 18}, {0, 19}, {15, 20}, {16, 21}};
  for (const SharedBlock::Row& row : b.rows) rows.emplace_back(row.a, row.b);
  CHECK(rows == expected);
}

TEST_CASE("two unrelated programs score low", "[grade][similarity]") {
  fs::path dir = scratch();
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
  fs::path dir = scratch();
  // Two subroutines and a main part; the copy puts them in the other order.
  std::string mainPart =
      "rLocate 400, 300\n"
      "rPen DOWN\n"
      "gosub Square\n"
      "gosub Star\n"
      "end\n";
  std::string square =
      "Square:\n"
      "  LineWidth 3\n"
      "  for n = 1 to 4\n"
      "    rForward 100\n"
      "    rTurn 90\n"
      "    print \"side \"; n\n"
      "  next\n"
      "return\n";
  std::string star =
      "Star:\n"
      "  k = 0\n"
      "  while k < 5\n"
      "    rForward 80 * Sin(dtor(36))\n"
      "    rTurn 144\n"
      "    k = k + 1\n"
      "  wend\n"
      "return\n";
  std::string a = write(dir, "a.bas", mainPart + square + star);  // square 6-13, star 14-21
  std::string b = write(dir, "b.bas", star + square + mainPart);  // star 1-8, square 9-16
  SimilarityReport r = findSimilar({a, b});
  REQUIRE(r.pairs.size() == 1);
  const SimilarPair& p = r.pairs[0];
  CHECK(p.score > 0.5);  // the k-grams across the moved boundaries are lost
  REQUIRE(p.blocks.size() >= 2);
  bool starFound = false, squareFound = false;
  for (const SharedBlock& blk : p.blocks) {
    // Each block maps a part of a to the same part of b.
    if (blk.a.first >= 13 && blk.a.last <= 21) {
      starFound = true;
      CHECK(blk.b.first == blk.a.first - 13);
      CHECK(blk.b.last == blk.a.last - 13);
    } else if (blk.a.first >= 6 && blk.a.last <= 14) {
      squareFound = true;
      CHECK(blk.b.first == blk.a.first + 3);
      CHECK(blk.b.last == blk.a.last + 3);
    }
  }
  CHECK(starFound);
  CHECK(squareFound);
  // Blocks come longest first.
  for (size_t i = 1; i < p.blocks.size(); ++i) CHECK(p.blocks[i - 1].tokens >= p.blocks[i].tokens);
}

TEST_CASE("code from the teacher's template does not count", "[grade][similarity]") {
  fs::path dir = scratch();
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
  std::string s1 = write(dir, "s1.bas", templ +
      "Initials:\n  for i = 1 to 3\n    rForward 50\n    rTurn 120\n  next\n  rSpeed 5\n"
      "  print \"I\"; i\n  rForward -50\nreturn\n");
  std::string s2 = write(dir, "s2.bas", templ +
      "Initials:\n  x = 0\n  while x < 200\n    rForward 10 * Sqrt(x)\n    rTurn Abs(x - 100)\n"
      "    x = x + 25\n  wend\nreturn\n");
  std::string s3 = write(dir, "s3.bas", templ +
      "Initials:\n  if rBumper() then rTurn 180 else rForward 40\n  repeat\n    rTurn 10\n"
      "    c = c + 1\n  until c >= 36 or rFeel() > 0\nreturn\n");
  std::string s4 = write(dir, "s4.bas", templ +
      "Initials:\n  if rBumper() then rTurn 90 else rForward 20\n  repeat\n    rTurn 5\n"
      "    count = count + 2\n  until count >= 72 or rFeel() > 0\nreturn\n");

  // Without the template, everyone looks like everyone.
  SimilarityReport plain = findSimilar({s1, s2, s3, s4});
  REQUIRE(findPair(plain, s1, s2) != nullptr);
  CHECK(findPair(plain, s1, s2)->score > 0.5);

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
  fs::path dir = scratch();
  std::string common =
      "rLocate 400, 300\nrInvisible GREEN\nLineWidth 4\nrPen DOWN\n"
      "for side = 1 to 4\n  rForward 100\n  rTurn 90\nnext\n"
      "rPen UP\nrForward 20\nrTurn 45\nxyText 10, 10, \"Square\", \"Arial\", 12\n";
  const char* functions[] = {"abs", "sqrt", "sin", "cos", "tan", "asin", "acos", "atan", "exp", "ln", "log", "int"};
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
  fs::path dir = scratch();
  std::string own =
      "x = 0\n"
      "while x < 360\n"
      "  rForward 2 * Sin(dtor(x))\n"
      "  rTurn 1\n"
      "  x = x + 1\n"
      "wend\n"
      "print \"done\"\n";
  std::string longer = std::string(kSquare) + own;
  std::string a = write(dir, "a.bas", longer);
  std::string b = write(dir, "b.bas", longer);                 // a's copy: 100% of a long program
  std::string c = write(dir, "c.bas", kSquare);                // all of c is in a and b: 100%, fewer shared
  std::string d = write(dir, "d.bas", std::string(kGuess) + own);  // half of d is a's own part
  SimilarityReport r = findSimilar({d, c, b, a});
  REQUIRE(r.pairs.size() >= 3);
  // a-b: score 1, the most shared; b-c and a-c: score 1 (c is wholly in them), fewer shared;
  // names break the tie: a's pair with c comes before b's. Pairs keep the order given: c first.
  CHECK(r.pairs[0].a == b);
  CHECK(r.pairs[0].b == a);
  CHECK(r.pairs[0].score == 1.0);
  CHECK(r.pairs[1].a == c);
  CHECK(r.pairs[1].b == a);
  CHECK(r.pairs[1].score == 1.0);
  CHECK(r.pairs[1].shared < r.pairs[0].shared);
  CHECK(r.pairs[2].a == c);
  CHECK(r.pairs[2].b == b);
  CHECK(r.pairs[2].shared == r.pairs[1].shared);
  for (size_t i = 3; i < r.pairs.size(); ++i) {
    CHECK(r.pairs[i].score < 1.0);
    CHECK(r.pairs[i].score <= r.pairs[i - 1].score);
  }

  SimilarityOptions two;
  two.maxPairs = 2;
  SimilarityReport cut = findSimilar({d, c, b, a}, two);
  REQUIRE(cut.pairs.size() == 2);
  CHECK(cut.pairs[1].a == c);
  CHECK(cut.matching == r.pairs.size());
}

TEST_CASE("the text shows the shared lines side by side", "[grade][similarity]") {
  fs::path dir = scratch();
  std::string ana = write(dir, "ana.bas", kSquare);
  std::string ben = write(dir, "ben.bas", std::string(kSquareDisguised) +
      "print \"a long line that goes on and on and on, far past the fifty columns of a side\"\n");
  std::string text = similarityText(findSimilar({ana, ben}));
  INFO(text);
  CHECK(text.rfind("Similar code: 1 pair of the 2 programs where 30% or more of one program's code is found in the other.\n", 0) == 0);
  CHECK(text.find("1. 100%  " + ana + "  and  " + ben) != std::string::npos);
  CHECK(text.find("lines 2-16 of " + ana + " and lines 4-21 of " + ben) != std::string::npos);
  // Row by row: line number and text of each, the columns 50 characters apart.
  std::string row = " 2 rLocate 400, 300";
  size_t at = text.find(row);
  REQUIRE(at != std::string::npos);
  std::string line = text.substr(at, text.find('\n', at) - at);
  CHECK(line.substr(50) == " |  4 RLOCATE 200,200   ' start here");
  CHECK(text.find("   16 return" + std::string(41, ' ') + " | 21 RETURN\n") != std::string::npos);
  CHECK(text.find("\n    4 LineWidth 4" + std::string(36, ' ') + " |  7 linewidth 2 // thick\n") != std::string::npos);
  CHECK(text.find("\n   " + std::string(50, ' ') + " |  6\n") != std::string::npos);  // a line of b alone
  CHECK(text.find("never a verdict") != std::string::npos);

  // Long lines are cut to the column.
  fs::path d2 = scratch();
  std::string longText = "x = 1\nprint \"" + std::string(200, 'y') + "\" + x + 2 * 3 + 4 * 5 + 6\nend\n";
  std::string l1 = write(d2, "l1.bas", longText);
  std::string l2 = write(d2, "l2.bas", longText);
  std::string t2 = similarityText(findSimilar({l1, l2}));
  INFO(t2);
  size_t yy = t2.find("yyyy");
  REQUIRE(yy != std::string::npos);
  std::string cutRow = t2.substr(t2.rfind('\n', yy) + 1);
  cutRow = cutRow.substr(0, cutRow.find('\n'));
  CHECK(cutRow.find("~ | ") == 3 + 49);
  CHECK(cutRow.size() == 3 + 50 + 3 + 50);

  SimilarityReport none;
  none.programs = 5;
  none.minScore = 0.3;
  CHECK(similarityText(none) ==
        "Similar code: no pair of the 5 programs where 30% or more of one program's code is found in the other.\n");
}

TEST_CASE("the JSON has every pair with its blocks and lines", "[grade][similarity]") {
  fs::path dir = scratch();
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

  CHECK(nlohmann::json::parse(similarityJson(SimilarityReport{})) == nlohmann::json::array());
}

TEST_CASE("bad input is skipped with a note, never a crash", "[grade][similarity]") {
  fs::path dir = scratch();
  std::string ana = write(dir, "ana.bas", kSquare);
  std::string ben = write(dir, "ben.bas", kSquareDisguised);
  std::string binary = write(dir, "binary.bas", std::string("\x7f" "ELF\x02\x01\x01\0\0\0\0\0", 12) + std::string(500, '\xff'));
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
  fs::path dir = scratch();
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
  for (const std::string& n : r.notes) cutNoted = cutNoted || n == oneLine + ": lines longer than 16 KiB are cut";
  CHECK(cutNoted);
}

TEST_CASE("winnowing options: k and the window", "[grade][similarity]") {
  fs::path dir = scratch();
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

// Not run by default: `rb_grade_tests "[perf]"` times a class of 1,000 generated programs.
TEST_CASE("a class of 1,000 programs", "[.perf]") {
  fs::path dir = scratch();
  std::vector<std::string> programs;
  uint64_t seed = 12345;
  auto next = [&](uint64_t n) {
    seed = seed * 6364136223846793005ull + 1442695040888963407ull;
    return (seed >> 33) % n;
  };
  const char* moves[] = {"rForward", "rTurn", "rSpeed", "rPen", "xyText", "LineWidth"};
  const char* functions[] = {"abs", "sqrt", "sin", "cos", "int", "round"};
  for (int i = 0; i < 1000; ++i) {
    std::string text = "// program " + std::to_string(i) + "\nrLocate 400, 300\nrInvisible GREEN\n";
    for (int line = 0; line < 28; ++line) {
      switch (next(5)) {
        case 0: text += std::string(moves[next(6)]) + " " + std::to_string(next(200)) + "\n"; break;
        case 1: text += "v" + std::to_string(next(9)) + " = " + functions[next(6)] + "(v" + std::to_string(next(9)) + ") + " + std::to_string(next(99)) + "\n"; break;
        case 2: text += "for n = 1 to " + std::to_string(next(9)) + "\n  rForward " + std::to_string(next(90)) + "\nnext\n"; break;
        case 3: text += "if rBumper() & " + std::to_string(next(15)) + " then rTurn " + std::to_string(next(180)) + "\n"; break;
        default: text += "print \"step\"; v" + std::to_string(next(9)) + "\n"; break;
      }
    }
    programs.push_back(write(dir, "p" + std::to_string(i) + ".bas", text));
  }
  // Ten pairs of copies.
  for (int i = 0; i < 10; ++i) fs::copy_file(programs[size_t(i)], programs[size_t(500 + i)], fs::copy_options::overwrite_existing);
  auto start = std::chrono::steady_clock::now();
  SimilarityReport r = findSimilar(programs);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  WARN("1,000 programs compared in " << seconds << " s; " << r.matching << " pairs from 30%, " << r.common
                                     << " common fingerprints");
  CHECK(r.programs == 1000);
  REQUIRE(r.pairs.size() >= 10);
  for (size_t i = 0; i < 10; ++i) CHECK(r.pairs[i].score == 1.0);
  fs::remove_all(dir);
}
