#pragma once

#include <deal.II/base/tensor.h>
#include <deal.II/particles/particle.h>

#include <dealmpm/grid/background_grid.h>
#include <dealmpm/particles/particle_set.h>

#include <vector>

namespace dealmpm
{
  /**
   * Anti-locking by a cell-averaged volume rate (F-bar in rate form, which
   * is B-bar on the velocity gradient; after Coombs et al. 2018,
   * "Overcoming volumetric locking in material point methods", CMAME 333,
   * and de Souza Neto et al. 1996 for finite elements).
   *
   * A linear cell with 2^dim particles gives each of them its own volume
   * change, and a material that flows without changing volume (plasticity,
   * nearly incompressible elasticity) cannot meet that many constraints:
   * it locks, and failure loads come out too high. F-bar lets the cell
   * carry one volume rate: with L_p the velocity gradient of particle p
   * and V0_p its reference volume, each body's particles in a cell share
   *   dbar = sum V0_p tr L_p / sum V0_p
   * and take Lbar_p = L_p + (dbar - tr L_p) / dim I and
   * F_p <- increment(dt Lbar_p) F_p: their rate of shape change is their
   * own, their volume rate the cell's (in 2D the in-plane block, so that
   * F_zz stays 1: plane strain).
   *
   * Why the rate and not the increment's determinant (de Souza Neto's
   * dFbar = (dJbar / dJ_p)^(1/dim) dF_p, used here before): at a
   * collapsing column's front a grain's own increment can nearly collapse
   * (dJ_p near 0, from a cell with tiny nodal masses), and scaled to the
   * cell's volume change its other stretch grows by (dJbar / dJ_p)^(1/dim):
   * our reading of why the collapse on cells half the shipped size
   * stopped with J <= 0 among grains with F entries up to 83 (not traced
   * step by step; the rate form runs there). The rate form shifts
   * L by at most the spread of its cell's volume rates, never amplifies a
   * particle's own increment, and has no special case for dJ_p <= 0. Its
   * price: the cell's volume changes agree to O(dt^2), not exactly.
   *
   * The weights are the reference volumes (the mass, within a body), not
   * the current volumes V_p = V0_p J_p as in Coombs et al.: the two agree
   * while the particles' J are alike, but a cohesionless grain that has
   * opened up (at its yield cone's apex J grows freely, to 20 and more at
   * a collapsing column's front) has a volume that is mostly void, and
   * weighted by it, it dictated the cell's volume rate and took a dense
   * neighbour's pressure onto its inflated volume: its nodes were pushed J
   * times as hard as a dense particle's.
   *
   * Used as a deforming sweep's gradient adjustment (adjusting(), which
   * records each particle's tr L_p, F_p and V0_p after the scene's own
   * adjustment) and its after-deformation callback (which holds each
   * particle until its cell is done): the sweeps visit the particles cell
   * by cell, so that when a new cell begins the previous one's particles
   * get their Lbar and F and then, through @p Inner (the stress update),
   * their stress. flush() ends the last cell. Nothing is kept between
   * steps, and a cell's particles are on its owner's rank: no
   * communication, the same numbers on any number of ranks.
   */
  template <int dim, typename Inner, typename Increment>
  class FBar
  {
  public:
    FBar(Inner                  &inner,
         const Increment        &increment,
         const double            dt,
         const ParticleSet<dim> &particles)
      : inner(inner)
      , increment(increment)
      , dt(dt)
      , particles(particles)
    {}

    /** The gradient adjustment of the sweep: @p adjust's, then the
     * particle's record. */
    template <typename Adjust>
    struct Adjusting
    {
      const Adjust &adjust;
      FBar         &f_bar;

      DEAL_II_ALWAYS_INLINE void
      operator()(const GridCell<dim>     &cell,
                 const ArrayView<double> &props,
                 Tensor<2, dim>          &L) const
      {
        adjust(cell, props, L);
        f_bar.record(cell, props, L);
      }
    };

    template <typename Adjust>
    Adjusting<Adjust>
    adjusting(const Adjust &adjust)
    {
      return {adjust, *this};
    }

    /** The after-deformation callback of the sweep: holds the particle
     * until its cell is done (finish() makes its F again, from Lbar). */
    template <typename Particle>
    void
    operator()(const Particle          &p,
               const ArrayView<double> &props,
               const Tensor<2, dim>    &L,
               const Tensor<2, dim> & /*F*/,
               const double h)
    {
      Held &held    = cell_particles.back();
      held.id       = p.get_id();
      held.location = p.get_location();
      held.props    = props.data();
      held.L        = L;
      held.h        = h;
    }

