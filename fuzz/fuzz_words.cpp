// Prints every built-in name from rb's table as a libFuzzer dictionary entry ("name"), so that
// fuzz/run.sh's dictionary reaches every command and function without building the rb binary.
#include <cstdio>

#include "lang/builtins.h"
#include "machine/builtins.h"

int main() {
  for (const rb::Builtin& b : rb::standardBuiltins().rows())
    std::printf("\"%.*s\"\n", static_cast<int>(b.name.size()), b.name.data());
  return 0;
}
