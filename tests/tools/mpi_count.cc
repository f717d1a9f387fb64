// Counts the MPI calls of a run, for tests/scenes/collectives.sh: loaded
// with LD_PRELOAD, it wraps MPI's entry points (the standard profiling
// interface: each wrapper calls the PMPI_ one) and, at MPI_Finalize, rank
// 0 appends one line to the file named by MPI_COUNT_FILE:
//   collectives N point_to_point M
// Collectives are every call all ranks of a communicator must make
// (reductions, broadcasts, gathers, barriers, scans); point-to-point
// counts the sends, the messages of ghost updates and particle exchanges.
#include <cstdio>
#include <cstdlib>
#include <mpi.h>

namespace
{
  long collectives    = 0;
  long point_to_point = 0;
} // namespace

extern "C"
{
  int
  MPI_Allreduce(const void  *in,
                void        *out,
                int          n,
                MPI_Datatype type,
                MPI_Op       op,
                MPI_Comm     comm)
  {
    ++collectives;
    return PMPI_Allreduce(in, out, n, type, op, comm);
  }

  int
  MPI_Iallreduce(const void  *in,
                 void        *out,
                 int          n,
                 MPI_Datatype type,
                 MPI_Op       op,
                 MPI_Comm     comm,
                 MPI_Request *request)
  {
    ++collectives;
    return PMPI_Iallreduce(in, out, n, type, op, comm, request);
  }

  int
  MPI_Reduce(const void  *in,
             void        *out,
             int          n,
             MPI_Datatype type,
             MPI_Op       op,
             int          root,
             MPI_Comm     comm)
  {
    ++collectives;
    return PMPI_Reduce(in, out, n, type, op, root, comm);
  }

  int
  MPI_Bcast(void *data, int n, MPI_Datatype type, int root, MPI_Comm comm)
  {
    ++collectives;
    return PMPI_Bcast(data, n, type, root, comm);
  }

  int
  MPI_Allgather(const void  *in,
                int          n_in,
                MPI_Datatype in_type,
                void        *out,
                int          n_out,
                MPI_Datatype out_type,
                MPI_Comm     comm)
  {
    ++collectives;
    return PMPI_Allgather(in, n_in, in_type, out, n_out, out_type, comm);
  }

  int
  MPI_Allgatherv(const void  *in,
                 int          n_in,
                 MPI_Datatype in_type,
                 void        *out,
                 const int   *counts,
                 const int   *offsets,
                 MPI_Datatype out_type,
                 MPI_Comm     comm)
  {
    ++collectives;
    return PMPI_Allgatherv(
      in, n_in, in_type, out, counts, offsets, out_type, comm);
  }

  int
  MPI_Gather(const void  *in,
             int          n_in,
             MPI_Datatype in_type,
             void        *out,
             int          n_out,
             MPI_Datatype out_type,
             int          root,
             MPI_Comm     comm)
  {
    ++collectives;
    return PMPI_Gather(in, n_in, in_type, out, n_out, out_type, root, comm);
  }

  int
  MPI_Alltoall(const void  *in,
               int          n_in,
               MPI_Datatype in_type,
               void        *out,
               int          n_out,
               MPI_Datatype out_type,
               MPI_Comm     comm)
  {
    ++collectives;
    return PMPI_Alltoall(in, n_in, in_type, out, n_out, out_type, comm);
  }

  int
  MPI_Barrier(MPI_Comm comm)
  {
    ++collectives;
    return PMPI_Barrier(comm);
  }

  int
  MPI_Ibarrier(MPI_Comm comm, MPI_Request *request)
  {
    ++collectives;
    return PMPI_Ibarrier(comm, request);
  }

  int
  MPI_Scan(const void  *in,
           void        *out,
           int          n,
           MPI_Datatype type,
           MPI_Op       op,
           MPI_Comm     comm)
  {
    ++collectives;
    return PMPI_Scan(in, out, n, type, op, comm);
  }

  int
  MPI_Exscan(const void  *in,
             void        *out,
             int          n,
             MPI_Datatype type,
             MPI_Op       op,
             MPI_Comm     comm)
  {
    ++collectives;
    return PMPI_Exscan(in, out, n, type, op, comm);
  }

  int
  MPI_Isend(const void  *data,
            int          n,
            MPI_Datatype type,
            int          to,
            int          tag,
            MPI_Comm     comm,
            MPI_Request *request)
  {
    ++point_to_point;
    return PMPI_Isend(data, n, type, to, tag, comm, request);
  }

  int
  MPI_Issend(const void  *data,
             int          n,
             MPI_Datatype type,
             int          to,
             int          tag,
             MPI_Comm     comm,
             MPI_Request *request)
  {
    ++point_to_point;
    return PMPI_Issend(data, n, type, to, tag, comm, request);
  }

  int
  MPI_Send(const void  *data,
           int          n,
           MPI_Datatype type,
           int          to,
           int          tag,
           MPI_Comm     comm)
  {
    ++point_to_point;
    return PMPI_Send(data, n, type, to, tag, comm);
  }

  int
  MPI_Finalize()
  {
    int rank = 0;
    PMPI_Comm_rank(MPI_COMM_WORLD, &rank);
    const char *file = std::getenv("MPI_COUNT_FILE");
    if (rank == 0 && file != nullptr)
      if (std::FILE *out = std::fopen(file, "a"))
        {
          std::fprintf(out,
                       "collectives %ld point_to_point %ld\n",
                       collectives,
                       point_to_point);
          std::fclose(out);
        }
    return PMPI_Finalize();
  }
}
