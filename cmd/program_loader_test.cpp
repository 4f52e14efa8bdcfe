#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "program_loader.h"

using namespace rb;
using namespace rb::cli;

namespace {

/// Every diagnostic of a loaded file, formatted, one after another.
std::string allDiagnostics(const LoadedFile& f) {
  std::string out;
  for (const Diagnostic& d : f.diags.all()) out += formatDiagnostic(f.program->sources, d);
  return out;
}

/// The golden programs and diagnostics inputs: programs with every kind of statement and error.
std::vector<std::string> testPrograms() {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::recursive_directory_iterator(RB_TESTDATA_DIR))
    if (e.is_regular_file() && e.path().extension() == ".bas") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

TEST_CASE("rb check finds the same diagnostics without keeping the compiled code", "[check]") {
  std::vector<std::string> files = testPrograms();
  REQUIRE(files.size() > 100);
  for (const std::string& file : files) {
    INFO(file);
    LoadedFile kept = loadFile(file, CompileOptions{}, true);
    CompileOptions dropped;
    dropped.keepCode = false;
    LoadedFile checked = loadFile(file, dropped, true);
    REQUIRE(kept.program);
    REQUIRE(checked.program);
    CHECK(allDiagnostics(checked) == allDiagnostics(kept));
    CHECK(bool(checked.compiled) == bool(kept.compiled));
    if (checked.compiled) CHECK(checked.compiled->code.empty());
  }
}
