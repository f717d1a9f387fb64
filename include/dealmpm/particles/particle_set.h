#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/particles/particle_handler.h>

#include <dealmpm/base/property_layout.h>
#include <dealmpm/particles/particle_order.h>

#include <memory>
#include <set>
#include <vector>

namespace dealmpm
{
  using namespace dealii;

  /** Offsets of the fields every particle has. */
  struct CoreFields
  {
    unsigned int mass;
    unsigned int initial_volume;
    unsigned int velocity;
    unsigned int displacement;
    unsigned int deformation_gradient; ///< dim x dim, row-major
    unsigned int stress;               ///< symmetric, deal.II's unrolled order
    /** The particle's body index (a double), or invalid_unsigned_int in a
     * scene of one body, whose particles store none: read it with
     * ParticleSet::body_of(). A particle's material is its body's
     * (ParticleSet::material_of()), so no particle stores it. */
    unsigned int body;
    /** APIC's B_p = sum N v_i (x) (x_i - x_p) (dim x dim), or
     * invalid_unsigned_int when the scene does not use APIC (then no particle
     * stores it). */
    unsigned int affine_velocity;
    /** Newmark's particle acceleration (dim), or invalid_unsigned_int when
     * the scene does not use Newmark. */
    unsigned int acceleration;
    /** GIMP's initial particle-domain half-lengths (dim), or
     * invalid_unsigned_int for kernels without a particle domain. */
    unsigned int domain_half_length;
    /** Doubles of the core fields above: every other field of the layout
     * lies at or after this offset. */
    unsigned int n_core;
  };

  /** The offsets of the fields every particle has (CoreFields' first six,
   * which ParticleSet lays out first and in this order, and checks): as
   * constants for the step's hot loops, where a runtime offset costs a load
   * and an address computation at each access. */
  template <int dim>
  struct FixedCore
  {
    static constexpr unsigned int mass                 = 0;
    static constexpr unsigned int initial_volume       = 1;
    static constexpr unsigned int velocity             = 2;
    static constexpr unsigned int displacement         = 2 + dim;
    static constexpr unsigned int deformation_gradient = 2 + 2 * dim;
    static constexpr unsigned int stress = 2 + 2 * dim + dim * dim;
  };

  /**
   * The material points: deal.II's ParticleHandler (positions, cells, ids,
   * MPI ownership) with a property layout of core fields and the internal
   * variables of the material models in use.
   */
  template <int dim>
  class ParticleSet
  {
  public:
    /**
     * The layout is built from what the parts of the run ask for, in this
     * order: the core fields, @p method_fields (the shape function's and
     * the transfer's: "domain_half_length", "apic_B",
     * "acceleration"), per material index
     * the model's @p internal_variables (models that share a name share
     * storage), then the listed effects' @p effect_fields. Body b's
     * particles are of material @p body_materials[b]; with more than one
     * body each particle stores its body index.
     */
    ParticleSet(
      const Triangulation<dim>                         &tria,
      const Mapping<dim>                               &mapping,
      const std::vector<unsigned int>                  &body_materials,
      const std::vector<std::string>                   &model_names,
      const std::vector<std::vector<FieldDescription>> &internal_variables,
      const std::vector<FieldDescription>              &method_fields = {},
      const std::vector<FieldDescription>              &effect_fields = {});

    PropertyLayout layout;
    CoreFields     fields;
    /** Offset of each material's internal variables (per material index). */
    std::vector<unsigned int> internal_offset;
    std::vector<unsigned int> n_internal;
    /** Each body's material index. */
    std::vector<unsigned int> material_of_body;

    /** The body index of the particle with properties @p props. */
    template <typename Properties>
    DEAL_II_ALWAYS_INLINE unsigned int
    body_of(const Properties &props) const
    {
      return fields.body == numbers::invalid_unsigned_int ?
               0 :
               static_cast<unsigned int>(props[fields.body]);
    }

    /** The material index of the particle with properties @p props: its
     * body's. */
    template <typename Properties>
    DEAL_II_ALWAYS_INLINE unsigned int
    material_of(const Properties &props) const
    {
      return material_of_body[body_of(props)];
    }
    /**
     * deal.II's particles: locations, ids and properties (always
     * current), reference locations (in the cell of the step's order),
     * ranks, and the lists of each cell's
     * particles. Those lists may lag behind the step, which moves
     * particles between this rank's cells in its own order (plan_relocation(),
     * finish_relocation()); walk a cell's particles with
     * for_each_particle_in_cell(), or call update_handler() before asking the
     * handler for them.
     */
    Particles::ParticleHandler<dim> handler;

