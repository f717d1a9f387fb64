#pragma once

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/partitioner.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>

#include <dealmpm/base/scene_reader.h>

#include <array>
#include <deque>
#include <functional>
#include <memory>
#include <vector>

namespace dealmpm
{
  using namespace dealii;

  /**
   * What the per-step kernels need of one locally owned cell, computed once
   * per mesh: its first and last vertex, the inverse Jacobian when the cell
   * is affine, its size for the CFL limit, and its "effective nodes": the
   * vertex DoFs with hanging nodes replaced by their masters, so that every
   * kernel sees continuous shape functions that sum to one without special
   * cases. The other vertices are the triangulation's (vertex()), or kept
   * aside for a cell that is not affine, whose map reads them all: a cell
   * costs 176 B in 3D instead of 320 B with all eight (a quarter of a
   * grid's memory before 2026-11-30).
   */
  template <int dim>
  struct GridCell
  {
    static constexpr unsigned int n_vertices = 1u << dim;
    using Vertices = std::array<Point<dim>, n_vertices>;

    typename Triangulation<dim>::active_cell_iterator cell;
    Point<dim>                                        origin; ///< vertex 0
    Point<dim> far_corner; ///< vertex n_vertices - 1
    /** All vertices, for a cell that is not affine (in the grid's
     * BackgroundGrid::curved_vertices) or one made by hand; else
     * nullptr, and vertex() reads the triangulation's. */
    const Vertices *stored_vertices = nullptr;
    /** d(xi)/dx of the map from the unit cell; exact for affine cells. */
    Tensor<2, dim> inverse_jacobian;
    double         h       = 0; ///< shortest edge
    double         measure = 0;

    unsigned int first_node = 0; ///< into BackgroundGrid::cell_nodes
    unsigned int n_nodes    = 0;
    /** Into BackgroundGrid::cell_node_weights (n_nodes x n_vertices), or
     * numbers::invalid_unsigned_int when no vertex is constrained (then the
     * effective nodes are the vertices, in order). */
    unsigned int first_weight = numbers::invalid_unsigned_int;
    bool         affine       = true;

    /** Vertex @p v, the same number the triangulation holds. */
    Point<dim>
    vertex(const unsigned int v) const
    {
      return stored_vertices != nullptr ? (*stored_vertices)[v] :
                                          cell->vertex(v);
    }

    /** All vertices (for bounding boxes; not on a per-particle path). */
    Vertices
    vertices() const
    {
      Vertices all;
      for (unsigned int v = 0; v < n_vertices; ++v)
        all[v] = vertex(v);
      return all;
    }

    /** Position of unit-cell point xi (the Q1 map). */
    Point<dim>
    real_point(const Point<dim> &xi) const;

    /** Unit-cell coordinates of x: exact for affine cells, Newton's method
     * on the Q1 map otherwise. May lie outside [0,1]^dim. Inline for
     * affine cells: G2P calls it once per particle and step. */
    Point<dim>
    reference_point(const Point<dim> &x) const
    {
      if (affine)
        return Point<dim>(inverse_jacobian * (x - origin));
      return reference_point_by_newton(x);
    }

    /** reference_point() of an axis-aligned box cell (d xi / d x
     * diagonal, LinearWeights::is_box()): the same numbers without the
     * products with the zero off-diagonal entries. */
    Point<dim>
    reference_point_in_box(const Point<dim> &x) const
    {
      Point<dim> xi;
      for (unsigned int d = 0; d < dim; ++d)
        xi[d] = (x[d] - origin[d]) * inverse_jacobian[d][d];
      return xi;
    }

    /** reference_point() of a cell that is not affine. */
    Point<dim>
    reference_point_by_newton(const Point<dim> &x) const;

    /** d(xi)/dx at xi (the inverse Jacobian of the Q1 map). */
    Tensor<2, dim>
    inverse_jacobian_at(const Point<dim> &xi) const;
  };

  /** The cells a grid will have and the box it fills, known before the
   * cells are made. */
  template <int dim>
  struct GridSize
  {
    double           n_cells = 0;
    BoundingBox<dim> box;
  };

  /** A grid saved in a checkpoint: the file Triangulation::save() wrote
   * and the coarse_checksum of the grid it refined. */
  struct SavedGrid
  {
    std::string file;
    std::string coarse_checksum;
  };

