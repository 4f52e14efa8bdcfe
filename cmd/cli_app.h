#pragma once
// CLI11's App, declared only: headers that hand an App around include this, and only the files
// that add options include <CLI/CLI.hpp> (it is slow to compile: every file that includes it
// compiles CLI11's formatter and config classes again).

namespace CLI {
class App;
}
