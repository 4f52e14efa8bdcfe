#pragma once
// Program files on disk: the SourceReader that core's loader uses, and where rb's own library
// files (RB-9.bas) live.

#include <optional>
#include <string>
#include <vector>

#include "lang/loader.h"

namespace rb::run {

/// Reads program files from the file system. A name that does not exist as written is also
/// looked up without regard to case, since RobotBASIC programs come from Windows.
/// With `confine` (every command that runs or checks a program; not the editor's language
/// server, whose files are the user's own), a program includes only files in its own folder and
/// below, the library folders, and the folders the person running rb allows (--allow-files):
/// docs/language.md, "What a program may touch".
class FileSourceReader : public SourceReader {
 public:
  FileSourceReader() = default;
  /// Confined to `mainFile`'s folder tree, the library folders and `allowed`.
  FileSourceReader(const std::string& mainFile, const std::vector<std::string>& allowed);
  std::optional<std::string> find(const std::string& path) override;
  std::optional<std::string> read(const std::string& canonical) override;
  std::string refusal(const std::string& canonical) override;

 private:
  bool confine_ = false;
  std::vector<std::string> roots_;  ///< canonical folders, each ending in '/'
};

/// The largest program, include or events file rb reads: programs are text, so anything larger
/// is a mistake (`rb run /dev/zero`) that must not exhaust the machine.
constexpr size_t kMaxInputBytes = 16u << 20;

/// Reads a whole file of at most kMaxInputBytes; nullopt when it cannot be read, with the reason
/// in `why` ("no such file", "it is a folder", "larger than 16 MiB", ...).
std::optional<std::string> readFile(const std::string& path, std::string* why = nullptr);
/// Reads standard input to the end (at most kMaxInputBytes; nullopt beyond, with the reason).
std::optional<std::string> readStdin(std::string* why = nullptr);

/// The program files PATHS name: a file as it is, a folder as every *.bas in it and below
/// (sorted, so a class folder is always checked in the same order).
std::vector<std::string> expandProgramPaths(const std::vector<std::string>& paths);

/// Folders searched for #include files after the including file's folder: $RB_LIB_PATH
/// (colon-separated), the installed share/rb/lib beside the executable, and the source tree's lib/.
std::vector<std::string> libraryDirs();

}  // namespace rb::run
