#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <dealmpm/adaptivity/adaptivity.h>
#include <dealmpm/transfer/stencil_order.h>

#include <algorithm>
#include <cctype>
#include <cmath>

namespace dealmpm
{
  namespace
  {
    /** For each active cell (by active_cell_index()), its index in
     * grid.cells, or invalid_unsigned_int if this rank does not own it. */
    template <int dim>
    std::vector<unsigned int>
    indices_in_grid(const BackgroundGrid<dim> &grid)
    {
      std::vector<unsigned int> index(grid.triangulation.n_active_cells(),
                                      numbers::invalid_unsigned_int);
      for (std::size_t i = 0; i < grid.cells.size(); ++i)
        index[grid.cells[i].cell->active_cell_index()] = i;
      return index;
    }

    /** "velocity jump" -> "Velocity jump": the criterion's subsection. */
    std::string
    title(std::string name)
    {
      if (!name.empty())
        name[0] = std::toupper(name[0]);
      return name;
    }

    /**
     * 'particles': the cells holding particles and the cells within a
     * buffer of k cells around them go to a level (the finest allowed by
     * default), every other cell to the coarsest. The buffer spreads
     * through the grid's nodes (a nodal vector with its ghosts), so that
     * it crosses rank boundaries and hanging nodes. With a margin of m
     * cells, the grid changes only when particles come within the buffer
     * of a coarser cell, and then the buffer and the margin are refined
     * (and what lies beyond coarsened): a body moving through the grid
     * changes it about every m + 1 cells of travel instead of every cell.
     */
    template <int dim>
    class ParticlesCriterion : public RefinementCriterion<dim>
    {
    public:
      explicit ParticlesCriterion(SceneReader &reader)
        : buffer(reader.get_integer("Buffer cells"))
        , margin(reader.get_integer("Margin cells"))
        , level(reader.get_integer("Level"))
      {}

      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry("Buffer cells",
                          "1",
                          Patterns::Integer(0, 10),
                          "Layers of cells around those with particles that "
                          "are refined too, so that particles moving "
                          "between adaptations stay on fine cells.");
        prm.declare_entry(
          "Margin cells",
          "1",
          Patterns::Integer(0, 10),
          "Layers beyond the buffer refined with it. The grid then changes "
          "only when particles come within 'Buffer cells' of a coarser "
          "cell: a body moving through the grid changes it about every "
          "margin + 1 cells of travel instead of every cell (a grid change "
          "costs tens of steps), on more fine cells (a 3D cube falling 0.4 "
          "m: 6 grid changes instead of 40, 0.65 of the time; "
          "benchmarks/README.md). 0: the grid follows the particles at "
          "every adaptation.");
        prm.declare_entry("Level",
                          "-1",
                          Patterns::Integer(-1),
                          "The level of cells with particles; -1: "
                          "'Maximum level'.");
      }

      unsigned int
      level_of_particle_cells(const unsigned int max_level) const override
      {
        return level < 0 ? max_level : level;
      }

      void
      target_levels(const AdaptivityContext<dim> &context,
                    std::vector<int>             &levels) const override
      {
        const BackgroundGrid<dim>                         &grid = context.grid;
        const ParticlesByCell<dim, const ParticleSet<dim>> particles(
          grid, context.particles);
        std::vector<bool> inside(grid.cells.size());
        for (std::size_t i = 0; i < grid.cells.size(); ++i)
          inside[i] = !particles.empty(i);
        spread(grid, buffer, inside);
        const int wanted = level_of_particle_cells(context.max_level);
        if (margin > 0)
          {
            // Particles still within fine cells and their buffer: keep the
            // grid as it is.
            const int target =
              std::clamp<int>(wanted, context.min_level, context.max_level);
            bool short_of_buffer = false;
            for (std::size_t i = 0; i < grid.cells.size(); ++i)
              short_of_buffer =
                short_of_buffer ||
                (inside[i] && grid.level(grid.cells[i].cell) < target);
            if (!Utilities::MPI::logical_or(short_of_buffer, context.comm))
              {
                for (std::size_t i = 0; i < grid.cells.size(); ++i)
                  levels[i] = grid.level(grid.cells[i].cell);
                return;
              }
            spread(grid, margin, inside);
          }
        for (std::size_t i = 0; i < grid.cells.size(); ++i)
          levels[i] = inside[i] ? wanted : context.min_level;
      }

