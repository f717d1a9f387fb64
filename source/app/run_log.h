#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace dealmpm
{
  using namespace dealii;

  /** The first line of the run.prm that start_run_files() writes: such a
   * scene sets every entry, those of unused sections too, on purpose. */
  inline const std::string scene_as_run_mark = "# dealmpm: the scene as it ran";

  /**
   * The two files that explain an output folder (rank 0; the folder is
   * made if it is not there yet; nothing is written where it cannot be,
   * the output writer says why then):
   * - run.prm: every entry of the scene @p prm as it ran, defaults and the
   *   command line's @p overrides included, which `dealmpm run.prm` runs
   *   again (not when @p scene_file is that file itself);
   * - run.log: from now on, a copy of everything the program prints on
   *   standard output and error (a resumed run appends, after a blank
   *   line), until the program ends.
   */
  void
  start_run_files(const ParameterHandler         &prm,
                  const std::string              &folder,
                  const std::string              &scene_file,
                  const std::vector<std::string> &overrides,
                  const bool                      resumed);
} // namespace dealmpm
