#include <deal.II/base/geometry_info.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/mapping_cartesian.h>
#include <deal.II/fe/mapping_q1.h>

#include <dealmpm/base/errors.h>
#include <dealmpm/grid/background_grid.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <sstream>
#include <utility>

namespace dealmpm
{
  template <int dim>
  BackgroundGrid<dim>::BackgroundGrid(const MPI_Comm comm)
    : comm(comm)
    , triangulation(comm,
                    // The level difference of cells sharing a vertex is
                    // at most one (what the kernels across hanging nodes
                    // assume). Smoothing beyond that (islands, patches)
                    // acts on each rank's own cells and made the same
                    // adaptation give different grids on 1 and 2 ranks.
                    Triangulation<dim>::limit_level_difference_at_vertices)
    , fe(1)
    , dof_handler(triangulation)
  {}

  template <int dim>
  void
  BackgroundGrid<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Grid");
    declare_mesh_entries<dim>(prm);
    prm.declare_entry(
      "Most coarse cells",
      "auto",
      Patterns::Anything(),
      "Rectangle: a grid of more cells is made of fewer coarse cells (Cells "
      "divided by the least power of two they share that leaves at most "
      "this many) refined back to Cells. Every rank holds every coarse cell, "
      "which costs about 250 B (2D) or 500-600 B (3D) more than a refined "
      "cell, and only its share of the rest. 'auto': 1e4 (the column ran as "
      "fast as with 1e5 and held 3-8 % less memory; 1, as few as the counts "
      "allow, ran it at 0.92-1.0: benchmarks/README.md), or 1 when "
      "'Adaptivity/Criteria' lists one: p4est's balance across coarse cells "
      "is the largest part of a grid change (3D, 16k cells: 8,000 coarse "
      "cells 290 ms, 125 190 ms).");
    prm.declare_entry("Global refinements",
                      "0",
                      Patterns::Integer(0, 12),
                      "Times every cell is split in 2 per direction.");
    prm.enter_subsection("Local refinement");
    prm.declare_entry("Levels",
                      "0",
                      Patterns::Integer(0, 8),
                      "Extra refinements of the cells whose centre lies in "
                      "the box below (hanging nodes are handled).");
    prm.declare_entry("Lower corner",
                      repeat_value<dim>("0"),
                      Patterns::List(Patterns::Double(), dim, dim),
                      "Box lower corner.");
    prm.declare_entry("Upper corner",
                      repeat_value<dim>("0"),
                      Patterns::List(Patterns::Double(), dim, dim),
                      "Box upper corner.");
    prm.leave_subsection();
    prm.leave_subsection();
  }

  namespace
  {
    /** 'Most coarse cells' (the reader in section Grid). */
    double
    most_coarse_cells(const SceneReader &reader, const bool adaptive)
    {
      const std::string entry = "Most coarse cells";
      if (reader.get(entry) == "auto")
        return adaptive ? 1 : 1e4;
      double value = 0;
      try
        {
          value = Utilities::string_to_double(reader.get(entry));
        }
      catch (...)
        {}
      if (!(value >= 1 && std::isfinite(value)))
        reader.fail(entry, "'auto' or a number >= 1");
      return value;
    }
  } // namespace

  template <int dim>
  void
  BackgroundGrid<dim>::create(
    SceneReader                                      &reader,
    const std::function<void(const GridSize<dim> &)> &before_allocating,
    const SavedGrid                                  *saved,
    const bool                                        adaptive)
  {
    SectionScope grid(reader, "Grid");
    base_level = read_coarse_mesh<dim>(
      reader,
      triangulation,
      [&](const double n_cells, const BoundingBox<dim> &box) {
        before_allocating(refined_size(reader, n_cells, box));
      },
      max_coarse_refinements(reader),
      most_coarse_cells(reader, adaptive));
    coarse_checksum = checksum_of_coarse_grid();
    if (saved != nullptr)
      {
        if (saved->coarse_checksum != coarse_checksum)
          throw InputError(
            reader.file_name() +
            ": the coarse grid (section 'Grid', its mesh file) differs from "
            "the saved run's (" +
            saved->file +
            "; a checkpoint written before 2026-11-29, of a scene with "
            "'Adaptivity/Criteria' before 2026-11-30, or of a rectangle of "
            "1e4 to 1e5 cells before 2026-12-04, when such a rectangle had "
            "a coarse cell per cell, cannot be resumed: run it again)");
        // The saved cells and partition; a different number of ranks
        // gets the cells shared by count (the caller repartitions).
        triangulation.load(saved->file);
      }
    else
      {
        triangulation.refine_global(base_level +
                                    reader.get_integer("Global refinements"));
        refine_box(reader);
      }
    setup();
  }

  template <int dim>
  unsigned int
  BackgroundGrid<dim>::max_coarse_refinements(SceneReader &reader) const
  {
    // p4est's deepest level is 29 (2D) or 19 (3D); leave the scene's
    // refinements and 8 levels of adaptivity room below it. 2^10 (2D) or
    // 2^7 (3D) cells a side already make the coarse mesh of a grid of
    // millions of cells one of a few cells.
    const long deepest = dim == 2 ? 29 : 19;
    long       room    = deepest - 8 - reader.get_integer("Global refinements");
    {
      SectionScope local(reader, "Local refinement");
      room -= reader.get_integer("Levels");
    }
    return static_cast<unsigned int>(std::clamp(room, 0L, dim == 2 ? 10L : 7L));
  }

  template <int dim>
  std::string
  BackgroundGrid<dim>::checksum_of_coarse_grid() const
  {
    // FNV-1a over the vertices' bits and each cell's vertex indices.
    std::uint64_t hash = 14695981039346656037ull;
    const auto    add  = [&hash](const void *data, const std::size_t n) {
      for (std::size_t i = 0; i < n; ++i)
        {
          hash ^= static_cast<const unsigned char *>(data)[i];
          hash *= 1099511628211ull;
        }
    };
    for (const Point<dim> &v : triangulation.get_vertices())
      for (unsigned int d = 0; d < dim; ++d)
        add(&v[d], sizeof(double));
    for (const auto &cell : triangulation.cell_iterators_on_level(0))
      for (const unsigned int v : cell->vertex_indices())
        {
          const unsigned int index = cell->vertex_index(v);
          add(&index, sizeof(index));
        }
    std::ostringstream out;
    out << std::hex << std::setw(16) << std::setfill('0') << hash;
    return out.str();
  }

  template <int dim>
  GridSize<dim>
  BackgroundGrid<dim>::refined_size(SceneReader            &reader,
                                    const double            n_cells,
                                    const BoundingBox<dim> &box) const
  {
    const long    global_refinements = reader.get_integer("Global refinements");
    GridSize<dim> size{n_cells * std::pow(2., dim * global_refinements), box};
    // deal.II (as Debian builds it) numbers cells and nodes in 32 bits.
    if (size.n_cells > 2e9)
      reader.fail(global_refinements > 0 ? "Global refinements" : "Cells",
                  "fewer cells: the grid would have " +
                    std::to_string(static_cast<long>(size.n_cells)) +
                    " cells (at most 2e9: deal.II numbers nodes in 32 bits)");
    // Local refinement: the box's share of the cells, each split
    // 2^(dim levels) times.
    SectionScope local(reader, "Local refinement");
    const long   levels = reader.get_integer("Levels");
    if (levels > 0)
      {
        const Point<dim> lower = reader.get_point<dim>("Lower corner");
        const Point<dim> upper = reader.get_point<dim>("Upper corner");
        double           share = 1;
        for (unsigned int d = 0; d < dim; ++d)
          share *= std::clamp((std::min(upper[d], box.upper_bound(d)) -
                               std::max(lower[d], box.lower_bound(d))) /
                                box.side_length(d),
                              0.,
                              1.);
        size.n_cells += share * size.n_cells * (std::pow(2., dim * levels) - 1);
      }
    return size;
  }

  template <int dim>
  void
  BackgroundGrid<dim>::refine_box(SceneReader &reader)
  {
    SectionScope local(reader, "Local refinement");
    const long   levels = reader.get_integer("Levels");
    if (levels == 0)
      return;
    const Point<dim>       lower = reader.get_point<dim>("Lower corner");
    const Point<dim>       upper = reader.get_point<dim>("Upper corner");
    const BoundingBox<dim> box({lower, upper});
    for (long level = 0; level < levels; ++level)
      {
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned() && box.point_inside(cell->center()))
            cell->set_refine_flag();
        triangulation.execute_coarsening_and_refinement();
      }
  }

  template <int dim>
  GridCell<dim>
  BackgroundGrid<dim>::make_cell(
    const typename DoFHandler<dim>::active_cell_iterator &dof_cell,
    bool                                                 &box)
  {
    constexpr unsigned int           n_vertices = GridCell<dim>::n_vertices;
    GridCell<dim>                    c;
    typename GridCell<dim>::Vertices vertices;
    c.cell = dof_cell;
    for (unsigned int v = 0; v < n_vertices; ++v)
      vertices[v] = dof_cell->vertex(v);
    c.origin     = vertices[0];
    c.far_corner = vertices[n_vertices - 1];
    c.h          = dof_cell->minimum_vertex_distance();
    c.measure    = dof_cell->measure();

    // Affine when x(xi) is linear: each vertex = v0 + sum of the edge
    // vectors along its set bits.
    Tensor<2, dim> J;
    for (unsigned int d = 0; d < dim; ++d)
      for (unsigned int e = 0; e < dim; ++e)
        J[e][d] = vertices[1u << d][e] - vertices[0][e];
    bool affine = true;
    box         = true;
    for (unsigned int v = 0; v < n_vertices; ++v)
      {
        Point<dim> expected = vertices[0];
        for (unsigned int d = 0; d < dim; ++d)
          if ((v >> d) & 1u)
            for (unsigned int e = 0; e < dim; ++e)
              expected[e] += J[e][d];
        if (expected.distance(vertices[v]) > 1e-12 * c.h)
          affine = false;
      }
    for (unsigned int d = 0; d < dim; ++d)
      for (unsigned int e = 0; e < dim; ++e)
        if (d != e && std::abs(J[e][d]) > 1e-12 * c.h)
          box = false;
    // A refined box cell's vertices are midpoints, off an axis by round-off
    // (1e-17 m); its K must be exactly diagonal, or the sweeps take the
    // general path in it (LinearWeights::is_box(): a 3D column refined once
    // took 1,308 instead of 859 instructions per particle-step).
    if (affine && box)
      for (unsigned int d = 0; d < dim; ++d)
        for (unsigned int e = 0; e < dim; ++e)
          if (d != e)
            J[e][d] = 0.;
    c.affine           = affine;
    c.inverse_jacobian = invert(J);
    if (!affine)
      {
        curved_vertices.push_back(vertices);
        c.stored_vertices = &curved_vertices.back();
        Point<dim> centre;
        for (unsigned int d = 0; d < dim; ++d)
          centre[d] = 0.5;
        c.affine           = false;
        c.inverse_jacobian = c.inverse_jacobian_at(centre);
      }

    add_effective_nodes(dof_cell, c);
    return c;
  }

  template <int dim>
  void
  BackgroundGrid<dim>::add_effective_nodes(
    const typename DoFHandler<dim>::active_cell_iterator &dof_cell,
    GridCell<dim>                                        &c)
  {
    constexpr unsigned int               n_vertices = GridCell<dim>::n_vertices;
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    // Effective nodes: vertex DoFs with constrained ones replaced by their
    // masters, weighted.
    dof_cell->get_dof_indices(dofs);
    bool constrained = false;
    for (const auto dof : dofs)
      constrained = constrained || hanging_node_constraints.is_constrained(dof);
    c.first_node = cell_nodes.size();
    if (!constrained)
      {
        for (const auto dof : dofs)
          cell_nodes.push_back(partitioner->global_to_local(dof));
        c.n_nodes = n_vertices;
      }
    else
      {
        std::vector<types::global_dof_index>        nodes;
        std::vector<std::array<double, n_vertices>> weights;
        const auto add = [&](const types::global_dof_index node,
                             const unsigned int            v,
                             const double                  w) {
          const auto        it = std::find(nodes.begin(), nodes.end(), node);
          const std::size_t k  = it - nodes.begin();
          if (it == nodes.end())
            {
              nodes.push_back(node);
              weights.emplace_back();
              weights.back().fill(0.);
            }
          weights[k][v] += w;
        };
        for (unsigned int v = 0; v < n_vertices; ++v)
          if (hanging_node_constraints.is_constrained(dofs[v]))
            for (const auto &entry :
                 *hanging_node_constraints.get_constraint_entries(dofs[v]))
              add(entry.first, v, entry.second);
          else
            add(dofs[v], v, 1.);
        c.n_nodes      = nodes.size();
        c.first_weight = cell_node_weights.size();
        for (unsigned int k = 0; k < nodes.size(); ++k)
          {
            cell_nodes.push_back(partitioner->global_to_local(nodes[k]));
            for (unsigned int v = 0; v < n_vertices; ++v)
              cell_node_weights.push_back(weights[k][v]);
          }
      }
  }

  namespace
  {
    /** Whether every rank's cells are all boxes, and the box around all
     * ranks' cells, from this rank's (@p any_cell: it has one), in one
     * reduction: the min of (boxes, lower corner, -upper corner). */
    template <int dim>
    std::pair<bool, BoundingBox<dim>>
    reduce_extent(const bool        all_boxes,
                  const bool        any_cell,
                  const Point<dim> &lower,
                  const Point<dim> &upper,
                  const MPI_Comm    comm)
    {
      double extremes[2 * dim + 1];
      extremes[0] = all_boxes ? 1 : 0;
      for (unsigned int d = 0; d < dim; ++d)
        {
          extremes[1 + d]       = any_cell ? lower[d] : 1e300;
          extremes[1 + dim + d] = any_cell ? -upper[d] : 1e300;
        }
      Utilities::MPI::min(ArrayView<const double>(extremes, 2 * dim + 1),
                          comm,
                          ArrayView<double>(extremes, 2 * dim + 1));
      Point<dim> low, high;
      for (unsigned int d = 0; d < dim; ++d)
        {
          low[d]  = extremes[1 + d];
          high[d] = -extremes[1 + dim + d];
        }
      return {extremes[0] == 1, BoundingBox<dim>({low, high})};
    }
  } // namespace

  template <int dim>
  void
  BackgroundGrid<dim>::setup()
  {
    ++generation;
    dof_handler.distribute_dofs(fe);
    const IndexSet owned = dof_handler.locally_owned_dofs();
    const IndexSet relevant =
      DoFTools::extract_locally_relevant_dofs(dof_handler);
    partitioner =
      std::make_shared<Utilities::MPI::Partitioner>(owned, relevant, comm);

    hanging_node_constraints.clear();
    hanging_node_constraints.reinit(relevant);
    DoFTools::make_hanging_node_constraints(dof_handler,
                                            hanging_node_constraints);
    hanging_node_constraints.close();

    node_positions.assign(partitioner->locally_owned_size() +
                            partitioner->n_ghost_indices(),
                          Point<dim>());
    // Q1's nodes are the vertices of the owned and ghost cells (hanging
    // ones included): read there, without DoFTools' map of every node
    // (about 100 B a node while it lives, the set-up's peak).
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() || cell->is_ghost())
        for (const unsigned int v : cell->vertex_indices())
          {
            const types::global_dof_index dof = cell->vertex_dof_index(v, 0);
            if (partitioner->in_local_range(dof) ||
                partitioner->is_ghost_entry(dof))
              node_positions[partitioner->global_to_local(dof)] =
                cell->vertex(v);
          }

    cells.clear();
    cells.reserve(triangulation.n_locally_owned_active_cells());
    ghost_cells.clear();
    curved_vertices.clear();
    cell_nodes.clear();
    cell_node_weights.clear();
    bool       all_boxes = true;
    Point<dim> lower, upper;
    bool       first = true;
    for (const auto &dof_cell : dof_handler.active_cell_iterators())
      {
        if (!dof_cell->is_locally_owned() && !dof_cell->is_ghost())
          continue;
        bool                box = true;
        const GridCell<dim> c   = make_cell(dof_cell, box);
        all_boxes               = all_boxes && c.affine && box;
        for (const Point<dim> &x : c.vertices())
          {
            for (unsigned int d = 0; d < dim; ++d)
              {
                lower[d] = first ? x[d] : std::min(lower[d], x[d]);
                upper[d] = first ? x[d] : std::max(upper[d], x[d]);
              }
            first = false;
          }
        (dof_cell->is_locally_owned() ? cells : ghost_cells).push_back(c);
      }
    clear_neighbors();
    // The mapping is made once: the particle handler keeps a reference to
    // it. Refining boxes gives boxes, so it stays right when the grid
    // changes.
    const auto [boxes, box] =
      reduce_extent(all_boxes, !first, lower, upper, comm);
    const bool was_cartesian = cartesian;
    cartesian                = boxes;
    if (!mapping)
      mapping = cartesian ? std::unique_ptr<Mapping<dim>>(
                              std::make_unique<MappingCartesian<dim>>()) :
                            std::make_unique<MappingQ1<dim>>();
    else
      AssertThrow(cartesian || !was_cartesian,
                  ExcMessage("a grid of boxes changed into one that is not"));

    bounding_box = box;
  }

  namespace
  {
    /** For each vertex of the triangulation, the cells of @p local (owned
     * and ghost, by active cell index) that touch it, as deal.II's
     * GridTools::vertex_to_cell_map counts touching (a hanging vertex
     * also lists the coarse cell whose face or, in 3D, edge holds it) and
     * in its order (by cell iterator), in flat arrays: vertex v's cells
     * are cell[begin[v]] to cell[begin[v + 1]], possibly repeated.
     * deal.II's map builds a std::set per vertex of the whole mesh. */
    template <int dim>
    struct CellsAtVertices
    {
      std::vector<unsigned int> begin;
      std::vector<unsigned int> cell; ///< BackgroundGrid::local_cell() index

      /** @p local: per active cell index, its local_cell() index or
       * numbers::invalid_unsigned_int. Indices, not pointers: this is the
       * peak of a moving scene's memory (about 32 entries a 3D cell). */
      CellsAtVertices(const BackgroundGrid<dim>       &grid,
                      const std::vector<unsigned int> &local)
      {
        const unsigned int n_local =
          grid.cells.size() + grid.ghost_cells.size();
        // Where every owned and ghost cell has one level, no vertex of an
        // owned cell hangs: a cell's own vertices are all it touches (the
        // faces and lines below would add only what the neighbours add
        // themselves).
        bool one_level = true;
        for (unsigned int k = 1; k < n_local; ++k)
          one_level = one_level && grid.local_cell(k).cell->level() ==
                                     grid.local_cell(0).cell->level();
        // Visit every (vertex, cell) pair twice: count, then place.
        const auto for_each_pair = [&](const auto &visit) {
          for (unsigned int k = 0; k < n_local; ++k)
            {
              const auto &cell = grid.local_cell(k).cell;
              for (const unsigned int v : cell->vertex_indices())
                visit(cell->vertex_index(v), k);
              if (one_level)
                continue;
              for (const unsigned int f : cell->face_indices())
                if (!cell->at_boundary(f) && cell->neighbor(f)->is_active())
                  if (const unsigned int n =
                        local[cell->neighbor(f)->active_cell_index()];
                      n != numbers::invalid_unsigned_int)
                    for (const unsigned int v : cell->face(f)->vertex_indices())
                      visit(cell->face(f)->vertex_index(v), n);
              if constexpr (dim == 3)
                for (unsigned int l = 0; l < cell->n_lines(); ++l)
                  if (cell->line(l)->has_children())
                    visit(cell->line(l)->child(0)->vertex_index(1), k);
            }
        };
        begin.assign(grid.triangulation.n_vertices() + 1, 0);
        for_each_pair(
          [&](const unsigned int v, unsigned int) { ++begin[v + 1]; });
        for (std::size_t v = 0; v + 1 < begin.size(); ++v)
          begin[v + 1] += begin[v];
        cell.resize(begin.back());
        std::vector<unsigned int> next(begin.begin(), begin.end() - 1);
        for_each_pair([&](const unsigned int v, const unsigned int k) {
          cell[next[v]++] = k;
        });
        for (std::size_t v = 0; v + 1 < begin.size(); ++v)
          std::sort(cell.begin() + begin[v],
                    cell.begin() + begin[v + 1],
                    [&grid](const unsigned int a, const unsigned int b) {
                      return grid.local_cell(a).cell < grid.local_cell(b).cell;
                    });
      }
    };
  } // namespace

  template <int dim>
  void
  BackgroundGrid<dim>::clear_neighbors()
  {
    neighbor_begin.clear();
    neighbor_list.clear();
    neighbor_by_side.clear();
  }

  template <int dim>
  void
  BackgroundGrid<dim>::find_neighbors()
  {
    if (has_neighbors() || cells.empty())
      return;
    std::vector<unsigned int> local(triangulation.n_active_cells(),
                                    numbers::invalid_unsigned_int);
    for (unsigned int k = 0; k < cells.size() + ghost_cells.size(); ++k)
      local[local_cell(k).cell->active_cell_index()] = k;
    const CellsAtVertices<dim> at_vertex(*this, local);
    neighbor_begin.assign(1, 0);
    neighbor_begin.reserve(cells.size() + 1);
    neighbor_list.clear();
    neighbor_list.reserve(cells.size() * Utilities::pow(3, dim));
    // listed_for[n] == i + 1: cell n is already among cell i's neighbours
    // (kept in the order first met, as a search of the list kept them).
    std::vector<unsigned int> listed_for(cells.size() + ghost_cells.size(), 0);
    for (unsigned int i = 0; i < cells.size(); ++i)
      {
        for (const unsigned int v : cells[i].cell->vertex_indices())
          {
            const unsigned int vertex = cells[i].cell->vertex_index(v);
            for (unsigned int k = at_vertex.begin[vertex];
                 k < at_vertex.begin[vertex + 1];
                 ++k)
              if (const unsigned int n = at_vertex.cell[k];
                  listed_for[n] != i + 1)
                {
                  listed_for[n] = i + 1;
                  neighbor_list.push_back(n);
                }
          }
        neighbor_begin.push_back(neighbor_list.size());
      }
    find_side_neighbors();
  }

  template <int dim>
  void
  BackgroundGrid<dim>::find_side_neighbors()
  {
    neighbor_by_side.clear();
    if (!cartesian)
      return;
    neighbor_by_side.resize(cells.size());
    for (unsigned int i = 0; i < cells.size(); ++i)
      {
        const GridCell<dim> &own = cells[i];
        neighbor_by_side[i].fill(numbers::invalid_unsigned_int);
        for (const unsigned int k : neighbors_of(i))
          {
            const GridCell<dim> &c     = local_cell(k);
            unsigned int         index = 0, stride = 1;
            for (unsigned int d = 0; d < dim; ++d, stride *= 3)
              {
                const double tolerance = 1e-10 * own.h;
                if (c.far_corner[d] <= own.origin[d] + tolerance)
                  index += 0;
                else if (c.origin[d] >= own.far_corner[d] - tolerance)
                  index += 2 * stride;
                else
                  index += stride;
              }
            neighbor_by_side[i][index] = k;
          }
      }
  }

  template class BackgroundGrid<2>;
  template class BackgroundGrid<3>;
} // namespace dealmpm
