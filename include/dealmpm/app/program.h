#pragma once

namespace dealmpm
{
  /** The dealmpm program (argument parsing, both passes over the scene,
   * the run or the study, error reporting and exit codes); examples call
   * it after registering their own models. */
  int
  run_program(int argc, char **argv);
} // namespace dealmpm
