// rb_seccomp_gen OUTPUT.cpp: a build-time tool. Builds the seccomp filter of every variant with
// libseccomp (seccomp_rules.cpp) and writes them as arrays of BPF instructions into OUTPUT.cpp,
// which rb_run compiles in (kernel_confine.h: embeddedSeccompProgram). The file is rewritten
// only when its text changes.

#include <seccomp.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include "seccomp_rules.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: rb_seccomp_gen OUTPUT.cpp\n");
    return 64;
  }
  const scmp_version* v = seccomp_version();
  std::ostringstream out;
  out << "// Generated at build time by rb_seccomp_gen (run/seccomp/seccomp_gen.cpp) with libseccomp " << v->major
      << '.' << v->minor << '.' << v->micro << "\n// from the rules in run/seccomp/seccomp_rules.cpp: do not edit.\n"
      << "#include \"kernel_confine.h\"\n\nnamespace rb::run {\n\nnamespace {\n\n";
  for (int variant = 0; variant < 4; ++variant) {
    const bool allowSpawn = variant & 1, sanitized = variant & 2;
    std::string error;
    const std::vector<uint8_t> bytes = rb::run::seccomp::filterBytes(allowSpawn, sanitized, error);
    if (bytes.empty()) {
      std::fprintf(stderr, "rb_seccomp_gen: %s\n", error.c_str());
      return 1;
    }
    out << "// allowSpawn " << allowSpawn << ", sanitized " << sanitized << ": " << bytes.size() / 8
        << " instructions\nconstexpr BpfInstruction kFilter" << variant << "[] = {\n";
    for (size_t at = 0; at < bytes.size(); at += 8) {
      uint16_t code;
      uint8_t jt, jf;
      uint32_t k;
      std::memcpy(&code, &bytes[at], 2);
      jt = bytes[at + 2];
      jf = bytes[at + 3];
      std::memcpy(&k, &bytes[at + 4], 4);
      char line[80];
      std::snprintf(line, sizeof line, "    {0x%04x, %u, %u, 0x%08x},\n", code, jt, jf, k);
      out << line;
    }
    out << "};\n\n";
  }
  char arch[16];
  std::snprintf(arch, sizeof arch, "0x%08x", rb::run::seccomp::nativeArch());
  out << "}  // namespace\n\nuint32_t embeddedSeccompArch() { return " << arch << "u; }\n\n"
      << "std::span<const BpfInstruction> embeddedSeccompProgram(bool allowSpawn, bool sanitized) {\n"
      << "  switch ((sanitized ? 2 : 0) + (allowSpawn ? 1 : 0)) {\n"
      << "    case 0: return kFilter0;\n    case 1: return kFilter1;\n    case 2: return kFilter2;\n"
      << "    default: return kFilter3;\n  }\n}\n\n}  // namespace rb::run\n";
  const std::string text = out.str();
  std::ifstream old(argv[1], std::ios::binary);
  if (old && std::string(std::istreambuf_iterator<char>(old), {}) == text) return 0;
  old.close();
  std::ofstream file(argv[1], std::ios::binary | std::ios::trunc);
  file << text;
  file.close();
  if (!file) {
    std::fprintf(stderr, "rb_seccomp_gen: cannot write %s\n", argv[1]);
    return 1;
  }
  return 0;
}