      bool
      reads_handler_lists() const override
      {
        return false;
      }

    private:
      /** Widen the marked cells @p inside by @p layers layers of cells
       * (those sharing a node with a marked one). Collective. */
      static void
      spread(const BackgroundGrid<dim> &grid,
             const unsigned int         layers,
             std::vector<bool>         &inside)
      {
        LinearAlgebra::distributed::Vector<double> marked(grid.partitioner);
        std::vector<types::global_dof_index>       dofs(
          GeometryInfo<dim>::vertices_per_cell);
        const auto cell_dofs = [&](const std::size_t i) {
          typename DoFHandler<dim>::active_cell_iterator(*grid.cells[i].cell,
                                                         &grid.dof_handler)
            ->get_dof_indices(dofs);
        };
        for (unsigned int layer = 0; layer < layers; ++layer)
          {
            marked = 0;
            for (std::size_t i = 0; i < grid.cells.size(); ++i)
              if (inside[i])
                {
                  cell_dofs(i);
                  for (const types::global_dof_index d : dofs)
                    marked(d) = 1;
                }
            marked.compress(VectorOperation::max);
            marked.update_ghost_values();
            for (std::size_t i = 0; i < grid.cells.size(); ++i)
              if (!inside[i])
                {
                  cell_dofs(i);
                  inside[i] = std::any_of(dofs.begin(),
                                          dofs.end(),
                                          [&](const types::global_dof_index d) {
                                            return marked(d) > 0;
                                          });
                }
            marked.zero_out_ghost_values();
          }
      }

      unsigned int buffer;
      unsigned int margin;
      int          level;
    };

    /**
     * 'velocity jump' and 'stress jump': refine where the particles of a
     * cell differ (the largest distance of a particle's velocity or stress
     * from the cell's mean, about h |grad|), relative to the largest speed
     * or stress of the run; coarsen where the particles of the cell's
     * parent (all its children) barely differ. Judging coarsening on the
     * parent keeps a refined cell whose children each hold one side of a
     * jump: judged on themselves they would be coarsened again at once.
     */
    template <int dim>
    class JumpCriterion : public RefinementCriterion<dim>
    {
    public:
      JumpCriterion(SceneReader &reader, const bool stress)
        : stress(stress)
        , refine_fraction(reader.get_in_open_range("Refine fraction", 0, 1))
        , coarsen_fraction(reader.get_nonnegative("Coarsen fraction"))
      {
        if (!(coarsen_fraction < refine_fraction))
          reader.fail("Coarsen fraction", "a number below Refine fraction");
      }

      static void
      declare_parameters(ParameterHandler &prm, const std::string &what)
      {
        prm.declare_entry("Refine fraction",
                          "0.1",
                          Patterns::Double(),
                          "Refine a cell whose particles' " + what +
                            " differ from their mean by more than this "
                            "fraction of the largest " +
                            what + " of all particles (in (0, 1)).");
        prm.declare_entry("Coarsen fraction",
                          "0.02",
                          Patterns::Double(),
                          "Coarsen where the particles of the cell's parent "
                          "differ by less than this fraction (below Refine "
                          "fraction).");
      }

