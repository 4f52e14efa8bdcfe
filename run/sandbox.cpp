#include "sandbox.h"

#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#if defined(__linux__)
#include <linux/openat2.h>
#include <sys/syscall.h>
#endif

#include <cerrno>
#include <cstring>
#include <algorithm>
#include <deque>
#include <filesystem>
#include <system_error>

#include "base/runtime_error.h"
#include "base/text.h"

extern char** environ;

namespace rb::run {

namespace fs = std::filesystem;

namespace {

/// A canonical absolute folder (links resolved), or the absolute lexical form when it does not
/// exist yet; a folder that cannot be resolved keeps its lexical form and so matches nothing the
/// kernel resolves.
std::string canonicalFolder(const fs::path& p) {
  std::error_code ec;
  fs::path abs = fs::absolute(p, ec);
  fs::path c = fs::weakly_canonical(abs, ec);
  return (ec ? abs.lexically_normal() : c).string();
}

/// `rest` when `path` is `root` or lies lexically below it.
bool below(const std::string& path, const std::string& root, std::string& rest) {
  if (path.compare(0, root.size(), root) != 0) return false;
  if (path.size() == root.size()) {
    rest.clear();
    return true;
  }
  if (root.back() == '/') {
    rest = path.substr(root.size());
    return true;
  }
  if (path[root.size()] != '/') return false;
  rest = path.substr(root.size() + 1);
  return true;
}

std::string join(const std::string& a, const std::string& b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  return a + "/" + b;
}

/// 'name' for a message, with its control characters escaped (a NUL as \x00): whole, and
/// harmless on a terminal.
std::string quoted(const std::string& s) { return cQuoted(s, std::string_view::npos, '\''); }

/// The last component of `path` and the folder it is in ("" when none), trailing slashes aside.
std::pair<std::string, std::string> splitLast(std::string path) {
  while (path.size() > 1 && path.back() == '/') path.pop_back();
  size_t slash = path.rfind('/');
  if (slash == std::string::npos) return {"", path};
  return {slash == 0 ? "/" : path.substr(0, slash), path.substr(slash + 1)};
}

}  // namespace

Sandbox::Sandbox(std::string home, std::vector<std::string> allowed, bool allowSpawn) : allowSpawn_(allowSpawn) {
  auto add = [&](const fs::path& p) {
    Root r;
    r.path = canonicalFolder(p);
    r.fd = ::open(r.path.c_str(), O_PATH | O_DIRECTORY | O_CLOEXEC);
    roots_.push_back(std::move(r));
  };
  add(home.empty() ? fs::path(".") : fs::path(home));
  for (const std::string& a : allowed) add(a);
  if (roots_[0].fd >= 0) currentFd_ = ::dup(roots_[0].fd);
}

Sandbox::~Sandbox() {
  for (const Root& r : roots_)
    if (r.fd >= 0) ::close(r.fd);
  if (currentFd_ >= 0) ::close(currentFd_);
}

int Sandbox::openBeneath(size_t root, const std::string& below, int flags) const {
  if (roots_[root].fd < 0) {
    errno = ENOENT;
    return -1;
  }
#if defined(__linux__) && defined(SYS_openat2)
  if (!byComponents_) {
    open_how how{};
    how.flags = static_cast<uint64_t>(flags | O_CLOEXEC);
    how.resolve = RESOLVE_BENEATH | RESOLVE_NO_MAGICLINKS;
    long fd = ::syscall(SYS_openat2, roots_[root].fd, below.empty() ? "." : below.c_str(), &how, sizeof how);
    if (fd >= 0 || errno != ENOSYS) return static_cast<int>(fd);
  }
#endif
  return walkBeneath(root, below, flags);
}

int Sandbox::walkBeneath(size_t root, const std::string& below, int flags) const {
  // The folders walked through, the root first: ".." pops one, and popping the root is leaving
  // it. Links are read and their target's components walked in their place.
  std::vector<int> stack{::dup(roots_[root].fd)};
  auto closeAll = [&](int error) {
    for (int fd : stack)
      if (fd >= 0) ::close(fd);
    errno = error;
    return -1;
  };
  if (stack[0] < 0) return closeAll(errno);
  if (below.size() >= PATH_MAX) return closeAll(ENAMETOOLONG);
  std::deque<std::string> parts;
  auto push = [&](const std::string& text, bool front) {
    std::vector<std::string> split;
    for (size_t at = 0; at <= text.size();) {
      size_t slash = std::min(text.find('/', at), text.size());
      split.push_back(text.substr(at, slash - at));
      at = slash + 1;
    }
    if (front) parts.insert(parts.begin(), split.begin(), split.end());
    else parts.insert(parts.end(), split.begin(), split.end());
  };
  push(below, false);
  int links = 0;
  int last = -1;  // the object the walk ended on, O_PATH
  while (!parts.empty()) {
    std::string part = std::move(parts.front());
    parts.pop_front();
    if (last >= 0) {  // a file was reached with more components to go
      ::close(last);
      return closeAll(ENOTDIR);
    }
    if (part.empty() || part == ".") continue;
    if (part.size() > NAME_MAX) return closeAll(ENAMETOOLONG);
    if (part == "..") {
      if (stack.size() == 1) return closeAll(EXDEV);
      ::close(stack.back());
      stack.pop_back();
      continue;
    }
    int fd = ::openat(stack.back(), part.c_str(), O_PATH | O_NOFOLLOW | O_CLOEXEC);
    if (fd < 0) return closeAll(errno);
    struct stat st{};
    if (::fstat(fd, &st) != 0) {
      int e = errno;
      ::close(fd);
      return closeAll(e);
    }
    if (S_ISLNK(st.st_mode)) {
      ::close(fd);
      if (++links > 40) return closeAll(ELOOP);
      char target[PATH_MAX];
      ssize_t n = ::readlinkat(stack.back(), part.c_str(), target, sizeof target - 1);
      if (n < 0) return closeAll(errno);
      if (n == 0 || target[0] == '/') return closeAll(EXDEV);  // as RESOLVE_BENEATH: no absolute link
      push(std::string(target, static_cast<size_t>(n)), true);
      continue;
    }
    if (S_ISDIR(st.st_mode)) stack.push_back(fd);
    else last = fd;
  }
  // The walk opens O_PATH only, which is all the sandbox asks for.
  int fd = -1, error = 0;
  if ((flags & O_DIRECTORY) && last >= 0) error = ENOTDIR;
  else if ((fd = ::fcntl(last >= 0 ? last : stack.back(), F_DUPFD_CLOEXEC, 0)) < 0) error = errno;
  if (last >= 0) ::close(last);
  closeAll(error);
  return fd;
}

std::vector<Sandbox::Place> Sandbox::places(std::string_view who, const std::string& path) const {
  if (path.empty()) throw RuntimeError(std::string(who) + ": the file name is empty");
  if (path.find('\0') != std::string::npos)
    throw RuntimeError(std::string(who) + ": " + quoted(path) + " is not a file name (it holds a NUL character)");
  std::vector<Place> out;
  std::string rest;
  std::string absolute;
  if (path[0] == '/') {
    absolute = path;
    for (size_t i = 0; i < roots_.size(); ++i)
      if (below(path, roots_[i].path, rest)) out.push_back({i, rest});
  } else {
    out.push_back({current_.root, join(current_.below, path)});
    absolute = join(roots_[current_.root].path, join(current_.below, path));
  }
  // The same name with its links resolved: a link into another folder the run may reach
  // (--allow-files) is followed there. What it resolves to is opened beneath that folder again.
  std::error_code ec;
  if (absolute.size() < PATH_MAX) {
    std::string canonical = fs::weakly_canonical(fs::path(absolute), ec).string();
    if (!ec)
      for (size_t i = 0; i < roots_.size(); ++i)
        if (below(canonical, roots_[i].path, rest)) out.push_back({i, rest});
  }
  return out;
}

void Sandbox::refuse(std::string_view who, const std::string& path, int error) const {
  std::string name = quoted(path);
  switch (error) {
    case EXDEV:
      throw RuntimeError(std::string(who) + ": " + name +
                         " is outside the program's folder; rb lets a program reach only its own "
                         "folder (rb run --allow-files DIR allows another)");
    case ELOOP:
      throw RuntimeError(std::string(who) + ": " + name + " cannot be followed: too many symbolic links (a loop?)");
    case ENAMETOOLONG:
      throw RuntimeError(std::string(who) + ": " + name.substr(0, 60) + (name.size() > 60 ? "...'" : "") +
                         " is too long a file name");
    default:
      throw RuntimeError(std::string(who) + ": " + name + ": " + std::strerror(error));
  }
}

int Sandbox::open(std::string_view who, const std::string& path, int flags, Place* where) const {
  std::vector<Place> candidates = places(who, path);
  int firstError = EXDEV;
  for (const Place& p : candidates) {
    int fd = openBeneath(p.root, p.below, flags);
    int e = errno;
    if (fd >= 0) {
      if (where) *where = p;
      return fd;
    }
    if (e == ENOENT || e == ENOTDIR) {
      // Resolved inside the folder, and not there.
      if (where) *where = p;
      errno = e;
      return -1;
    }
    if (firstError == EXDEV) firstError = e;
  }
  refuse(who, path, firstError);
}

bool Sandbox::fileExists(std::string_view who, const std::string& path) {
  int fd = open(who, path, O_PATH);
  if (fd < 0) return false;
  struct stat st{};
  bool regular = ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode);
  ::close(fd);
  return regular;
}

