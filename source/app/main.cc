#include <dealmpm/app/program.h>

#ifdef DEALMPM_X86_64_V3
#  include <cstdio>
#  include <unistd.h>

namespace
{
  /** A library built for x86-64-v3 (CMakeLists.txt) stops on an older
   * processor with "Illegal instruction", perhaps already in its own
   * initialisers: this check runs before those (.preinit_array) and says
   * what to do instead. */
  void
  check_processor(int, char **, char **)
  {
    __builtin_cpu_init();
    if (__builtin_cpu_supports("x86-64-v3"))
      return;
    std::fputs("dealmpm: this build needs a processor with x86-64-v3 (AVX2); "
               "build it on this machine, or configure with "
               "-DDEALMPM_X86_64_V3=OFF\n",
               stderr);
    _exit(1);
  }

  [[gnu::section(".preinit_array"),
    gnu::used]] void (*const preinit)(int, char **, char **) = &check_processor;
} // namespace
#endif

int
main(int argc, char **argv)
{
  return dealmpm::run_program(argc, argv);
}
