#pragma once
// A compiled program as text, for `rb check --dump-code` and the compiler tests
// (testdata/compiler/): one instruction a line with its opcode's name (from the RB_OPCODES
// X-macro), its operands with their bases named (g: global slot, f: frame slot, k: constant),
// jump targets, the program's labels and sub entries, and the source line each run of
// instructions was compiled from.
//
//   globals    g0 x, g1 i
//   constants  k0 1, k1 "hi"
//
//   main
//               ; t.bas:1  x = 1
//        0      Move         g0:x, k0:1
//   ...
//   sub Twice(v): entry 7, frame 3 (locals v; 2 temporaries)
//   ...
//
// '>' before an instruction marks a jump target; `(steps N)` is the statement count a
// control transfer reports (see bytecode.h).

#include <string>

#include "base/source.h"
#include "lang/bytecode.h"

namespace rb {

/// `program`, compiled from `sources`, as text.
std::string dumpCode(const Program& program, const SourceSet& sources);

}  // namespace rb
