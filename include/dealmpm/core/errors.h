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
} // namespace dealmpm