  /** The entries of a mesh (Type, Lower corner, Upper corner, Cells, Mesh
   * file) in the current section: the background grid's and each FEM
   * region's. */
  template <int dim>
  void
  declare_mesh_entries(ParameterHandler &prm);

  /** The coarse mesh those entries describe, into @p mesh: a colorized
   * rectangle, or a Gmsh file of quadrilaterals/hexahedra whose cells are
   * neither inverted nor twisted (one-line failures). @p before sees the
   * number of cells the entries ask for and the box before any is made.
   *
   * Returns how many global refinements make the entries' cells of
   * @p mesh: a rectangle of more than @p most_coarse_cells cells is made
   * of its Cells divided by 2^k, the least power of two that divides them
   * all and leaves at most that many coarse cells (or the largest that
   * divides them all, k at most @p max_refinements), so that the coarse
   * mesh, which p4est and deal.II keep whole on every rank, stays small;
   * the caller refines it k times. 0 for a smaller rectangle and for a
   * Gmsh mesh, which are their own coarse mesh. */
  template <int dim>
  unsigned int
  read_coarse_mesh(
    const SceneReader                                           &reader,
    Triangulation<dim>                                          &mesh,
    const std::function<void(double, const BoundingBox<dim> &)> &before =
      [](double, const BoundingBox<dim> &) {},
    unsigned int max_refinements   = 0,
    double       most_coarse_cells = 1e5);

  /**
   * The background grid: a distributed triangulation (a subdivided rectangle
   * or a Gmsh mesh, optionally refined), FE_Q(1) nodes, hanging-node
   * constraints, the layout of nodal vectors, and the per-cell data of the
   * locally owned cells.
   */
  template <int dim>
  class BackgroundGrid
  {
  public:
    explicit BackgroundGrid(const MPI_Comm comm);

    static void
    declare_parameters(ParameterHandler &prm);

    /** Read the "Grid" section, build and refine the mesh, set up nodes.
     * The reader must be at the top level. @p before_allocating sees the
     * grid's size before its cells are made (and may refuse it by
     * throwing). A @p saved grid (a resumed run's) replaces the scene's
     * refinement with its own cells and partition, after its coarse grid
     * is found to be this scene's (else InputError). An @p adaptive grid
     * (one that 'Adaptivity' will change) is made of as few coarse cells
     * as its counts allow unless 'Most coarse cells' says otherwise. */
    void
    create(
      SceneReader                                      &reader,
      const std::function<void(const GridSize<dim> &)> &before_allocating =
        [](const GridSize<dim> &) {},
      const SavedGrid *saved    = nullptr,
      bool             adaptive = false);

    /** (Re)build DoFs, constraints, the node layout and the cell data, and
     * forget the neighbour tables (the shape function asks for them again),
     * after the mesh changed. The mapping is kept. */
    void
    setup();

    MPI_Comm                                           comm;
    parallel::distributed::Triangulation<dim>          triangulation;
    FE_Q<dim>                                          fe;
    DoFHandler<dim>                                    dof_handler;
    AffineConstraints<double>                          hanging_node_constraints;
    std::shared_ptr<const Utilities::MPI::Partitioner> partitioner;
    /** MappingCartesian when every cell is an axis-aligned box (the particle
     * sort is about 2.5x cheaper), MappingQ1 otherwise; made by the first
     * setup() and kept (the particle handler holds it). */
    std::unique_ptr<Mapping<dim>> mapping;
    bool                          cartesian = true;
    BoundingBox<dim>              bounding_box;
    /** A hash of the coarse grid's vertices and cells (the same on every
     * rank), which a checkpoint records. */
    std::string coarse_checksum;
    /** The level in the triangulation of the scene's cells ('Grid/Cells',
     * before 'Global refinements'): a rectangle's coarse mesh is fewer
     * cells refined this many times (read_coarse_mesh()). */
    unsigned int base_level = 0;

    /** The level of @p cell counted from the scene's cells, as the scene's
     * levels are ('Adaptivity/Minimum level', the output's "level"). */
    template <typename CellIterator>
    int
    level(const CellIterator &cell) const
    {
      return cell->level() - static_cast<int>(base_level);
    }

    /** How many times setup() ran: data kept per cell elsewhere (the
     * particles' order) records it and is rebuilt when it changed. */
    unsigned int generation = 0;

