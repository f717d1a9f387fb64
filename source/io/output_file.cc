#include <deal.II/base/mpi.h>

#include <dealmpm/base/errors.h>
#include <dealmpm/io/output_file.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <unistd.h>

namespace dealmpm
{
  using namespace dealii;

  OutputFile::OutputFile(const std::string &path)
    : path(path)
    , temporary(path + ".tmp")
  {
    fd =
      ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0)
      fail(errno);
  }

  OutputFile::~OutputFile()
  {
    if (fd >= 0)
      {
        ::close(fd);
        ::unlink(temporary.c_str());
      }
  }

  void
  OutputFile::write(const void *data, const std::size_t n_bytes)
  {
    const char *bytes = static_cast<const char *>(data);
    std::size_t done  = 0;
    while (done < n_bytes)
      {
        const ssize_t n = ::write(fd, bytes + done, n_bytes - done);
        if (n < 0)
          {
            if (errno == EINTR)
              continue;
            fail(errno);
          }
        done += static_cast<std::size_t>(n);
      }
  }

  void
  OutputFile::write(const std::string &text)
  {
    write(text.data(), text.size());
  }

  void
  OutputFile::commit()
  {
    // close() reports the errors of delayed writes (network file systems).
    const int closed = ::close(fd);
    fd               = -1;
    if (closed != 0 || std::rename(temporary.c_str(), path.c_str()) != 0)
      {
        const int error = errno;
        ::unlink(temporary.c_str());
        fail(error);
      }
  }

  void
  OutputFile::fail(const int error)
  {
    if (fd >= 0)
      {
        ::close(fd);
        fd = -1;
        ::unlink(temporary.c_str());
      }
    throw OutputError("cannot write " + path + ": " + std::strerror(error));
  }

  void
  agree_on_output_error(const std::string &local_error,
                        const std::string &context,
                        const MPI_Comm     comm)
  {
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
    const unsigned int root =
      Utilities::MPI::min(local_error.empty() ? n_ranks : rank, comm);
    if (root == n_ranks)
      return;
    throw OutputError(Utilities::MPI::broadcast(comm, local_error, root) +
                      context);
  }
} // namespace dealmpm
