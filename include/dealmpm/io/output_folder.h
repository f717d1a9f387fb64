#pragma once

#include <string>

namespace dealmpm
{
  /** The subfolder of the output folder that holds each output's files
   * (.pvtu, .vtu, .h5, particle .csv), so that the folder's top shows the
   * series (.pvd, .xdmf), statistics.csv, run.prm and run.log. */
  inline const std::string step_folder = "steps";

  /**
   * Whether @p file_name is one of the files a run writes into its output
   * folder: particles_NNNNN.pvtu, particles_NNNNN.R.vtu, particles_NNNNN.csv,
   * grid_NNNNN.pvtu, grid_NNNNN.R.vtu, fem_region_R_NNNNN.pvtu and .R.vtu,
   * rigid_body_B_NNNNN.vtu, the .h5 files of the same names,
   * statistics.csv, *.pvd, *.xdmf, and the temporary files (".tmp") a killed
   * run may have left of these.
   */
  bool
  is_run_output_file(const std::string &file_name);

  /**
   * Remove the files of an earlier run from @p directory and its
   * step_folder (regular files of those names, nothing else), so that they
   * do not lie beside the new series; returns how many. Rank 0 calls it before
   * the first output. Throws OutputError naming the file it could not remove.
   */
  unsigned int
  remove_earlier_output(const std::string &directory);

  /**
   * Remove the numbered output files (particles_NNNNN*, grid_NNNNN*,
   * fem_region_R_NNNNN*, rigid_body_B_NNNNN*) from @p first_counter on, in @p
   * directory and its step_folder: a resumed run's files after its checkpoint,
   * which it writes again. Returns how many; throws OutputError.
   */
  unsigned int
  remove_later_output(const std::string &directory,
                      const unsigned int first_counter);
} // namespace dealmpm
