#pragma once

#include <dealmpm/grid/nodal_fields.h>

#include <array>
#include <initializer_list>
#include <vector>

namespace dealmpm
{
  /**
   * Several nodal vectors of one partitioner exchanged together: one message
   * per neighbouring rank and direction instead of one per vector, the
   * entries of all vectors packed after one another. P2G sums 1 + 2 dim
   * vectors (mass, momentum, force), the grid update sends 2 dim (v*, the
   * increment): with deal.II's compress() and update_ghost_values() that
   * is a message per vector, with these one per neighbour. On one rank
   * both return at once.
   *
   * The vectors end in deal.II's states: after sum_ghosts_into_owners()
   * the owned entries hold the sums and the ghosts are zero (as after
   * compress(VectorOperation::add)); after copy_owners_to_ghosts() the
   * ghosts hold their owners' values (as after update_ghost_values()).
   */
  class NodalExchange
  {
  public:
    NodalExchange() = default;
    NodalExchange(std::initializer_list<NodalVector *> vectors);

    /** Add @p v to the vectors exchanged (same partitioner as the rest). */
    NodalExchange &
    add(NodalVector &v);

    /** Add each of @p vectors (a vector field's components). */
    template <std::size_t n>
    NodalExchange &
    add(std::array<NodalVector, n> &vectors)
    {
      for (NodalVector &v : vectors)
        add(v);
      return *this;
    }

    /** compress(VectorOperation::add) of every vector, in one message per
     * neighbour. */
    void
    sum_ghosts_into_owners();

    /** update_ghost_values() of every vector, in one message per
     * neighbour. */
    void
    copy_owners_to_ghosts();

  private:
    std::vector<NodalVector *> vectors;
  };
} // namespace dealmpm
