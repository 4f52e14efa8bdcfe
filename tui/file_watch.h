#pragma once
// Tells when the files a program was loaded from change on disk, for `rb run --tui --watch`,
// which runs the program again when it is saved. On Linux it listens with inotify to the folders
// that hold the files, so that an editor that saves by writing a new file and renaming it over
// the old one is seen too; elsewhere (or when inotify cannot be had) it looks at each file's
// modification time and size every kPollInterval. Either way a change counts only once the
// file's bytes differ from what they were when watch() was called, and only after no further
// change came for kSettle: editors write a file in several steps (truncate, write, rename), and
// a save that leaves the bytes as they were (`touch`, saving an unchanged buffer) is no change.

#include <chrono>
#include <optional>
#include <string>
#include <vector>

namespace rb::tui {

class FileWatch {
 public:
  using Clock = std::chrono::steady_clock;

  enum class Mode {
    Auto,  ///< inotify where there is one, else polling
    Poll,  ///< polling only (the fallback; tests choose it to cover it on Linux too)
  };
  static constexpr auto kPollInterval = std::chrono::milliseconds(500);
  static constexpr auto kSettle = std::chrono::milliseconds(150);

  explicit FileWatch(Mode mode = Mode::Auto);
  ~FileWatch();
  FileWatch(const FileWatch&) = delete;
  FileWatch& operator=(const FileWatch&) = delete;

  /// Watches these files from now on (instead of those of an earlier call); their bytes now
  /// are what a change is measured against. A file that does not exist may be watched: its
  /// appearing is a change.
  void watch(const std::vector<std::string>& paths);
  /// Never blocks: true when a watched file changed since watch() (see above). Once it has
  /// said so it says so again only after the next watch().
  bool changed();
  /// True when the watch listens with inotify (false: it polls).
  bool listens() const { return fd_ >= 0; }

 private:
  struct File {
    std::string path;      ///< as given
    std::string folder;    ///< the folder that holds it (absolute)
    std::string name;      ///< its name in that folder
    std::optional<std::string> bytes;  ///< at watch() (nullopt: it did not exist)
    // Polling: what stat said last.
    bool existed = false;
    long long mtimeNs = 0;
    long long size = 0;
  };

  /// Reads inotify's events; true when one concerns a watched file (or events were lost).
  bool drainEvents();
  /// Polling: true when a watched file's stat changed since the last look.
  bool statsChanged();
  void closeWatches();

  std::vector<File> files_;
  int fd_ = -1;                ///< inotify (-1: polling)
  std::vector<int> watches_;   ///< inotify watch descriptors, one per folder
  std::vector<std::string> watchedFolders_;  ///< the folder of each watch descriptor
  bool pending_ = false;       ///< something happened: compare the bytes once it settles
  bool reported_ = false;      ///< changed() said true since the last watch()
  Clock::time_point lastEvent_{};
  Clock::time_point lastPoll_{};
};

}  // namespace rb::tui
