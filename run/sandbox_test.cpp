#include "sandbox.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "base/runtime_error.h"

using namespace rb;
using namespace rb::cli;
namespace fs = std::filesystem;

namespace {
struct TempTree {
  fs::path root;
  TempTree() {
    root = fs::temp_directory_path() / ("rb_sandbox_" + std::to_string(::getpid()));
    fs::remove_all(root);
    fs::create_directories(root / "class" / "sub");
    fs::create_directories(root / "other");
    std::ofstream(root / "class" / "a.txt") << "a";
    std::ofstream(root / "other" / "b.txt") << "b";
    fs::create_directory_symlink(root / "other", root / "class" / "link");
  }
  ~TempTree() { fs::remove_all(root); }
};
}  // namespace

TEST_CASE("sandbox: files inside the program's folder only", "[sandbox]") {
  TempTree t;
  Sandbox box((t.root / "class").string(), {}, false);
  CHECK(box.fileExists("FileExists", "a.txt"));
  CHECK_FALSE(box.fileExists("FileExists", "sub/none.txt"));
  CHECK_THROWS_AS(box.fileExists("FileExists", "../other/b.txt"), RuntimeError);
  CHECK_THROWS_AS(box.fileExists("FileExists", (t.root / "other" / "b.txt").string()), RuntimeError);
  // A symbolic link cannot lead out either.
  CHECK_THROWS_AS(box.fileExists("FileExists", "link/b.txt"), RuntimeError);
  CHECK_THROWS_AS(box.setDirectory("DirSet", ".."), RuntimeError);
  box.setDirectory("DirSet", "sub");
  CHECK(box.fileExists("FileExists", "../a.txt"));
  CHECK_THROWS_AS(box.spawn("Spawn", "true", true), RuntimeError);
}

TEST_CASE("sandbox: --allow-files and --allow-spawn open more", "[sandbox]") {
  TempTree t;
  Sandbox box((t.root / "class").string(), {(t.root / "other").string()}, true);
  CHECK(box.fileExists("FileExists", "../other/b.txt"));
  CHECK(box.fileExists("FileExists", "link/b.txt"));
  box.renameFile("FileRename", "../other/b.txt", "../other/c.txt");
  CHECK(fs::exists(t.root / "other" / "c.txt"));
  CHECK(box.spawn("Spawn", "exit 7", true) == 7);
  CHECK(box.spawn("Spawn", "true", false) == 1);
}