    /** End the last cell (after the sweep). */
    void
    flush()
    {
      for (Held &held : cell_particles)
        finish(held);
      share_mean_stress();
      cell_particles.clear();
      groups.clear();
      cell = nullptr;
    }

  private:
    /** What the stress update asks of a particle (its id and place, for
     * reports). */
    struct Reported
    {
      types::particle_index id;
      Point<dim>            location;

      types::particle_index
      get_id() const
      {
        return id;
      }
      const Point<dim> &
      get_location() const
      {
        return location;
      }
    };

    /** One body's particles in the cell in hand: their reference volume,
     * the sum of V0_p tr L_p, and their mean normal stresses' force
     * sum V_p p_p (current volumes). */
    struct Group
    {
      unsigned int body;
      double       volume = 0, rates = 0, force = 0;

      /** The weighted mean volume rate dbar. */
      double
      mean_rate() const
      {
        return rates / volume;
      }
    };

    /** A particle of the cell in hand. */
    struct Held
    {
      unsigned int          group;
      double                volume, rate; ///< V0_p and tr L_p
      double                J  = 1;       ///< det F_p after the step
      types::particle_index id = 0;
      Point<dim>            location;
      double               *props = nullptr;
      Tensor<2, dim>        L, F_old; ///< F_old: F_p at the step's start
      double                h = 0;
    };

    void
    record(const GridCell<dim>     &c,
           const ArrayView<double> &props,
           const Tensor<2, dim>    &L)
    {
      if (&c != cell)
        {
          flush();
          cell = &c;
        }
      Held held;
      held.rate = trace(L);
      held.F_old =
        read_tensor<dim>(&props[FixedCore<dim>::deformation_gradient]);
      held.volume = props[FixedCore<dim>::initial_volume];
      held.group  = group_of(particles.body_of(props));
      groups[held.group].volume += held.volume;
      groups[held.group].rates += held.volume * held.rate;
      cell_particles.push_back(held);
    }

    /** The index of @p body's group in the cell in hand (a cell holds
     * few bodies). */
    unsigned int
    group_of(const unsigned int body)
    {
      for (unsigned int g = 0; g < groups.size(); ++g)
        if (groups[g].body == body)
          return g;
      groups.push_back(Group{body});
      return groups.size() - 1;
    }

    /** Each body's particles in the cell share the force of their mean
     * (in-plane in 2D) normal stresses, P = sum V_p p_p, in the weights of
     * dbar: V_p pbar_p = P V0_p / sum V0. So the grid's internal force
     * does the work the materials count: with one volume rate per cell,
     * a particle's pressure works on the cell's mean volume rate (B-bar's
     * internal force, sum V_p pbar_p tr L_p = P dbar), not on its own. */
    void
    share_mean_stress()
    {
      for (const Held &held : cell_particles)
        groups[held.group].force += held.volume * held.J * mean_stress(held);
      for (const Held &held : cell_particles)
        {
          const Group &group = groups[held.group];
          if (!(group.volume > 0 && held.J > 0)) // J <= 0 is reported
            continue;
          const double shared = group.force / (group.volume * held.J);
          const double shift  = shared - mean_stress(held);
          // The symmetric tensor's first dim entries are its diagonal.
          for (unsigned int d = 0; d < dim; ++d)
            held.props[FixedCore<dim>::stress + d] += shift;
        }
    }

    /** The mean of a particle's in-plane (2D) or full normal stress. */
    static double
    mean_stress(const Held &held)
    {
      double sum = 0;
      for (unsigned int d = 0; d < dim; ++d)
        sum += held.props[FixedCore<dim>::stress + d];
      return sum / dim;
    }

    /** The particle's Lbar and F, then its stress update. */
    void
    finish(Held &held)
    {
      // The group holds this particle: its volume is positive.
      const double   shift = (groups[held.group].mean_rate() - held.rate) / dim;
      Tensor<2, dim> L     = held.L;
      for (unsigned int d = 0; d < dim; ++d)
        L[d][d] += shift;
      const Tensor<2, dim>    F = increment(dt * L) * held.F_old;
      const ArrayView<double> props(
        held.props, particles.handler.n_properties_per_particle());
      write_tensor<dim>(&props[FixedCore<dim>::deformation_gradient], F);
      held.J = determinant(F);
      inner(Reported{held.id, held.location}, props, L, F, held.h);
    }

    Inner                  &inner;
    const Increment        &increment;
    const double            dt;
    const ParticleSet<dim> &particles;
    const GridCell<dim>    *cell = nullptr;
    std::vector<Held>       cell_particles;
    std::vector<Group>      groups;
  };
} // namespace dealmpm
