// rb_no_landlock PROGRAM ARGS...: runs PROGRAM as on a kernel without Landlock (its system calls
// fail with ENOSYS, as where the kernel lacks them), for the tests of what rb does there
// (confine_test.py, case no_landlock).
#include <errno.h>
#include <seccomp.h>
#include <sys/prctl.h>
#include <unistd.h>

#include <cstdio>
#include <initializer_list>

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: rb_no_landlock PROGRAM [ARGS...]\n");
    return 64;
  }
  prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0);
  scmp_filter_ctx ctx = seccomp_init(SCMP_ACT_ALLOW);
  for (const char* name : {"landlock_create_ruleset", "landlock_add_rule", "landlock_restrict_self"})
    seccomp_rule_add(ctx, SCMP_ACT_ERRNO(ENOSYS), seccomp_syscall_resolve_name(name), 0);
  if (!ctx || seccomp_load(ctx) != 0) {
    std::perror("rb_no_landlock: seccomp");
    return 70;
  }
  seccomp_release(ctx);
  execv(argv[1], argv + 1);
  std::perror("rb_no_landlock: exec");
  return 127;
}
