#include "render_command.h"

namespace rb::cli {

void addRenderCommand(CLI::App& /*app*/, int& /*exitCode*/) {}

}  // namespace rb::cli