      void
      target_levels(const AdaptivityContext<dim> &context,
                    std::vector<int>             &levels) const override
      {
        const BackgroundGrid<dim> &grid = context.grid;
        const ParticleSet<dim>    &set  = context.particles;
        const unsigned int         n =
          stress ? SymmetricTensor<2, dim>::n_independent_components : dim;
        const unsigned int offset =
          stress ? set.fields.stress : set.fields.velocity;
        // The step's order of the particles, cell by cell (deal.II's lists
        // may lag behind it), and where each active cell is in grid.cells.
        const ParticlesByCell<dim, const ParticleSet<dim>> particles(grid, set);
        const std::vector<unsigned int> index = indices_in_grid(grid);
        // The largest squared distance from the mean of the particles in
        // @p cells (indices in grid.cells; the mean over all of them).
        std::vector<double> mean(n);
        const auto spread = [&](const std::vector<unsigned int> &cells) {
          std::fill(mean.begin(), mean.end(), 0.);
          double count = 0;
          for (const unsigned int i : cells)
            particles.for_each(i, [&](const auto &p) {
              for (unsigned int c = 0; c < n; ++c)
                mean[c] += p.get_properties()[offset + c];
              ++count;
            });
          double largest = 0;
          for (double &m : mean)
            m /= std::max(count, 1.);
          for (const unsigned int i : cells)
            particles.for_each(i, [&](const auto &p) {
              double d2 = 0;
              for (unsigned int c = 0; c < n; ++c)
                d2 += std::pow(p.get_properties()[offset + c] - mean[c], 2);
              largest = std::max(largest, d2);
            });
          return largest;
        };
        double largest = 0;
        for (std::size_t i = 0; i < grid.cells.size(); ++i)
          particles.for_each(i, [&](const auto &p) {
            double norm2 = 0;
            for (unsigned int c = 0; c < n; ++c)
              norm2 += std::pow(p.get_properties()[offset + c], 2);
            largest = std::max(largest, norm2);
          });
        largest = Utilities::MPI::max(largest, context.comm);
        if (!(largest > 0))
          {
            for (std::size_t i = 0; i < grid.cells.size(); ++i)
              levels[i] = grid.level(grid.cells[i].cell);
            return;
          }
        const double refine  = refine_fraction * refine_fraction * largest;
        const double coarsen = coarsen_fraction * coarsen_fraction * largest;
        for (std::size_t i = 0; i < grid.cells.size(); ++i)
          {
            const auto &cell = grid.cells[i].cell;
            levels[i]        = grid.level(cell);
            if (spread({static_cast<unsigned int>(i)}) > refine)
              levels[i] = context.max_level;
            else if (levels[i] > 0)
              {
                std::vector<unsigned int> family;
                for (const auto &child : cell->parent()->child_iterators())
                  if (child->is_active() && child->is_locally_owned())
                    family.push_back(index[child->active_cell_index()]);
                if (family.size() == cell->parent()->n_children() &&
                    spread(family) < coarsen)
                  levels[i] = grid.level(cell) - 1;
              }
          }
      }

      bool
      reads_handler_lists() const override
      {
        return false;
      }

