#pragma once

#include <deal.II/base/parameter_handler.h>

#include <dealmpm/base/registry.h>
#include <dealmpm/base/scene_reader.h>
#include <dealmpm/grid/background_grid.h>
#include <dealmpm/particles/particle_set.h>

#include <memory>
#include <string>
#include <vector>

namespace dealmpm
{
  using namespace dealii;

  /** What a refinement criterion sees: the grid, the particles and the
   * levels the scene allows. Levels count from the scene's cells
   * ('Grid/Cells', before 'Global refinements'): a cell's is
   * grid.level(cell), not cell->level() (a rectangle's coarse mesh is
   * fewer cells, refined grid.base_level times). */
  template <int dim>
  struct AdaptivityContext
  {
    const BackgroundGrid<dim> &grid;
    const ParticleSet<dim>    &particles;
    unsigned int               min_level;
    unsigned int               max_level;
    MPI_Comm                   comm;
  };

  /**
   * A reason to refine or coarsen the background grid, chosen by name in
   * 'Adaptivity/Criteria'. It gives each locally owned cell the level it
   * should have; the grid then takes, per cell, the largest level any
   * criterion asks for (so a cell is refined if one criterion wants it and
   * coarsened only if all allow it), within the scene's minimum and
   * maximum level.
   */
  template <int dim>
  class RefinementCriterion
  {
  public:
    virtual ~RefinementCriterion() = default;

    /** @p levels has one entry per cell of context.grid.cells, in that
     * order; the criterion writes the level it wants (values outside the
     * scene's levels are clamped). Collective. */
    virtual void
    target_levels(const AdaptivityContext<dim> &context,
                  std::vector<int>             &levels) const = 0;

    /** Whether target_levels() asks deal.II's particle handler for a
     * cell's particles (particles_in_cell(), n_particles_in_cell()): its
     * lists are then sorted first, which costs about as much as a step.
     * A criterion that walks the step's order instead (ParticlesByCell in
     * transfer/stencil_order.h, as 'particles' does) says false. */
    virtual bool
    reads_handler_lists() const
    {
      return true;
    }

    /** The level it asks for the cells that hold particles at the start
     * (the bodies are then filled at that level), for the memory estimate
     * made before the grid exists; 0 when it asks none. */
    virtual unsigned int
    level_of_particle_cells(const unsigned int /*max_level*/) const
    {
      return 0;
    }
  };

  /** The registered criteria; each reads its parameters from
   * 'Adaptivity/<Name>' (section_title of its name). Register your own
   * before the scene is read (see examples/custom_refinement.cc). */
  template <int dim>
  Registry<RefinementCriterion<dim>> &
  refinement_criterion_registry();

  /** The "Adaptivity" section. */
  template <int dim>
  struct AdaptivitySettings
  {
    std::vector<std::unique_ptr<RefinementCriterion<dim>>> criteria;
    std::vector<std::string>                               names;
    unsigned int                                           step_interval = 10;
    unsigned int                                           min_level     = 0;
    unsigned int                                           max_level     = 2;
    double                                                 max_cells     = 1e6;
    bool                                                   split         = true;
    bool                                                   merge = false;
    unsigned int particles_per_direction                         = 2;

    bool
    enabled() const
    {
      return !criteria.empty();
    }

    /** The level of the cells that hold particles at the start (the most
     * any criterion asks, within the levels; 0 without adaptivity). */
    unsigned int
    level_of_particle_cells() const;

    static void
    declare_parameters(ParameterHandler &prm);

    /** Read and check the section (the reader at the top level). */
    static AdaptivitySettings
    read(SceneReader &reader);
  };

  /**
   * The level each locally owned cell should have: the largest of the
   * criteria's, clamped to [min_level, max_level]. Collective.
   */
  template <int dim>
  std::vector<int>
  target_levels(const AdaptivitySettings<dim> &settings,
                const AdaptivityContext<dim>  &context);

  /**
   * Flag the cells of @p grid whose level differs from @p levels (from
   * target_levels()); refinement flags are dropped when the grid would
   * have more than @p max_cells cells. Returns whether they were dropped.
   * Collective.
   */
  template <int dim>
  bool
  flag_cells(const BackgroundGrid<dim> &grid,
             const std::vector<int>    &levels,
             const double               max_cells);

  /**
   * Whether the refinement and coarsening flags of this rank's cells may
   * change the grid: false when deal.II's preparation of them would
   * surely undo them all. The level rule at vertices undoes a coarsening
   * that would leave two levels between cells sharing a vertex, and a
   * family coarsens whole. The 'particles' criterion flags just such
   * cells most of the time (the layer between fine and coarse cells), and
   * deal.II's preparation walks the grid several times to find that out
   * (about 80 % of a criteria call that changes nothing). This undoes a
   * part of what deal.II's preparation on this rank undoes, from the same
   * flags (a ghost's are those it has here, as deal.II sees them; a
   * sibling owned elsewhere counts as flagged), so a false is exact; a
   * true says: ask deal.II. Not collective.
   */
  template <int dim>
  bool
  flags_may_change_grid(const BackgroundGrid<dim> &grid);
} // namespace dealmpm
