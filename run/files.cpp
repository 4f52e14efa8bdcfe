#include "files.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <system_error>

#include "base/large_memory.h"

namespace fs = std::filesystem;

namespace rb::run {

namespace {
bool sameIgnoringCase(const std::string& a, const std::string& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i])))
      return false;
  return true;
}
}  // namespace

std::optional<std::string> FileSourceReader::find(const std::string& path) {
  std::error_code ec;
  fs::path p(path);
  if (fs::is_regular_file(p, ec)) return fs::weakly_canonical(p, ec).string();
  // Resolve each component of the path without regard to case.
  fs::path resolved = p.is_absolute() ? p.root_path() : fs::path(".");
  for (const fs::path& part : p.relative_path()) {
    fs::path exact = resolved / part;
    if (part == "." || part == ".." || fs::exists(exact, ec)) {
      resolved = exact;
      continue;
    }
    bool found = false;
    for (const auto& entry : fs::directory_iterator(resolved, ec)) {
      if (sameIgnoringCase(entry.path().filename().string(), part.string())) {
        resolved = entry.path();
        found = true;
        break;
      }
    }
    if (!found) return std::nullopt;
  }
  if (!fs::is_regular_file(resolved, ec)) return std::nullopt;
  return fs::weakly_canonical(resolved, ec).string();
}

FileSourceReader::FileSourceReader(const std::string& mainFile, const std::vector<std::string>& allowed)
    : confine_(true) {
  std::error_code ec;
  auto root = [&](const fs::path& dir) {
    fs::path c = fs::weakly_canonical(dir.empty() ? fs::path(".") : dir, ec);
    if (ec) return;
    std::string s = c.string();
    if (s.empty() || s.back() != '/') s += '/';
    roots_.push_back(s);
  };
  root(mainFile == "-" ? fs::current_path(ec) : fs::absolute(mainFile, ec).parent_path());
  for (const std::string& lib : libraryDirs()) root(lib);
  for (const std::string& dir : allowed) root(dir);
}

std::optional<std::string> FileSourceReader::read(const std::string& canonical) {
  if (!refusal(canonical).empty()) return std::nullopt;  // never read past the rule
  return readFile(canonical);
}

std::string FileSourceReader::refusal(const std::string& canonical) {
  if (!confine_) return "";
  for (const std::string& r : roots_)
    if (canonical.compare(0, r.size(), r) == 0) return "";
  return "it is outside the program's folder and the library folders (rb run --allow-files DIR "
         "allows another folder)";
}

namespace {
/// Reads IN to its end; `expected` (a regular file's size, 0 when unknown) sizes the text at
/// once, so that a file is read straight into it: reading 64 KiB at a time into a growing
/// string touched about three times the file's size in fresh memory.
std::optional<std::string> readLimited(std::istream& in, std::string* why, uintmax_t expected = 0) {
  std::string text;
  if (expected > 0 && expected <= kMaxInputBytes) {
    text.reserve(static_cast<size_t>(expected));
    prepareLarge(text.data(), static_cast<size_t>(expected));  // a big file: its pages at once
    text.resize(static_cast<size_t>(expected));
    in.read(text.data(), static_cast<std::streamsize>(expected));
    text.resize(static_cast<size_t>(in.gcount()));  // shorter if the file shrank meanwhile
  }
  char buf[1 << 16];
  while (in) {
    in.read(buf, sizeof buf);
    text.append(buf, static_cast<size_t>(in.gcount()));
    if (text.size() > kMaxInputBytes) {
      if (why) *why = "larger than " + std::to_string(kMaxInputBytes >> 20) + " MiB, not a program";
      return std::nullopt;
    }
  }
  if (in.bad()) {
    if (why) *why = "read error";
    return std::nullopt;
  }
  return text;
}
}  // namespace

std::optional<std::string> readFile(const std::string& path, std::string* why) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (fs::is_directory(status)) {
    if (why) *why = "it is a folder";
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    if (why) *why = fs::exists(status) ? "permission denied" : "no such file";
    return std::nullopt;
  }
  uintmax_t size = fs::is_regular_file(status) ? fs::file_size(path, ec) : 0;
  return readLimited(in, why, ec ? 0 : size);
}

std::optional<std::string> readStdin(std::string* why) { return readLimited(std::cin, why); }

std::vector<std::string> expandProgramPaths(const std::vector<std::string>& paths) {
  std::vector<std::string> out;
  for (const std::string& p : paths) {
    std::error_code ec;
    if (p == "-" || !fs::is_directory(p, ec)) {
      out.push_back(p);
      continue;
    }
    std::vector<std::string> found;
    for (auto it = fs::recursive_directory_iterator(p, fs::directory_options::skip_permission_denied, ec);
         !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
      std::string ext = it->path().extension().string();
      for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      if (ext == ".bas" && it->is_regular_file(ec)) found.push_back(it->path().string());
    }
    std::sort(found.begin(), found.end());
    out.insert(out.end(), found.begin(), found.end());
  }
  return out;
}

std::vector<std::string> libraryDirs() {
  std::vector<std::string> dirs;
  if (const char* env = std::getenv("RB_LIB_PATH")) {
    std::string s(env);
    size_t start = 0;
    while (start <= s.size()) {
      size_t colon = s.find(':', start);
      std::string part = s.substr(start, colon == std::string::npos ? std::string::npos : colon - start);
      if (!part.empty()) dirs.push_back(part);
      if (colon == std::string::npos) break;
      start = colon + 1;
    }
  }
  std::error_code ec;
  fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    // Installed (cmake --install, or the tree copied anywhere): PREFIX/bin/rb finds
    // PREFIX/share/rb/lib, relative to itself.
    fs::path installed = exe.parent_path().parent_path() / "share" / "rb" / "lib";
    if (fs::is_directory(installed, ec)) dirs.push_back(installed.string());
  }
#if defined(RB_SOURCE_LIB_DIR) && defined(RB_BUILD_DIR)
  // The source tree's lib/ only for the binary that still sits in its build tree: a copied or
  // installed rb never reaches back into the sources it was built from.
  std::error_code builtEc;
  if (!exe.empty()) {
    std::string built = fs::weakly_canonical(fs::path(RB_BUILD_DIR), builtEc).string();
    std::string at = exe.string();
    if (!builtEc && !built.empty() && at.compare(0, built.size(), built) == 0 &&
        (at.size() == built.size() || at[built.size()] == '/'))
      dirs.push_back(RB_SOURCE_LIB_DIR);
  }
#endif
  return dirs;
}

}  // namespace rb::run
