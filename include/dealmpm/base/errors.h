#pragma once

#include <stdexcept>
#include <string>

namespace dealmpm
{
  /**
   * An error in what the user gave us (scene file, command line). The program
   * prints what() as one line and exits with code 2 before writing anything.
   */
  class InputError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /**
   * A run that cannot go on: non-finite state, an inverted particle, a particle
   * that left the grid under the 'stop' policy. The last regular output stays
   * on disk; the program exits with code 3.
   */
  class RunError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /**
   * An output file that could not be written (full disk, no permission):
   * what() names the file and the system's reason. Every rank throws it
   * together, after the files a series entry points to were checked on all
   * ranks, so the series on disk stay consistent; the program exits with
   * code 5.
   */
  class OutputError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };
} // namespace dealmpm