void Sandbox::renameFile(std::string_view who, const std::string& from, const std::string& to) {
  auto parent = [&](const std::string& name, std::string& last) {
    if (name.empty()) throw RuntimeError(std::string(who) + ": the file name is empty");
    auto [folder, file] = splitLast(name);
    if (file.empty() || file == "." || file == ".." || file == "/")
      throw RuntimeError(std::string(who) + ": " + quoted(name) + " is not a file name");
    last = file;
    int fd = open(who, folder.empty() ? "." : folder, O_PATH | O_DIRECTORY);
    if (fd < 0) {
      int e = errno;
      throw RuntimeError(std::string(who) + ": cannot rename " + quoted(from) + " to " + quoted(to) + ": " +
                         std::strerror(e));
    }
    return fd;
  };
  std::string a, b;
  int fromDir = parent(from, a);
  int toDir = -1;
  try {
    toDir = parent(to, b);
  } catch (...) {
    ::close(fromDir);
    throw;
  }
  int rc = ::renameat(fromDir, a.c_str(), toDir, b.c_str());
  int e = errno;
  ::close(fromDir);
  ::close(toDir);
  if (rc != 0)
    throw RuntimeError(std::string(who) + ": cannot rename " + quoted(from) + " to " + quoted(to) + ": " +
                       std::strerror(e));
}

