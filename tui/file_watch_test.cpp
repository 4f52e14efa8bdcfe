// FileWatch: saves seen by inotify and by polling, settled, and measured by the file's bytes.
// The waits poll changed() until a generous deadline: nothing here times how fast it is.
#include <catch2/catch.hpp>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <thread>

#include "file_watch.h"

using namespace rb::tui;
namespace fs = std::filesystem;

namespace {

struct TempFolder {
  fs::path root;
  TempFolder() {
    static int n = 0;
    root = fs::temp_directory_path() /
           ("rb_watch_" + std::to_string(::getpid()) + "_" + std::to_string(n++));
    fs::create_directories(root);
  }
  ~TempFolder() {
    std::error_code ec;
    fs::remove_all(root, ec);
  }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(root / name, std::ios::binary) << text;
    return (root / name).string();
  }
};

/// changed() within `seconds`, asking as the live view does (every few milliseconds).
bool changesWithin(FileWatch& w, double seconds) {
  auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    if (w.changed()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

/// Makes sure the next write gets another modification time, even on a coarse clock.
void later() { std::this_thread::sleep_for(std::chrono::milliseconds(20)); }

void savesAreSeen(FileWatch::Mode mode) {
  TempFolder dir;
  std::string prog = dir.write("prog.bas", "print 1\n");
  std::string inc = dir.write("lib.bas", "x = 1\n");
  FileWatch w(mode);
  w.watch({prog, inc});
  CHECK_FALSE(changesWithin(w, 0.8));

  // A plain write.
  later();
  dir.write("prog.bas", "print 2\n");
  CHECK(changesWithin(w, 5));
  CHECK_FALSE(w.changed());  // said once, until the next watch()

  // An editor that writes a new file and renames it over the old one; an included file.
  w.watch({prog, inc});
  later();
  dir.write("lib.bas.tmp", "x = 2\n");
  fs::rename(dir.root / "lib.bas.tmp", dir.root / "lib.bas");
  CHECK(changesWithin(w, 5));

  // Bytes as they were: no change (touch, saving an unchanged buffer); other files: none.
  w.watch({prog, inc});
  later();
  dir.write("prog.bas", "print 2\n");
  dir.write("notes.txt", "hello\n");
  CHECK_FALSE(changesWithin(w, 1.2));

  // A file that goes away and comes back with other bytes.
  fs::remove(dir.root / "prog.bas");
  later();
  dir.write("prog.bas", "print 3\n");
  CHECK(changesWithin(w, 5));
}

}  // namespace

TEST_CASE("file watch: saves, renames, includes, unchanged bytes (inotify where there is one)", "[watch]") {
  savesAreSeen(FileWatch::Mode::Auto);
#ifdef __linux__
  FileWatch w;
  CHECK(w.listens());
#endif
}

TEST_CASE("file watch: the same by polling", "[watch]") {
  FileWatch w(FileWatch::Mode::Poll);
  CHECK_FALSE(w.listens());
  savesAreSeen(FileWatch::Mode::Poll);
}

TEST_CASE("file watch: a file that did not exist appears", "[watch]") {
  TempFolder dir;
  std::string prog = (dir.root / "new.bas").string();
  FileWatch w;
  w.watch({prog});
  CHECK_FALSE(w.changed());
  dir.write("new.bas", "print 1\n");
  CHECK(changesWithin(w, 5));
}
