#include "tui_run.h"

#include <cstdio>

#include "exit_codes.h"

namespace rb::cli {

int runTui(const RunOptions&) {
  std::fprintf(stderr, "rb run: --tui is not available in this build yet\n");
  return exitcode::kUsage;
}

}  // namespace rb::cli
