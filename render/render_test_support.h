#pragma once
// Helpers for render's unit tests: run a program in-process and keep its Machine (so the test
// can picture the screen), find files of the source tree, compare with golden files, and make
// temporary file names. Tests only: nothing in the library includes this.

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include <unistd.h>

#include "lang/compiler.h"
#include "machine/interpreter.h"
#include "lang/loader.h"
#include "machine/machine.h"
#include "robot_view.h"
#include "machine/test_support.h"

namespace rb::render::test {

/// A finished run: the host outlives the machine that refers to it.
struct PictureRun {
  rb::test::TestHost host;            ///< records output; a virtual clock
  std::unique_ptr<Machine> machine;   ///< the screen and the robot after the run
  RunResult result;                   ///< how the run ended
  std::string diagnostics;            ///< load errors and the runtime error, formatted
  bool loaded = false;                ///< false when the program did not compile

  /// The robot as the pictures draw it.
  RobotView robot() const { return robotView(*machine); }
  /// The screen.
  const Canvas& canvas() const { return machine->canvas(); }
};

/// Loads, compiles and runs `text` (as "test.bas") with seed 1.
inline std::unique_ptr<PictureRun> runForPicture(const std::string& text, RunLimits limits = {}) {
  auto run = std::make_unique<PictureRun>();
  rb::test::MemoryReader reader;
  reader.files["test.bas"] = text;
  DiagnosticList diags;
  auto loaded = loadProgram("test.bas", text, reader, standardBuiltins(), {}, diags);
  auto program = compileProgram(*loaded, {}, diags);
  for (const Diagnostic& d : diags.all()) run->diagnostics += formatDiagnostic(loaded->sources, d);
  run->machine = std::make_unique<Machine>(run->host, 1);
  run->machine->canvas().keepDisplayList(true);  // the SVG tests read it
  if (!program) return run;
  run->loaded = true;
  Interpreter interp(*program, *run->machine);
  run->result = interp.run(limits);
  if (run->result.error) run->diagnostics += formatDiagnostic(loaded->sources, *run->result.error);
  return run;
}

/// The source tree's root: $RB_SOURCE_DIR, else two folders above this header (CMake compiles
/// with absolute paths, so __FILE__ is absolute).
inline std::filesystem::path sourceRoot() {
  if (const char* dir = std::getenv("RB_SOURCE_DIR"); dir && *dir) return dir;
  return std::filesystem::path(__FILE__).parent_path().parent_path();
}

/// A whole file's text; empty when it cannot be read.
inline std::string readText(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// A file name in the temporary folder, unique to this process and `name`; removed by the
/// destructor.
class TempFile {
 public:
  explicit TempFile(const std::string& name)
      : path_(std::filesystem::temp_directory_path() /
              ("rb_render_test_" + std::to_string(::getpid()) + "_" + name)) {}
  ~TempFile() {
    std::error_code ignored;
    std::filesystem::remove(path_, ignored);
  }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  /// The file's path.
  std::string str() const { return path_.string(); }

 private:
  std::filesystem::path path_;
};

/// The result of comparing with a golden file.
struct GoldenResult {
  bool matched = false;
  bool updated = false;  ///< RB_UPDATE_GOLDEN=1 rewrote the file
  std::string message;   ///< why it did not match (the first differing line)
};

/// Compares `actual` with testdata/render/NAME. With RB_UPDATE_GOLDEN=1 in the environment the
/// file is rewritten instead (review the diff before committing it).
inline GoldenResult checkGolden(const std::string& name, const std::string& actual) {
  GoldenResult r;
  const std::filesystem::path path = sourceRoot() / "testdata" / "render" / name;
  if (const char* update = std::getenv("RB_UPDATE_GOLDEN"); update && std::string(update) == "1") {
    std::ofstream(path, std::ios::binary) << actual;
    r.matched = r.updated = true;
    return r;
  }
  if (!std::filesystem::exists(path)) {
    r.message = path.string() + " is missing: run the test with RB_UPDATE_GOLDEN=1 to make it";
    return r;
  }
  const std::string expected = readText(path);
  if (expected == actual) {
    r.matched = true;
    return r;
  }
  std::istringstream e(expected), a(actual);
  std::string el, al;
  for (int line = 1;; ++line) {
    bool moreE = static_cast<bool>(std::getline(e, el)), moreA = static_cast<bool>(std::getline(a, al));
    if (!moreE && !moreA) break;
    if (el != al || moreE != moreA) {
      r.message = path.string() + ":" + std::to_string(line) + " differs\n expected: " +
                  (moreE ? el : "<end>") + "\n actual:   " + (moreA ? al : "<end>") +
                  "\n(RB_UPDATE_GOLDEN=1 rewrites the golden files)";
      break;
    }
  }
  return r;
}

}  // namespace rb::render::test