    private:
      bool   stress;
      double refine_fraction;
      double coarsen_fraction;
    };
  } // namespace

  template <int dim>
  Registry<RefinementCriterion<dim>> &
  refinement_criterion_registry()
  {
    static Registry<RefinementCriterion<dim>> registry = [] {
      Registry<RefinementCriterion<dim>> r;
      r.add(
        "particles",
        "cells with particles and a buffer around them refined, empty cells "
        "coarsened.",
        &ParticlesCriterion<dim>::declare_parameters,
        [](SceneReader &reader) {
          return std::make_unique<ParticlesCriterion<dim>>(reader);
        });
      r.add(
        "velocity jump",
        "refined where the particles of a cell differ in velocity.",
        [](ParameterHandler &prm) {
          JumpCriterion<dim>::declare_parameters(prm, "velocities");
        },
        [](SceneReader &reader) {
          return std::make_unique<JumpCriterion<dim>>(reader, false);
        });
      r.add(
        "stress jump",
        "refined where the particles of a cell differ in stress.",
        [](ParameterHandler &prm) {
          JumpCriterion<dim>::declare_parameters(prm, "stresses");
        },
        [](SceneReader &reader) {
          return std::make_unique<JumpCriterion<dim>>(reader, true);
        });
      return r;
    }();
    return registry;
  }

  template <int dim>
  void
  AdaptivitySettings<dim>::declare_parameters(ParameterHandler &prm)
  {
    const auto &registry = refinement_criterion_registry<dim>();
    prm.enter_subsection("Adaptivity");
    prm.declare_entry(
      "Criteria",
      "",
      Patterns::MultipleSelection(registry.pattern()),
      "Comma-separated reasons to refine the background grid during the "
      "run (empty: the grid stays as made). A cell is refined when one "
      "criterion wants it finer, coarsened when all allow it. Available: " +
        registry.describe());
    prm.declare_entry("Steps between adaptations",
                      "10",
                      Patterns::Integer(1),
                      "The grid is adapted at the start and every this "
                      "many steps.");
    prm.declare_entry("Minimum level",
                      "0",
                      Patterns::Integer(0, 20),
                      "Cells are not coarsened below this level (0: the "
                      "cells of 'Grid/Cells' or the mesh file, before "
                      "'Grid/Global refinements').");
    prm.declare_entry("Maximum level",
                      "2",
                      Patterns::Integer(0, 20),
                      "Cells are not refined beyond this level.");
    prm.declare_entry("Maximum cells",
                      "1e6",
                      Patterns::Double(),
                      "No cell is refined while the grid would have more "
                      "cells than this (a warning says so once).");
    prm.declare_entry(
      "Split particles",
      "true",
      Patterns::Bool(),
      "Split a particle into 2^dim (mass, volume, momentum and the first "
      "moment of mass kept; stress, F and internal variables copied) when "
      "its cell is too small for it (see 'Particles per cell'), so that "
      "refined cells keep enough particles.");
    prm.declare_entry(
      "Merge particles",
      "false",
      Patterns::Bool(),
      "Merge the particles of coarsened cells where 2^dim or more of one "
      "body and material lie in the same of the cell's 'Particles per "
      "cell'^dim sub-cells (as the parts of a split particle do): they "
      "become one (mass, momentum, the "
      "first moment of mass and the current volume kept; F, stress and "
      "internal variables averaged: their spread is lost).");
    prm.declare_entry("Particles per cell",
                      "2",
                      Patterns::Integer(1, 10),
                      "Particles per direction a cell should hold: a "
                      "particle whose 2^dim parts would each fill at least "
                      "half of cell volume / this^dim is split.");
    for (const std::string &name : registry.names())
      {
        prm.enter_subsection(title(name));
        registry.get(name).declare(prm);
        prm.leave_subsection();
      }
    prm.leave_subsection();
  }

  template <int dim>
  unsigned int
  AdaptivitySettings<dim>::level_of_particle_cells() const
  {
    unsigned int level = 0;
    for (const auto &criterion : criteria)
      level = std::max(level, criterion->level_of_particle_cells(max_level));
    return enabled() ? std::clamp(level, min_level, max_level) : 0;
  }

  template <int dim>
  AdaptivitySettings<dim>
  AdaptivitySettings<dim>::read(SceneReader &reader)
  {
    const auto        &registry = refinement_criterion_registry<dim>();
    AdaptivitySettings s;
    SectionScope       section(reader, "Adaptivity");
    for (const std::string &name :
         Utilities::split_string_list(reader.get("Criteria"), ','))
      {
        if (!registry.has(name))
          reader.fail("Criteria",
                      "a comma-separated list of: " + registry.describe());
        if (std::find(s.names.begin(), s.names.end(), name) != s.names.end())
          reader.fail("Criteria", "each criterion listed once");
        SectionScope criterion(reader, title(name));
        s.criteria.push_back(registry.get(name).create(reader));
        s.names.push_back(name);
      }
    s.step_interval = reader.get_integer("Steps between adaptations");
    s.min_level     = reader.get_integer("Minimum level");
    s.max_level     = reader.get_integer("Maximum level");
    if (s.max_level < s.min_level)
      reader.fail("Maximum level", "a level at least 'Minimum level'");
    s.max_cells               = reader.get_positive("Maximum cells");
    s.split                   = reader.get_bool("Split particles");
    s.particles_per_direction = reader.get_integer("Particles per cell");
    return s;
  }

  template <int dim>
  std::vector<int>
  target_levels(const AdaptivitySettings<dim> &settings,
                const AdaptivityContext<dim>  &context)
  {
    const std::size_t n = context.grid.cells.size();
    std::vector<int>  combined(n, context.min_level), wanted(n);
    for (const auto &criterion : settings.criteria)
      {
        std::fill(wanted.begin(), wanted.end(), context.min_level);
        criterion->target_levels(context, wanted);
        for (std::size_t i = 0; i < n; ++i)
          combined[i] = std::max(combined[i], wanted[i]);
      }
    for (int &level : combined)
      level = std::clamp<int>(level, context.min_level, context.max_level);
    return combined;
  }

  template <int dim>
  bool
  flag_cells(const BackgroundGrid<dim> &grid,
             const std::vector<int>    &levels,
             const double               max_cells)
  {
    double n_refined = 0;
    for (std::size_t i = 0; i < grid.cells.size(); ++i)
      {
        const auto &cell = grid.cells[i].cell;
        cell->clear_refine_flag();
        cell->clear_coarsen_flag();
        if (grid.level(cell) < levels[i])
          {
            cell->set_refine_flag();
            ++n_refined;
          }
        else if (grid.level(cell) > levels[i])
          cell->set_coarsen_flag();
      }
    n_refined = Utilities::MPI::sum(n_refined, grid.comm);
    if (grid.triangulation.n_global_active_cells() +
          n_refined * (GeometryInfo<dim>::max_children_per_cell - 1) <=
        max_cells)
      return false;
    for (const GridCell<dim> &c : grid.cells)
      c.cell->clear_refine_flag();
    return true;
  }

  template <int dim>
  bool
  flags_may_change_grid(const BackgroundGrid<dim> &grid)
  {
    std::vector<bool> coarsen(grid.cells.size());
    for (std::size_t i = 0; i < grid.cells.size(); ++i)
      {
        if (grid.cells[i].cell->refine_flag_set())
          return true;
        coarsen[i] = grid.cells[i].cell->coarsen_flag_set() &&
                     grid.cells[i].cell->level() > 0;
      }
    // Where each sibling is in grid.cells.
    const std::vector<unsigned int> index = indices_in_grid(grid);
    std::vector<int> vertex_level(grid.triangulation.n_vertices());
    bool             undone = true;
    while (undone)
      {
        undone = false;
        // Each vertex's finest level after the flags; a ghost with the
        // flags it has here (deal.II's preparation sees no others).
        std::fill(vertex_level.begin(), vertex_level.end(), -1);
        const auto touch = [&](const auto &cell, const int level) {
          for (const unsigned int v : cell->vertex_indices())
            vertex_level[cell->vertex_index(v)] =
              std::max(vertex_level[cell->vertex_index(v)], level);
        };
        for (std::size_t i = 0; i < grid.cells.size(); ++i)
          touch(grid.cells[i].cell, grid.cells[i].cell->level() - coarsen[i]);
        for (const GridCell<dim> &c : grid.ghost_cells)
          touch(c.cell,
                c.cell->level() + c.cell->refine_flag_set() -
                  c.cell->coarsen_flag_set());
        for (std::size_t i = 0; i < grid.cells.size(); ++i)
          {
            if (!coarsen[i])
              continue;
            const auto &cell = grid.cells[i].cell;
            bool        keep = true;
            for (const unsigned int v : cell->vertex_indices())
              keep =
                keep && vertex_level[cell->vertex_index(v)] <= cell->level();
            // A family coarsens whole: a sibling that is refined, or owned
            // here and kept, keeps this one (one owned elsewhere may be
            // flagged).
            for (const auto &sibling : cell->parent()->child_iterators())
              keep = keep && sibling->is_active() &&
                     (!sibling->is_locally_owned() ||
                      coarsen[index[sibling->active_cell_index()]]);
            if (!keep)
              {
                coarsen[i] = false;
                undone     = true;
              }
          }
      }
    return std::find(coarsen.begin(), coarsen.end(), true) != coarsen.end();
  }

#define DEALMPM_INSTANTIATE(dim)                                           \
  template Registry<RefinementCriterion<dim>>                              \
    &refinement_criterion_registry<dim>();                                 \
  template struct AdaptivitySettings<dim>;                                 \
  template std::vector<int> target_levels(const AdaptivitySettings<dim> &, \
                                          const AdaptivityContext<dim> &); \
  template bool             flag_cells(const BackgroundGrid<dim> &,        \
                                       const std::vector<int> &,           \
                                       const double);                      \
  template bool             flags_may_change_grid(const BackgroundGrid<dim> &);
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
