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

  namespace
  {
    /** Call @p f(v, i, k) for entry i (a local index) of each vector v at
     * place k of the packed buffer, target by target: each target's
     * block holds its @p count entries of vector 0, then of vector 1, ...
     * @p local(j) is the local index of the j-th entry over all targets. */
    template <typename Local, typename F>
    void
    for_each_packed(
      const std::vector<NodalVector *>                         &vectors,
      const std::vector<std::pair<unsigned int, unsigned int>> &targets,
      const Local                                              &local,
      const F                                                  &f)
    {
      std::size_t k = 0, next = 0;
      for (const auto &[rank, count] : targets)
        {
          for (NodalVector *v : vectors)
            for (unsigned int i = 0; i < count; ++i)
              f(*v, local(next + i), k++);
          next += count;
        }
    }
  } // namespace

  namespace
  {
    /** The entries of all @p vectors from one side to the other in one
     * message per neighbour: from ghosts to their owners (@p from_ghosts)
     * or from owners to the ranks that hold them as ghosts; each received
     * value x lands as @p unpack(entry, x). */
    template <typename Unpack>
    void
    send_and_unpack(const std::vector<NodalVector *> &vectors,
                    const bool                        from_ghosts,
                    const int                         tag,
                    const Unpack                     &unpack)
    {
      const Utilities::MPI::Partitioner &p = *vectors[0]->get_partitioner();
      const unsigned int                 n_owned = p.locally_owned_size();
      const std::vector<unsigned int>    owned   = import_list(p);
      const auto  ghost  = [&](const unsigned int j) { return n_owned + j; };
      const auto  import = [&](const unsigned int j) { return owned[j]; };
      const auto &ghosts = p.ghost_targets(), &imports = p.import_targets();
      const std::size_t n_ghost  = vectors.size() * p.n_ghost_indices(),
                        n_import = vectors.size() * owned.size();
      std::vector<double> sent(from_ghosts ? n_ghost : n_import),
        received(from_ghosts ? n_import : n_ghost);
      const auto pack = [&](NodalVector &v, unsigned int i, std::size_t k) {
        sent[k] = v.local_element(i);
      };
      const auto take = [&](NodalVector &v, unsigned int i, std::size_t k) {
        unpack(v.local_element(i), received[k]);
      };
      if (from_ghosts)
        for_each_packed(vectors, ghosts, ghost, pack);
      else
        for_each_packed(vectors, imports, import, pack);
      exchange(from_ghosts ? imports : ghosts,
               from_ghosts ? ghosts : imports,
               vectors.size(),
               received,
               sent,
               tag,
               p.get_mpi_communicator());
      if (from_ghosts)
        for_each_packed(vectors, imports, import, take);
      else
        for_each_packed(vectors, ghosts, ghost, take);
    }
  } // namespace

  void
  NodalExchange::sum_ghosts_into_owners()
  {
    if (vectors.empty())
      return;
    if (vectors[0]->get_partitioner()->n_mpi_processes() > 1)
      send_and_unpack(vectors, true, sum_tag, [](double &to, const double x) {
        to += x;
      });
    for (NodalVector *v : vectors)
      v->zero_out_ghost_values();
  }

  void
  NodalExchange::copy_owners_to_ghosts()
  {
    if (vectors.empty())
      return;
    if (vectors[0]->get_partitioner()->n_mpi_processes() > 1)
      send_and_unpack(vectors, false, copy_tag, [](double &to, const double x) {
        to = x;
      });
    for (NodalVector *v : vectors)
      v->set_ghost_state(true);
  }
} // namespace dealmpm
