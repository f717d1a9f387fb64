#include <deal.II/base/mpi.h>

#include <dealmpm/grid/nodal_exchange.h>

#include <stdexcept>

namespace dealmpm
{
  namespace
  {
    // Above deal.II's own tags (300 and up by a few hundred), below the
    // 32767 every MPI allows.
    constexpr int sum_tag  = 7301;
    constexpr int copy_tag = 7302;

    /** The local indices a rank owns and others hold as ghosts, in the
     * order of the partitioner's import targets. */
    std::vector<unsigned int>
    import_list(const Utilities::MPI::Partitioner &partitioner)
    {
      std::vector<unsigned int> list;
      list.reserve(partitioner.n_import_indices());
      for (const auto &range : partitioner.import_indices())
        for (unsigned int i = range.first; i < range.second; ++i)
          list.push_back(i);
      return list;
    }

    /** Both directions: the packed entries of @p n_vectors vectors, each
     * neighbour's block holding vector 0's entries, then vector 1's, ...
     * Receives from @p recv_targets into @p received, sends @p sent to
     * @p send_targets. */
    void
    exchange(
      const std::vector<std::pair<unsigned int, unsigned int>> &recv_targets,
      const std::vector<std::pair<unsigned int, unsigned int>> &send_targets,
      const unsigned int                                        n_vectors,
      std::vector<double>                                      &received,
      std::vector<double>                                      &sent,
      const int                                                 tag,
      const MPI_Comm                                            comm)
    {
      std::vector<MPI_Request> requests;
      requests.reserve(recv_targets.size() + send_targets.size());
      // Post one message per target, each its block of @p buffer.
      const auto post = [&](const auto &targets, double *buffer, auto start) {
        for (const auto &[rank, count] : targets)
          {
            requests.emplace_back();
            const int ierr =
              start(buffer, n_vectors * count, rank, &requests.back());
            AssertThrowMPI(ierr);
            buffer += std::size_t(n_vectors) * count;
          }
      };
      post(recv_targets,
           received.data(),
           [&](double *data, int n, int rank, MPI_Request *request) {
             return MPI_Irecv(data, n, MPI_DOUBLE, rank, tag, comm, request);
           });
      post(send_targets,
           sent.data(),
           [&](double *data, int n, int rank, MPI_Request *request) {
             return MPI_Isend(data, n, MPI_DOUBLE, rank, tag, comm, request);
           });
      const int ierr =
        MPI_Waitall(requests.size(), requests.data(), MPI_STATUSES_IGNORE);
      AssertThrowMPI(ierr);
    }
  } // namespace

  NodalExchange::NodalExchange(std::initializer_list<NodalVector *> list)
  {
    for (NodalVector *v : list)
      add(*v);
  }

  NodalExchange &
  NodalExchange::add(NodalVector &v)
  {
    if (!vectors.empty() &&
        v.get_partitioner() != vectors[0]->get_partitioner() &&
        !v.get_partitioner()->is_compatible(*vectors[0]->get_partitioner()))
      throw std::logic_error("nodal vectors of different grids exchanged "
                             "together");
    vectors.push_back(&v);
    return *this;
  }

  void
  NodalExchange::sum_ghosts_into_owners()
  {
    if (vectors.empty())
      return;
    const Utilities::MPI::Partitioner &partitioner =
      *vectors[0]->get_partitioner();
    const unsigned int n_owned = partitioner.locally_owned_size();
    const unsigned int n_ghost = partitioner.n_ghost_indices();
    const unsigned int K       = vectors.size();
    if (partitioner.n_mpi_processes() > 1)
      {
        // Pack each neighbour's ghosts, vector after vector.
        std::vector<double> sent(std::size_t(K) * n_ghost);
        std::size_t         out = 0, first = n_owned;
        for (const auto &[rank, count] : partitioner.ghost_targets())
          {
            for (const NodalVector *v : vectors)
              for (unsigned int i = 0; i < count; ++i)
                sent[out++] = v->local_element(first + i);
            first += count;
          }
        std::vector<double> received(std::size_t(K) *
                                     partitioner.n_import_indices());
        exchange(partitioner.import_targets(),
                 partitioner.ghost_targets(),
                 K,
                 received,
                 sent,
                 sum_tag,
                 partitioner.get_mpi_communicator());
        const std::vector<unsigned int> owned = import_list(partitioner);
        std::size_t                     in = 0, next = 0;
        for (const auto &[rank, count] : partitioner.import_targets())
          {
            for (NodalVector *v : vectors)
              for (unsigned int i = 0; i < count; ++i)
                v->local_element(owned[next + i]) += received[in++];
            next += count;
          }
      }
    for (NodalVector *v : vectors)
      v->zero_out_ghost_values();
  }

  void
  NodalExchange::copy_owners_to_ghosts()
  {
    if (vectors.empty())
      return;
    const Utilities::MPI::Partitioner &partitioner =
      *vectors[0]->get_partitioner();
    if (partitioner.n_mpi_processes() > 1)
      {
        const unsigned int  K     = vectors.size();
        const auto          owned = import_list(partitioner);
        std::vector<double> sent(std::size_t(K) * owned.size());
        std::size_t         out = 0, next = 0;
        for (const auto &[rank, count] : partitioner.import_targets())
          {
            for (const NodalVector *v : vectors)
              for (unsigned int i = 0; i < count; ++i)
                sent[out++] = v->local_element(owned[next + i]);
            next += count;
          }
        std::vector<double> received(std::size_t(K) *
                                     partitioner.n_ghost_indices());
        exchange(partitioner.ghost_targets(),
                 partitioner.import_targets(),
                 K,
                 received,
                 sent,
                 copy_tag,
                 partitioner.get_mpi_communicator());
        std::size_t in = 0, first = partitioner.locally_owned_size();
        for (const auto &[rank, count] : partitioner.ghost_targets())
          {
            for (NodalVector *v : vectors)
              for (unsigned int i = 0; i < count; ++i)
                v->local_element(first + i) = received[in++];
            first += count;
          }
      }
    for (NodalVector *v : vectors)
      v->set_ghost_state(true);
  }
} // namespace dealmpm
