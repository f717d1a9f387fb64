#include <dealmpm/app/program.h>

int
main(int argc, char **argv)
{
  return dealmpm::run_program(argc, argv);
}