void Sandbox::setDirectory(std::string_view who, const std::string& path) {
  Place where;
  int fd = open(who, path, O_PATH | O_DIRECTORY, &where);
  if (fd < 0) throw RuntimeError(std::string(who) + ": " + quoted(path) + " is not a folder");
  // The folder's place below its root as the kernel resolved it, when /proc can tell; else as
  // written (it is resolved beneath the root again each time it is used).
  std::string rel = where.below;
  char link[PATH_MAX];
  std::string self = "/proc/self/fd/" + std::to_string(fd);
  ssize_t n = ::readlink(self.c_str(), link, sizeof link - 1);
  std::string rest;
  if (n > 0 && below(std::string(link, static_cast<size_t>(n)), roots_[where.root].path, rest)) rel = rest;
  if (rel.size() >= PATH_MAX) {
    ::close(fd);
    refuse(who, path, ENAMETOOLONG);
  }
  current_ = {where.root, rel};
  if (currentFd_ >= 0) ::close(currentFd_);
  currentFd_ = fd;
}

int64_t Sandbox::spawn(std::string_view who, const std::string& command, bool wait,
                       const std::function<void()>& checkpoint) {
  if (!allowSpawn_)
    throw RuntimeError(std::string(who) + ": running other programs is not allowed; rb run "
                       "--allow-spawn allows it");
  const char* argv[] = {"/bin/sh", "-c", command.c_str(), nullptr};
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (currentFd_ >= 0) posix_spawn_file_actions_addfchdir_np(&actions, currentFd_);
  pid_t pid = 0;
  int rc = posix_spawn(&pid, "/bin/sh", &actions, nullptr, const_cast<char**>(argv), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0)
    throw RuntimeError(std::string(who) + ": cannot start " + quoted(command) + ": " +
                       std::generic_category().message(rc));
  if (!wait) return 1;
  // Waited for a little at a time, the run's limits looked at in between: a command that never
  // ends is ended with the run.
  int status = 0;
  for (int pause = 1;; pause = std::min(pause * 2, 20)) {
    pid_t got = waitpid(pid, &status, WNOHANG);
    if (got == pid) break;
    if (got < 0 && errno != EINTR) return -1;
    try {
      if (checkpoint) checkpoint();
    } catch (...) {
      ::kill(pid, SIGKILL);
      while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
      }
      throw;
    }
    ::usleep(static_cast<useconds_t>(pause) * 1000);
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace rb::run
