#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/particles/property_pool.h>

#include <string>

namespace dealmpm
{
  using namespace dealii;

  /** "(x, y[, z])" with 6 digits, for messages about a place. */
  template <int dim>
  std::string
  format_point(const Point<dim> &x);

  /** "step N (t = T)", T with 3 significant digits, for messages. */
  std::string
  step_and_time(const unsigned int step, const double time);

  /** x with 3 significant digits, for messages. */
  std::string
  short_number(const double x);

  /** The message of the lowest rank that has one, on every rank ("" when
   * none has). Collective. */
  std::string
  first_message(const std::string &local, const MPI_Comm comm);

  /**
   * Throw the RunError "step N (t = T): particle P at (x): reason" for the
   * first particle (over all ranks) that stopped the step. Collective:
   * call it on every rank when any rank has one.
   */
  template <int dim>
  [[noreturn]] void
  stop_on_particle(const bool                  failed_here,
                   const types::particle_index particle,
                   const Point<dim>           &location,
                   const std::string          &reason,
                   const unsigned int          step,
                   const double                time,
                   const MPI_Comm              comm);
} // namespace dealmpm
