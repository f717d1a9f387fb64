#pragma once

#include <deal.II/base/tensor.h>
#include <deal.II/particles/particle.h>

#include <dealmpm/grid/background_grid.h>
#include <dealmpm/particles/particle_set.h>

#include <cmath>
#include <vector>

namespace dealmpm
{
  /**
   * Anti-locking by a cell-averaged volume change (F-bar; Coombs et al.
   * 2018, "Overcoming volumetric locking in material point methods", CMAME
   * 333, after de Souza Neto et al. 1996 for finite elements).
   *
   * A linear cell with 2^dim particles gives each of them its own volume
   * change, and a material that flows without changing volume (plasticity,
   * nearly incompressible elasticity) cannot meet that many constraints:
   * it locks, and failure loads come out too high. F-bar lets the cell
   * carry one volume change: with dF_p = increment(dt L_p) the step's
   * deformation increment of particle p, dJ_p = det dF_p and V0_p its
   * reference volume, each body's particles in a cell share
   *   dJbar = sum V0_p dJ_p / sum V0_p
   * and take dFbar_p = (dJbar / dJ_p)^(1/dim) dF_p: their shape change is
   * their own, their volume change the cell's (in 2D the in-plane block,
   * so that F_zz stays 1: plane strain). The rate models see
   * Lbar_p = L_p + (s_p - 1) / dt I with s_p the factor, which differs
   * from the increment's at O(dt).
   *
   * The weights are the reference volumes (the mass, within a body), not
   * the current volumes V_p = V0_p J_p as in Coombs et al.: the two agree
   * while the particles' J are alike, but a cohesionless grain that has
   * opened up (at its yield cone's apex J grows freely, to 20 and more at
   * a collapsing column's front) has a volume that is mostly void, and
   * weighted by it, it dictated the cell's volume change and took a
   * dense neighbour's pressure onto its inflated volume: its nodes were
   * pushed J times as hard as a dense particle's, and the granular
   * collapse under USL and cpGIMP stopped with J <= 0 (it runs at every
   * CFL number from 0.1 to 0.5 with these weights).
   *
   * Used as a deforming sweep's gradient adjustment (adjusting(), which
   * records each particle's dJ_p and V0_p after the scene's own adjustment)
   * and its after-deformation callback (which holds each particle until its
   * cell is done): the sweeps visit the particles cell by cell, so that
   * when a new cell begins the previous one's particles get their dFbar and
   * then, through @p Inner (the stress update), their stress. flush() ends
   * the last cell. Particles whose own or whose cell's dJ is not positive
   * keep their F (the stress update then reports J <= 0). Nothing is kept
   * between steps, and a cell's particles are on its owner's rank: no
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
     * with its new F until its cell is done. */
    template <typename Particle>
    void
    operator()(const Particle          &p,
               const ArrayView<double> &props,
               const Tensor<2, dim>    &L,
               const Tensor<2, dim>    &F,
               const double             h)
    {
      Held &held    = cell_particles.back();
      held.id       = p.get_id();
      held.location = p.get_location();
      held.props    = props.data();
      held.L        = L;
      held.F        = F;
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
     * their reference volume times their own volume change, and their
     * mean normal stresses' force sum V_p p_p (current volumes). */
    struct Group
    {
      unsigned int body;
      double       volume = 0, changed = 0, force = 0;

      /** The weighted mean volume change dJbar (0 if the group has no
       * volume: its particles then keep their F). */
      double
      dJ_bar() const
      {
        return volume > 0 ? changed / volume : 0.;
      }
    };

    /** A particle of the cell in hand. */
    struct Held
    {
      unsigned int          group;
      double                volume, dJ; ///< V0_p and dJ_p
      double                J  = 1;     ///< det F_p after the step
      types::particle_index id = 0;
      Point<dim>            location;
      double               *props = nullptr;
      Tensor<2, dim>        L, F;
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
      held.dJ     = determinant(increment(dt * L));
      held.volume = props[FixedCore<dim>::initial_volume];
      held.group  = group_of(particles.body_of(props));
      groups[held.group].volume += held.volume;
      groups[held.group].changed += held.volume * held.dJ;
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
     * dJbar: V_p pbar_p = P V0_p / sum V0. So the grid's internal force
     * does the work the materials count: with one volume change per cell,
     * a particle's pressure works on the cell's mean volume rate (B-bar's
     * internal force), not on its own. */
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

    /** The particle's Fbar and Lbar, then its stress update. */
    void
    finish(Held &held)
    {
      const double         dJ_bar = groups[held.group].dJ_bar();
      const double         ratio  = dJ_bar / held.dJ;
      const double         s      = (held.dJ > 0 && dJ_bar > 0) ?
                                      (dim == 2 ? std::sqrt(ratio) : std::cbrt(ratio)) :
                                      1.;
      const Tensor<2, dim> F      = s * held.F;
      Tensor<2, dim>       L      = held.L;
      for (unsigned int d = 0; d < dim; ++d)
        L[d][d] += (s - 1.) / dt;
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
