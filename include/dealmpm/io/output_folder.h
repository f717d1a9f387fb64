#pragma once

#include <string>

namespace dealmpm
{
  /**
   * Whether @p file_name is one of the files a run writes into its output
   * folder: particles_NNNNN.pvtu, particles_NNNNN.R.vtu, particles_NNNNN.csv,
   * grid_NNNNN.pvtu, grid_NNNNN.R.vtu, the .h5 files of the same names,
   * statistics.csv, *.pvd, *.xdmf, and the temporary files (".tmp") a killed
   * run may have left of these.
   */
  bool
  is_run_output_file(const std::string &file_name);

  /**
   * Remove the files of an earlier run from @p directory (regular files in
   * the folder itself, nothing else), so that they do not lie beside the new
   * series; returns how many. Rank 0 calls it before the first output.
   * Throws OutputError naming the file it could not remove.
   */
  unsigned int
  remove_earlier_output(const std::string &directory);

  /**
   * Remove the numbered output files (particles_NNNNN*, grid_NNNNN*) from
   * @p first_counter on: a resumed run's files after its checkpoint, which
   * it writes again. Returns how many; throws OutputError.
   */
  unsigned int
  remove_later_output(const std::string &directory,
                      const unsigned int first_counter);
} // namespace dealmpm