    /** A particle that left its cell: its position in the step's order,
     * the indices in grid.cells of the cell it left and of the one it
     * entered, its unit-cell coordinates there, and whether its reference
     * location is set to them already (by G2P). */
    struct Move
    {
      unsigned int position, from, to;
      bool         placed;
      Point<dim>   reference;
    };

    /** The particles the step's move took out of their cells, recorded by
     * G2P for plan_relocation(), which then checks only these: their positions
     * in the step's order and the indices in grid.cells of the cells they
     * left; and those G2P put into a neighbour itself (moves, by position,
     * see g2p_sweep::enter_side_neighbor()). Trusted only while
     * `recorded`, which relocation, sort() and changed() clear. */
    struct Leavers
    {
      std::vector<unsigned int> position;
      std::vector<unsigned int> cell;
      std::vector<Move>         moves;
      bool                      recorded = false;

      void
      start()
      {
        position.clear();
        cell.clear();
        moves.clear();
        recorded = true;
      }
    } leavers;

    /** Sort the particles into their ranks and cells (deal.II's sort);
     * the step's order is rebuilt on its next use, and with it each
     * particle's reference location, by the same map the step uses (so
     * that a sort for a checkpoint leaves no trace in the last digits).
     * Collective. */
    void
    sort()
    {
      spare = {}; // the relocations' arrays: the sort has its own peak
      handler.sort_particles_into_subdomains_and_cells();
      leavers.recorded    = false;
      handler_lags        = false;
      reference_from_sort = true;
      order.invalidate();
    }

    /**
     * Put every particle the step moved out of its cell into the cell that
     * holds it now, after the step and before the next. When each such
     * particle is in a locally owned cell sharing a vertex with its old
     * one, only the step's order changes: the moved particles' handles go
     * to their new cells (regroup()), their reference locations set;
     * their data stay where they are, and deal.II's per-cell lists
     * lag until update_handler(). This replaces deal.II's sort, which
     * locates every particle again, copies the whole property pool and
     * cost more than a 2D step. When a particle on any rank went further
     * (another rank's cells, out of the grid, past the neighbours), every
     * rank sorts with deal.II instead, which also reports lost particles.
     * First, each particle that crossed a face of its cell that is one of
     * @p walls is put back on it (hold_at_walls()), counted in @p n_held.
     *
     * In two halves, so that the ranks agree on what to do in the step's
     * one reduction: plan_relocation() looks at this rank's particles that
     * G2P saw leave (all of them if it did not record) and returns 0 (none
     * left its cell), 1 (each that left is in one of this rank's
     * neighbouring cells) or 2 (one went further); not collective.
     * With @p may_cancel false (a particle here left by more than
     * round-off, so the ranks relocate for sure) it keeps no record for
     * cancel_relocation().
     */
    int
    plan_relocation(BackgroundGrid<dim>                &grid,
                    const std::set<types::boundary_id> &walls,
                    unsigned int                       &n_held,
                    const bool                          may_cancel = true);

    /** The second half: @p everywhere is the largest plan_relocation()
     * over the ranks (every rank calls this, also one that planned
     * nothing). Collective when it is 2 (deal.II sorts). Returns whether
     * the particles were moved here (false: deal.II sorted them). */
    bool
    finish_relocation(const BackgroundGrid<dim> &grid, const int everywhere);

    /** Or, where no rank relocates after all (the particles left their
     * cells by round-off only), put back what plan_relocation() changed:
     * the particles held at walls and the reference locations it set
     * (not allowed after a plan that may not be cancelled). */
    void
    cancel_relocation();

    /** Both halves, agreed in a reduction of their own (for tests and
     * tools; the step agrees in its own reduction). Collective. */
    bool
    relocate(BackgroundGrid<dim>                &grid,
             const std::set<types::boundary_id> &walls  = {},
             unsigned int                       *n_held = nullptr)
    {
      unsigned int held = 0;
      const int    here = plan_relocation(grid, walls, held, false);
      if (n_held != nullptr)
        *n_held = held;
      return finish_relocation(grid, Utilities::MPI::max(here, grid.comm));
    }

    /** A particle as it was before plan_relocation() changed it: its
     * location and reference location, and its properties if they
     * changed too (empty if not). */
    struct PoolEdit
    {
      typename ParticleOrder<dim>::Handle handle;
      Point<dim>                          location, reference;
      std::vector<double>                 properties;
    };