    /** Locally owned active cells, in the order every kernel visits them. */
    std::vector<GridCell<dim>> cells;
    /** The ghost layer's cells (same data), for kernels that reach into
     * neighbour cells. */
    std::vector<GridCell<dim>> ghost_cells;
    /** The vertices of the owned and ghost cells that are not affine
     * (GridCell::stored_vertices points here; a deque does not move its
     * elements as it grows). */
    std::deque<typename GridCell<dim>::Vertices> curved_vertices;
    /** Owned cell @p k (k < cells.size()), else ghost cell k -
     * cells.size(): the indices neighbors_of() and side_neighbor() use. */
    const GridCell<dim> &
    local_cell(const unsigned int k) const
    {
      return k < cells.size() ? cells[k] : ghost_cells[k - cells.size()];
    }

    /** Whether find_neighbors() has run on the present cells. */
    bool
    has_neighbors() const
    {
      return !neighbor_begin.empty();
    }

    /** The owned or ghost cells that share a vertex with owned cell @p i,
     * itself included, as local_cell() indices (after find_neighbors();
     * relocation and kernels with particle domains need it). */
    ArrayView<const unsigned int>
    neighbors_of(const unsigned int i) const
    {
      return {neighbor_list.data() + neighbor_begin[i],
              neighbor_begin[i + 1] - neighbor_begin[i]};
    }

    /** On grids of boxes, after find_neighbors(): the neighbour of owned
     * cell @p i lying below (0), level with (1) or above (2) it along each
     * axis, at @p side = sum_d side_d 3^d; nullptr where there is none. A
     * first guess for point location (next to hanging nodes a side may
     * hold several cells: check the guess, then search neighbors_of()). */
    const GridCell<dim> *
    side_neighbor(const unsigned int i, const unsigned int side) const
    {
      const unsigned int k = neighbor_by_side[i][side];
      return k == numbers::invalid_unsigned_int ? nullptr : &local_cell(k);
    }

    /** Whether side_neighbor() is there (grids of boxes). */
    bool
    has_side_neighbors() const
    {
      return !neighbor_by_side.empty();
    }

    /** Make neighbors_of() and side_neighbor() (once per grid). */
    void
    find_neighbors();
    /** Forget them (the cells changed). */
    void
    clear_neighbors();
    /** Local (owned + ghost) indices of the effective nodes of all cells. */
    std::vector<unsigned int> cell_nodes;
    /** Position of each local (owned + ghost) node, by local index. */
    std::vector<Point<dim>> node_positions;
    std::vector<double>     cell_node_weights;

  private:
    /** side_neighbor()'s table, from neighbors_of(). */
    void
    find_side_neighbors();

    /** neighbors_of(i) is neighbor_list[neighbor_begin[i]] to
     * [neighbor_begin[i + 1]]: 4 B a neighbour and none of a vector's
     * own (a vector of pointers per cell took about 250 B of a 3D cell
     * before 2026-11-30). */
    std::vector<unsigned int> neighbor_begin;
    std::vector<unsigned int> neighbor_list;
    /** Per owned cell, side_neighbor()'s local_cell() indices
     * (numbers::invalid_unsigned_int: none). */
    std::vector<std::array<unsigned int, Utilities::pow(3, dim)>>
      neighbor_by_side;

    void
    refine_box(SceneReader &reader);
    /** coarse_checksum of the triangulation before it is refined. */
    std::string
    checksum_of_coarse_grid() const;
    /** The cell data of one owned or ghost cell; @p box: whether it is an
     * axis-aligned box. */
    GridCell<dim>
    make_cell(const typename DoFHandler<dim>::active_cell_iterator &dof_cell,
              bool                                                 &box);
    /** Its effective nodes (hanging ones replaced by their masters). */
    void
    add_effective_nodes(
      const typename DoFHandler<dim>::active_cell_iterator &dof_cell,
      GridCell<dim>                                        &c);
    /** How many cells Global refinements and Local refinement make of
     * the scene's @p n_cells filling @p box; refuses more than 2e9. */
    GridSize<dim>
    refined_size(SceneReader            &reader,
                 const double            n_cells,
                 const BoundingBox<dim> &box) const;
    /** The most refinements read_coarse_mesh() may leave to make the
     * scene's cells. */
    unsigned int
    max_coarse_refinements(SceneReader &reader) const;
  };
} // namespace dealmpm
