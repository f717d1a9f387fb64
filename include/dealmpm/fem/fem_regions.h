#pragma once

#include <dealmpm/effects/effect.h>
#include <dealmpm/fem/fem_region.h>
#include <dealmpm/fem/nodes_on_grid.h>
#include <dealmpm/grid/background_grid.h>
#include <dealmpm/grid/nodal_field_set.h>
#include <dealmpm/materials/material.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace dealmpm
{
  /** What a region adds to the run's statistics: to the coupled system's
   * totals, and its own columns (fem<N>_...). */
  template <int dim>
  struct RegionTotals
  {
    double                   mass = 0;
    Tensor<1, dim>           momentum;
    double                   kinetic_energy       = 0;
    double                   strain_energy        = 0;
    double                   gravitational_energy = 0;
    bool                     dissipates           = false;
    double                   dissipated_work      = 0;
    std::vector<std::string> columns;
    std::vector<double>      values;
  };

  /**
   * A scene's FEM regions ('Number of FEM regions', 'FEM region N') with
   * the lifecycle an effect has: made from the scene, forces and update for
   * the step's stages, their share of the stable step, statistics and
   * external work, saved state, and a rebuild after the grid changed. The
   * effects' body forces and potential act on the regions too.
   */
  template <int dim>
  class FemRegions
  {
  public:
    /** 'Number of FEM regions' and @p n_regions 'FEM region N' sections. */
    static void
    declare_parameters(ParameterHandler &prm, const unsigned int n_regions);

    explicit FemRegions(
      const std::vector<std::unique_ptr<Effect<dim>>> &effects)
      : effects(effects)
    {}

    /** Make the regions from their sections (collective; InputError on
     * bad input); bonded nodes carry the APIC affine field with @p apic. */
    void
    make(SceneReader                                       &reader,
         const unsigned int                                 n_regions,
         const std::vector<std::unique_ptr<Material<dim>>> &materials,
         const unsigned int                                 n_bodies,
         const BackgroundGrid<dim>                         &grid,
         const bool                                         apic);

    bool
    empty() const
    {
      return regions.empty();
    }

    const std::vector<FemRegion<dim>> &
    list() const
    {
      return regions;
    }

    /** After P2G and the effects: the regions' internal and body forces,
     * the bonded nodes' mass, momentum and force to the grid. */
    void
    compute_forces(const double               time,
                   const double               dt,
                   const BackgroundGrid<dim> &grid,
                   NodalFieldSet<dim>        &fields);

    /** After the grid update: bonded nodes take the grid's velocity,
     * contact corrects both sides where the particles (their weights in
     * @p stencil) meet a region, the regions advance. */
    void
    update(const double               time,
           const double               dt,
           const double               mass_threshold,
           const BackgroundGrid<dim> &grid,
           NodalFieldSet<dim>        &fields,
           const ParticleSet<dim>    &particles,
           const Stencil<dim>        &stencil);

    /** The largest wave speed over node spacing of this rank's cells, 0
     * without regions (not collective). */
    double
    local_signal_rate() const;

    /** Each region's totals and columns for the statistics
     * (collective). */
    std::vector<RegionTotals<dim>>
    totals(const MPI_Comm comm) const;

    /** Work of tractions, prescribed motions and contact (this rank's). */
    double
    external_work() const;

    /** The support forces' means start again with the next row. */
    void
    start_statistics_row();

    /** Region @p r's state on this rank, as text (a checkpoint's file). */
    std::string
    saved_state(const unsigned int r) const;

    /** Region @p r's state from the texts each rank saved; the contact's
     * work goes to rank 0 (@p root). */
    void
    restore_state(const unsigned int              r,
                  const std::vector<std::string> &parts,
                  const bool                      root);

    /** Rebuild the couplings' grid data. */
    void
    grid_changed(const BackgroundGrid<dim> &grid);

    /** Whether a coupling node of this rank asks for the ranks' boxes to
     * be published again (NodesOnGrid; not collective). */
    bool
    coupling_wants_publication();

    /** Some rank asked: the couplings publish at the next step. */
    void
    publish_coupling_at_next_step();

    /** Why a coupling node of this rank could not be coupled this step,
     * or empty (not collective). */
    std::string
    coupling_failure();

  private:
    /** Call @p f with each coupling's nodes on the grid. */
    void
    for_each_coupling(const std::function<void(NodesOnGrid<dim> &)> &f);

    /** The effects' potential per unit mass, for the regions' nodes. */
    std::function<double(const Point<dim> &)>
    potential() const;

    /** Whether every effect's potential is steady from time @p t on. */
    bool
    potential_steady_from(const double t) const;

    const std::vector<std::unique_ptr<Effect<dim>>> &effects;
    std::vector<FemRegion<dim>>                      regions;
  };
} // namespace dealmpm
