#include "sandbox.h"

#include <spawn.h>
#include <sys/wait.h>

#include <filesystem>
#include <system_error>

#include "base/runtime_error.h"
#include "base/text.h"

extern char** environ;

namespace rb::cli {

namespace fs = std::filesystem;

namespace {

/// An absolute path with `.`, `..` and symbolic links of its existing part resolved, so that
/// `../x` or a link cannot lead out of a folder.
std::string normalize(const fs::path& p) {
  std::error_code ec;
  fs::path n = fs::weakly_canonical(fs::absolute(p, ec), ec);
  if (ec) n = fs::absolute(p).lexically_normal();
  return n.string();
}

bool inside(const std::string& path, const std::string& root) {
  if (path.compare(0, root.size(), root) != 0) return false;
  return path.size() == root.size() || path[root.size()] == '/' || root.back() == '/';
}

/// 'name' for a message, with its control characters escaped (a NUL as \x00): whole, and
/// harmless on a terminal.
std::string quoted(const std::string& s) { return cQuoted(s, std::string_view::npos, '\''); }

}  // namespace

Sandbox::Sandbox(std::string home, std::vector<std::string> allowed, bool allowSpawn)
    : allowSpawn_(allowSpawn) {
  roots_.push_back(normalize(home.empty() ? fs::path(".") : fs::path(home)));
  for (const std::string& a : allowed) roots_.push_back(normalize(a));
  current_ = roots_[0];
}

std::string Sandbox::resolve(std::string_view who, const std::string& path) const {
  if (path.empty()) throw RuntimeError(std::string(who) + ": the file name is empty");
  std::string full = normalize(fs::path(current_) / path);
  for (const std::string& root : roots_)
    if (inside(full, root)) return full;
  throw RuntimeError(std::string(who) + ": " + quoted(path) +
                     " is outside the program's folder; rb lets a program reach only its own "
                     "folder (rb run --allow-files DIR allows another)");
}

bool Sandbox::fileExists(std::string_view who, const std::string& path) {
  std::string full = resolve(who, path);
  std::error_code ec;
  return fs::is_regular_file(full, ec);
}

void Sandbox::renameFile(std::string_view who, const std::string& from, const std::string& to) {
  std::string a = resolve(who, from);
  std::string b = resolve(who, to);
  std::error_code ec;
  fs::rename(a, b, ec);
  if (ec)
    throw RuntimeError(std::string(who) + ": cannot rename " + quoted(from) + " to " + quoted(to) +
                       ": " + ec.message());
}

void Sandbox::setDirectory(std::string_view who, const std::string& path) {
  std::string full = resolve(who, path);
  std::error_code ec;
  if (!fs::is_directory(full, ec))
    throw RuntimeError(std::string(who) + ": " + quoted(path) + " is not a folder");
  current_ = full;
}

int64_t Sandbox::spawn(std::string_view who, const std::string& command, bool wait) {
  if (!allowSpawn_)
    throw RuntimeError(std::string(who) + ": running other programs is not allowed; rb run "
                       "--allow-spawn allows it");
  const char* argv[] = {"/bin/sh", "-c", command.c_str(), nullptr};
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addchdir_np(&actions, current_.c_str());
  pid_t pid = 0;
  int rc = posix_spawn(&pid, "/bin/sh", &actions, nullptr, const_cast<char**>(argv), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0)
    throw RuntimeError(std::string(who) + ": cannot start " + quoted(command) + ": " +
                       std::generic_category().message(rc));
  if (!wait) return 1;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return -1;
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace rb::cli
