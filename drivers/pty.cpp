#include "pty.h"

#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>  // posix_openpt, grantpt, unlockpt, ptsname
#include <cstring>
#include <filesystem>
#include <system_error>

#include "base/runtime_error.h"

namespace fs = std::filesystem;

namespace rb::drivers {

Pty::Pty() {
  master_ = ::posix_openpt(O_RDWR | O_NOCTTY);
  if (master_ < 0) throw RuntimeError(std::string("cannot open a pseudo-terminal: ") + std::strerror(errno));
  char name[128] = {};
  bool ok = ::grantpt(master_) == 0 && ::unlockpt(master_) == 0;
#ifdef __linux__
  ok = ok && ::ptsname_r(master_, name, sizeof name) == 0;
#else
  // ptsname's static buffer: rb opens its one pty before any other thread exists.
  const char* n = ok ? ::ptsname(master_) : nullptr;
  ok = ok && n && std::strlen(n) < sizeof name;
  if (ok) std::strncpy(name, n, sizeof name - 1);
#endif
  if (!ok) {
    int e = errno;
    close();
    throw RuntimeError(std::string("cannot set up a pseudo-terminal: ") + std::strerror(e));
  }
  slavePath_ = name;
  ::fcntl(master_, F_SETFD, FD_CLOEXEC);
  ::fcntl(master_, F_SETFL, ::fcntl(master_, F_GETFL) | O_NONBLOCK);
  // Raw from the start, so that nothing is echoed or line-buffered before a client has set the
  // port up itself (on Linux the master's settings are the slave's).
  termios t{};
  if (::tcgetattr(master_, &t) == 0) {
    ::cfmakeraw(&t);
    ::tcsetattr(master_, TCSANOW, &t);
  }
}

Pty::~Pty() { close(); }

void Pty::close() {
  if (master_ >= 0) ::close(master_);
  master_ = -1;
}

SymlinkGuard::SymlinkGuard(std::string link, const std::string& target)
    : link_(std::move(link)), target_(target) {
  std::error_code ec;
  fs::file_status st = fs::symlink_status(link_, ec);
  if (fs::exists(st) && !fs::is_symlink(st))
    throw RuntimeError("cannot create the link " + link_ + ": a file that is not a symbolic link is there");
  // Made under a temporary name and renamed over the old one, so the name never dangles.
  std::string temp = link_ + ".tmp" + std::to_string(::getpid());
  fs::remove(temp, ec);
  fs::create_symlink(target_, temp, ec);
  if (!ec) fs::rename(temp, link_, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(temp, ignored);
    throw RuntimeError("cannot create the link " + link_ + ": " + ec.message());
  }
}

SymlinkGuard::~SymlinkGuard() {
  // Only our own link: another emulator may have taken the name over since.
  std::error_code ec;
  if (fs::is_symlink(link_, ec) && fs::read_symlink(link_, ec) == fs::path(target_)) fs::remove(link_, ec);
}

}  // namespace rb::drivers
