#pragma once

#include <deal.II/base/mpi.h>

#include <cstddef>
#include <string>

namespace dealmpm
{
  /**
   * A file written whole or not at all: the bytes go to a temporary file
   * beside it (`<path>.tmp`), and commit() renames that over @p path, which
   * POSIX makes atomic. A run killed at any moment (SIGKILL, a full disk)
   * leaves either the old file or the new one, never an empty or cut one,
   * which is what ParaView needs of a .pvd that is rewritten at every
   * output. Failures throw OutputError with the file's name and the
   * system's reason (strerror); an uncommitted temporary file is removed.
   */
  class OutputFile
  {
  public:
    explicit OutputFile(const std::string &path);

    ~OutputFile();

    OutputFile(const OutputFile &) = delete;
    OutputFile &
    operator=(const OutputFile &) = delete;

    void
    write(const void *data, const std::size_t n_bytes);

    void
    write(const std::string &text);

    /** Close and rename over the target. */
    void
    commit();

  private:
    [[noreturn]] void
    fail(const int error);

    std::string path;
    std::string temporary;
    int         fd = -1;
  };

  /**
   * Collective: if any rank has a message in @p local_error, every rank
   * throws OutputError with the lowest such rank's message followed by
   * @p context. A rank that failed alone must not throw alone: the others
   * would wait for it in the next collective call.
   */
  void
  agree_on_output_error(const std::string &local_error,
                        const std::string &context,
                        const MPI_Comm     comm);
} // namespace dealmpm