    /** Bring deal.II's per-cell lists up to the step's order over
     * @p grid (deal.II's sort, and the order rebuilt from it) if
     * a relocation moved particles since the last sort: before a grid
     * change, a repartition, a checkpoint, or code that asks the handler
     * for a cell's particles. Collective. */
    void
    update_handler(const BackgroundGrid<dim> &grid)
    {
      if (!handler_lags)
        return;
      sort();
      order_over(grid);
    }

    /** Whether deal.II's per-cell lists lag behind the step's order. */
    bool
    handler_lags_order() const
    {
      return handler_lags;
    }

    /** Say that the handler's particles or their cells changed other than
     * through sort(): an insertion or removal, a grid change, a restore.
     * Every such change must say so, or the step would visit handles that
     * are no longer these particles'. Collective when the handler's lists
     * lag (they are brought up to date first, as the order is rebuilt
     * from them). */
    void
    changed()
    {
      if (handler_lags)
        sort();
      leavers.recorded = false;
      order.invalidate();
    }

    /** The step's order of this rank's particles over @p grid's cells,
     * rebuilt here when the particles or the grid changed. */
    const ParticleOrder<dim> &
    order_over(const BackgroundGrid<dim> &grid) const
    {
      if (!order.is_valid_for(grid))
        {
          // Rebuilt from deal.II's lists, which must not lag: whoever
          // changes the grid calls update_handler() first.
          AssertThrow(!handler_lags, ExcInternalError());
          order.rebuild(grid, handler);
          if (reference_from_sort)
            set_reference_locations(grid);
        }
      return order;
    }

  private:
    /** Each particle's reference location in its cell of the order, by
     * GridCell::reference_point (deal.II's sort computes it by the
     * mapping, which may differ in the last digit). */
    void
    set_reference_locations(const BackgroundGrid<dim> &grid) const
    {
      auto &pool = handler.get_property_pool();
      for (std::size_t i = 0; i < grid.cells.size(); ++i)
        for (unsigned int k = order.cell_begin[i]; k < order.cell_begin[i + 1];
             ++k)
          pool.set_reference_location(order.handles[k],
                                      grid.cells[i].reference_point(
                                        pool.get_location(order.handles[k])));
      reference_from_sort = false;
    }

    mutable ParticleOrder<dim> order;
    /** What plan_relocation() found for finish_relocation(): the moves,
     * by position in the step's order. */
    std::vector<Move>     planned_moves;
    std::vector<PoolEdit> planned_edits;
    bool                  planned_may_cancel = true;
    bool                  handler_lags       = false;
    /** The order's arrays before the last relocation, reused by the next
     * (4 B a particle and 8 B a cell; the peak is the same without them,
     * as a relocation needs them while it regroups); sort() frees them. */
    struct
    {
      std::vector<typename ParticleOrder<dim>::Handle> handles;
      std::vector<unsigned int>                        cell_begin, filled;
    } spare;
    mutable bool reference_from_sort = false;
  };

  /** Read and write small tensors from a particle's property array. */
  template <int dim>
  inline Tensor<1, dim>
  read_vector(const double *p)
  {
    // deal.II's constructor from an array: a tensor made and then filled
    // is zeroed first, in stores the compiler keeps.
    return Tensor<1, dim>(*reinterpret_cast<const double(*)[dim]>(p));
  }

  template <int dim>
  inline void
  write_vector(double *p, const Tensor<1, dim> &t)
  {
    for (unsigned int d = 0; d < dim; ++d)
      p[d] = t[d];
  }

  template <int dim>
  inline Tensor<2, dim>
  read_tensor(const double *p)
  {
    return Tensor<2, dim>(*reinterpret_cast<const double(*)[dim][dim]>(p));
  }

  /** A particle's volume now, V0 det F, from its properties @p props. */
  template <int dim>
  inline double
  current_volume(const double *props, const CoreFields &f)
  {
    return props[f.initial_volume] *
           determinant(read_tensor<dim>(props + f.deformation_gradient));
  }

  template <int dim>
  inline void
  write_tensor(double *p, const Tensor<2, dim> &t)
  {
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        p[i * dim + j] = t[i][j];
  }

  template <int dim>
  inline SymmetricTensor<2, dim>
  read_symmetric(const double *p)
  {
    constexpr unsigned int n =
      SymmetricTensor<2, dim>::n_independent_components;
    return SymmetricTensor<2, dim>(*reinterpret_cast<const double(*)[n]>(p));
  }

  template <int dim>
  inline void
  write_symmetric(double *p, const SymmetricTensor<2, dim> &t)
  {
    for (unsigned int i = 0;
         i < SymmetricTensor<2, dim>::n_independent_components;
         ++i)
      p[i] = t.access_raw_entry(i);
  }
} // namespace dealmpm
