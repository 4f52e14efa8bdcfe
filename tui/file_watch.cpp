#include "file_watch.h"

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <filesystem>

#include "files.h"

#ifdef __linux__
#include <sys/inotify.h>
#include <unistd.h>
#endif

namespace rb::tui {

namespace {

/// stat's modification time in nanoseconds and size; false when the file is not there.
bool statOf(const std::string& path, long long& mtimeNs, long long& size) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return false;
#ifdef __APPLE__
  mtimeNs = static_cast<long long>(st.st_mtimespec.tv_sec) * 1000000000LL + st.st_mtimespec.tv_nsec;
#else
  mtimeNs = static_cast<long long>(st.st_mtim.tv_sec) * 1000000000LL + st.st_mtim.tv_nsec;
#endif
  size = static_cast<long long>(st.st_size);
  return true;
}

}  // namespace

FileWatch::FileWatch(Mode mode) {
#ifdef __linux__
  if (mode == Mode::Auto) fd_ = ::inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
#else
  (void)mode;
#endif
}

FileWatch::~FileWatch() {
  closeWatches();
#ifdef __linux__
  if (fd_ >= 0) ::close(fd_);
#endif
}

void FileWatch::closeWatches() {
#ifdef __linux__
  for (int wd : watches_) ::inotify_rm_watch(fd_, wd);
#endif
  watches_.clear();
  watchedFolders_.clear();
}

void FileWatch::watch(const std::vector<std::string>& paths) {
  closeWatches();
  files_.clear();
  for (const std::string& path : paths) {
    File f;
    f.path = path;
    std::error_code ec;
    std::filesystem::path full = std::filesystem::absolute(path, ec);
    if (ec) full = path;
    f.folder = full.parent_path().string();
    f.name = full.filename().string();
    f.bytes = run::readFile(path);
    f.existed = statOf(path, f.mtimeNs, f.size);
    files_.push_back(std::move(f));
  }
#ifdef __linux__
  if (fd_ >= 0) {
    // The folders, not the files: a save that renames a new file over the old one replaces
    // the inode a watch on the file would follow.
    constexpr uint32_t kEvents = IN_CLOSE_WRITE | IN_MODIFY | IN_ATTRIB | IN_CREATE | IN_DELETE |
                                 IN_MOVED_FROM | IN_MOVED_TO;
    for (const File& f : files_) {
      auto& folders = watchedFolders_;
      if (std::find(folders.begin(), folders.end(), f.folder) != folders.end()) continue;
      int wd = ::inotify_add_watch(fd_, f.folder.c_str(), kEvents);
      if (wd < 0) {
        // A folder inotify will not watch (a network file system, the watch limit): poll all.
        closeWatches();
        ::close(fd_);
        fd_ = -1;
        break;
      }
      watches_.push_back(wd);
      watchedFolders_.push_back(f.folder);
    }
    drainEvents();  // what happened before this call is measured by the bytes, not by events
  }
#endif
  pending_ = false;
  reported_ = false;
  lastPoll_ = Clock::now();
}

bool FileWatch::drainEvents() {
  bool relevant = false;
#ifdef __linux__
  alignas(struct inotify_event) char buf[8192];
  for (;;) {
    ssize_t n = ::read(fd_, buf, sizeof buf);
    if (n <= 0) break;  // EAGAIN: nothing more now
    for (ssize_t at = 0; at < n;) {
      const auto* e = reinterpret_cast<const struct inotify_event*>(buf + at);
      at += static_cast<ssize_t>(sizeof(struct inotify_event) + e->len);
      if (e->mask & IN_Q_OVERFLOW) {
        relevant = true;
        continue;
      }
      auto folder = std::find(watches_.begin(), watches_.end(), e->wd);
      if (folder == watches_.end() || e->len == 0) continue;
      const std::string& dir = watchedFolders_[static_cast<size_t>(folder - watches_.begin())];
      std::string name = e->name;  // NUL-padded to e->len
      for (const File& f : files_)
        if (f.folder == dir && f.name == name) relevant = true;
    }
  }
#endif
  return relevant;
}

bool FileWatch::statsChanged() {
  bool any = false;
  for (File& f : files_) {
    long long mtime = 0, size = 0;
    bool exists = statOf(f.path, mtime, size);
    if (exists != f.existed || mtime != f.mtimeNs || size != f.size) any = true;
    f.existed = exists;
    f.mtimeNs = mtime;
    f.size = size;
  }
  return any;
}

bool FileWatch::changed() {
  if (reported_ || files_.empty()) return false;
  Clock::time_point now = Clock::now();
  bool happened = false;
  if (fd_ >= 0) {
    happened = drainEvents();
  } else if (now - lastPoll_ >= kPollInterval) {
    lastPoll_ = now;
    happened = statsChanged();
  }
  if (happened) {
    pending_ = true;
    lastEvent_ = now;
  }
  if (!pending_ || now - lastEvent_ < kSettle) return false;
  pending_ = false;
  for (const File& f : files_) {
    if (run::readFile(f.path) != f.bytes) {
      reported_ = true;
      return true;
    }
  }
  return false;
}

}  // namespace rb::tui
