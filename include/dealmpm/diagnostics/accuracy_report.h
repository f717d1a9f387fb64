#pragma once

#include <dealmpm/diagnostics/statistics.h>

#include <algorithm>
#include <ostream>
#include <string>

namespace dealmpm
{
  /**
   * How far a run has strayed from what it should conserve, gathered as it
   * goes and printed at its end (and written to every statistics.csv row):
   * - energy drift: (E - W_ext - E_0) / E_in, E the total energy (with
   *   gravity's potential), W_ext the work of effects without a potential
   *   (manufactured body forces), E_in the energy the scene was given: the
   *   kinetic and strain energy at the start plus the largest |W_ext| +
   *   (potential energy released) seen, or, if larger, the floor (m |g| +
   *   F) h / 1000, the work of gravity and the loads (F their largest total
   *   magnitude) over a thousandth of the smallest cell: a body that
   *   settles at rest puts in next to nothing, and round-off against
   *   nothing is no growth. Damping and walls that do work show up here
   *   too. Measured against what went in, not against the largest
   *   energy seen, so energy a scheme creates cannot hide itself;
   * - momentum drift: |P - P_0| / sqrt(2 M max kinetic energy seen): zero
   *   only without external forces and walls (the colliding disks); the
   *   printed line says "n/a" for a scene with them;
   * - mass loss: (M_0 - M) / M_0, from particles that left the grid;
   * - the smallest J and the largest particle CFL number dt (c + |v|) / h
   *   of any particle in any step;
   * - the displacement error norms when the scene has an exact solution.
   */
  struct AccuracyReport
  {
    double energy_drift   = 0;
    double momentum_drift = 0;
    double mass_loss      = 0;
    double min_J          = 1;
    double max_cfl        = 0;
    /** The drift is a fraction of the floor (m |g| + F) h / 1000, not of the
     * energy put in (AccuracyMonitor::energy_scale). */
    bool   of_floor  = false;
    bool   has_error = false;
    double error_L2  = 0;
    double error_max = 0;
    /** Whether the scene conserves momentum (no walls, loads, body forces
     * or FEM regions): else the printed line says "n/a" for its drift,
     * which walls and gravity make large without anything being wrong. */
    bool momentum_conserved = true;

    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int /*version*/)
    {
      archive &energy_drift &momentum_drift &mass_loss &min_J &max_cfl;
      archive &has_error &error_L2                            &error_max;
      archive                                                 &of_floor;
    }
  };

  class AccuracyMonitor
  {
  public:
    /** Start from the initial state. @p energy_floor: the smallest scale
     * the energy drift is measured against (see energy_scale()). */
    void
    start(const Statistics &initial, const double energy_floor = 0);

    /** Raise the floor to @p energy_floor if that is larger (loads that
     * grow). */
    void
    raise_floor(const double floor)
    {
      energy_floor = std::max(energy_floor, floor);
    }

    /** What the energy drift is a fraction of: "the energy put in", or,
     * when that is smaller than the floor (a body that settles at rest
     * under gravity puts in next to nothing), the floor with both values. */
    std::string
    energy_scale() const;

    /** After every step: the step's smallest J and largest particle CFL
     * number (global values). */
    void
    observe_step(const double min_J, const double cfl);

    /** At outputs: the statistics and the work done so far by effects
     * without a potential. */
    void
    observe(const Statistics &s, const double external_work);

    const AccuracyReport &
    report() const
    {
      return current;
    }

    /** The particles' mass at the start (given to start()). */
    double
    initial_mass() const
    {
      return initial.mass;
    }

    /** Whether the scene conserves momentum (see AccuracyReport); set by
     * the run before its first step, also after a resume. */
    void
    set_momentum_conserved(const bool conserved)
    {
      current.momentum_conserved = conserved;
    }

    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int /*version*/)
    {
      archive &initial &max_energy_supplied &max_kinetic_energy &current;
      archive                                                   &energy_floor;
    }

  private:
    Statistics     initial;
    double         max_energy_supplied = 0; ///< |W_ext| + potential released
    double         max_kinetic_energy  = 0;
    double         energy_floor        = 0;
    AccuracyReport current;

    /** The energy put in: E_0 (kinetic and strain) + max_energy_supplied. */
    double
    energy_put_in() const;
  };

  /** The report as a few lines for the end of a run. */
  std::ostream &
  operator<<(std::ostream &out, const AccuracyReport &report);
} // namespace dealmpm
