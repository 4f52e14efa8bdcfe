// libFuzzer target: the input bytes are what a teacher or a class hands rb test. They are read
// as an assignment file (TOML: every key, check kind, region, colour, group and contradiction
// rule), as a roster (CSV), and as a submission compared with a fixed program for similarity
// (rb's lexer, winnowing, the text and JSON reports). Bad input must come back as an error
// message, never a crash, a sanitizer report or a hang.

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>

#include "assignment.h"
#include "grader.h"
#include "similarity.h"

namespace {

/// A folder of its own, with the files an assignment may name already in it.
const std::string& folder() {
  static const std::string dir = [] {
    char name[] = "/tmp/rb-fuzz-grade-XXXXXX";
    if (!mkdtemp(name)) std::abort();
    std::string d = name;
    for (const char* file : {"solution.bas", "world.bas", "goal.bas", "heading.bas", "square.bas"}) {
      std::ofstream out(d + "/" + file);
      out << "rLocate 400, 300\nrPen DOWN\nfor n = 1 to 4\n  rForward 120\n  rTurn 90\nnext\nprint 4 * 120\n";
    }
    std::ofstream(d + "/roster.csv") << "student,file\nAna,square.bas\n";
    std::ofstream(d + "/clicks.events") << "key a\n";
    return d;
  }();
  return dir;
}

void write(const std::string& path, const uint8_t* data, size_t size) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string& dir = folder();
  std::string toml = dir + "/assignment.toml";
  write(toml, data, size);
  std::string error;
  std::optional<rb::grade::Assignment> a = rb::grade::loadAssignment(toml, error);
  if (a) {
    (void)a->maxPoints();
    (void)a->posts();
    (void)a->watchedColours();
    (void)a->robotChecks();
    (void)rb::grade::allChecks(*a);
  } else if (error.empty()) {
    std::abort();  // a refused file always says why
  }

  std::string roster = dir + "/fuzzed.csv";
  write(roster, data, size);
  try {
    (void)rb::grade::readRoster(roster);
  } catch (const std::runtime_error&) {
  }

  std::string program = dir + "/fuzzed.bas";
  write(program, data, size);
  rb::grade::SimilarityOptions options;
  options.minShared = 1;
  options.minScore = 0;
  rb::grade::SimilarityReport report = rb::grade::findSimilar({program, dir + "/square.bas"}, options);
  (void)rb::grade::similarityText(report);
  (void)rb::grade::similarityJson(report);
  return 0;
}
