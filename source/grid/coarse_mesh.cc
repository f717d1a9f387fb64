// The mesh entries (a rectangle or a Gmsh file) that the background grid
// and each FEM region read, and the coarse mesh they describe.
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>

#include <dealmpm/base/errors.h>
#include <dealmpm/grid/background_grid.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

namespace dealmpm
{
  template <int dim>
  void
  declare_mesh_entries(ParameterHandler &prm)
  {
    prm.declare_entry("Type",
                      "rectangle",
                      Patterns::Selection("rectangle|mesh file"),
                      "'rectangle': a box from Lower corner to Upper corner "
                      "split into Cells; boundary ids 0/1 at x min/max, 2/3 at "
                      "y min/max, 4/5 at z min/max. 'mesh file': a Gmsh .msh "
                      "file (quadrilaterals or hexahedra) whose physical "
                      "boundary tags become boundary ids.");
    prm.declare_entry("Lower corner",
                      repeat_value<dim>("0"),
                      Patterns::List(Patterns::Double(), dim, dim),
                      "Rectangle: lower corner, one number per dimension.");
    prm.declare_entry("Upper corner",
                      repeat_value<dim>("1"),
                      Patterns::List(Patterns::Double(), dim, dim),
                      "Rectangle: upper corner, one number per dimension.");
    prm.declare_entry("Cells",
                      repeat_value<dim>("10"),
                      Patterns::List(Patterns::Integer(1), dim, dim),
                      "Rectangle: cells per direction, one positive integer "
                      "per dimension. Counts with a common factor 2^k (2048, "
                      "1024 rather than 2000, 1000) let a large grid be "
                      "fewer coarse cells (Most coarse cells). Levels "
                      "(adaptivity, output) count from these cells.");
    prm.declare_entry("Mesh file",
                      "",
                      Patterns::FileName(),
                      "Mesh file: path of the Gmsh .msh file, relative to the "
                      "scene file's folder or absolute.");
  }

  namespace
  {
    /** The largest k <= @p at_most such that 2^k divides every count. */
    unsigned int
    common_power_of_two(const std::vector<unsigned int> &counts,
                        const unsigned int               at_most)
    {
      unsigned int k = at_most;
      for (const unsigned int n : counts)
        k = std::min(k, static_cast<unsigned int>(__builtin_ctz(n)));
      return k;
    }

    /** The rectangle of the section's entries into @p mesh, of few
     * coarse cells (read_coarse_mesh()); returns the refinements that
     * make its Cells. */
    template <int dim>
    unsigned int
    read_rectangle(
      const SceneReader                                           &reader,
      Triangulation<dim>                                          &mesh,
      const std::function<void(double, const BoundingBox<dim> &)> &before,
      const unsigned int max_refinements,
      const double       most_coarse_cells)
    {
      const Point<dim>          lower = reader.get_point<dim>("Lower corner");
      const Point<dim>          upper = reader.get_point<dim>("Upper corner");
      const std::vector<double> cells = reader.get_doubles("Cells");
      if (cells.size() != dim)
        reader.fail("Cells", std::to_string(dim) + " positive integers");
      std::vector<unsigned int> repetitions;
      double                    n_cells = 1;
      for (const double c : cells)
        {
          if (!(c >= 1 && c == static_cast<unsigned int>(c)))
            reader.fail("Cells",
                        "positive integers (at least one cell per direction)");
          repetitions.push_back(static_cast<unsigned int>(c));
          n_cells *= c;
        }
      for (unsigned int d = 0; d < dim; ++d)
        if (!(upper[d] > lower[d]))
          reader.fail("Upper corner",
                      "each coordinate larger than Lower corner's");
      // The least k that leaves at most most_coarse_cells (a grid of that
      // many or fewer stays as it was: its own coarse mesh).
      const unsigned int most =
        common_power_of_two(repetitions, max_refinements);
      unsigned int k = 0;
      while (k < most && n_cells / std::pow(2., dim * k) > most_coarse_cells)
        ++k;
      double n_coarse = 1;
      for (unsigned int &r : repetitions)
        {
          r >>= k;
          n_coarse *= r;
        }
      if (n_coarse > 2e8)
        reader.fail("Cells",
                    "counts that share a power of two (each count divided "
                    "by the largest 2^k that divides them all gives the "
                    "coarse cells, which every rank holds): " +
                      std::to_string(static_cast<long>(n_coarse)) +
                      " coarse cells (at most 2e8)");
      before(n_cells, BoundingBox<dim>({lower, upper}));
      GridGenerator::subdivided_hyper_rectangle(
        mesh, repetitions, lower, upper, /*colorize=*/true);
      return k;
    }
  } // namespace

  template <int dim>
  unsigned int
  read_coarse_mesh(
    const SceneReader                                           &reader,
    Triangulation<dim>                                          &mesh,
    const std::function<void(double, const BoundingBox<dim> &)> &before,
    const unsigned int max_refinements,
    const double       most_coarse_cells)
  {
    if (reader.get("Type") == "rectangle")
      return read_rectangle(
        reader, mesh, before, max_refinements, most_coarse_cells);
    std::ifstream in(reader.get_file("Mesh file", "a readable Gmsh .msh file"));
    // Read serially first: p4est crashes on simplices instead of saying so.
    Triangulation<dim> serial;
    GridIn<dim>        grid_in;
    grid_in.attach_triangulation(serial);
    try
      {
        grid_in.read_msh(in);
      }
    catch (const std::exception &e)
      {
        reader.fail("Mesh file",
                    "a Gmsh .msh mesh of quadrilaterals/hexahedra (reading "
                    "failed)");
      }
    if (!serial.all_reference_cells_are_hyper_cube())
      reader.fail("Mesh file",
                  "a mesh of quadrilaterals (2D) or hexahedra (3D), not "
                  "triangles or tetrahedra");
    for (const auto &cell : serial.active_cell_iterators())
      {
        // The Jacobian's sign at every vertex: negative where a cell is
        // inverted or twisted.
        double det_min = std::numeric_limits<double>::max();
        for (const unsigned int v : cell->vertex_indices())
          {
            Tensor<2, dim> J;
            for (unsigned int d = 0; d < dim; ++d)
              {
                const unsigned int w    = v ^ (1u << d);
                const double       sign = (v >> d) & 1u ? 1. : -1.;
                J[d] = sign * (cell->vertex(v) - cell->vertex(w));
              }
            det_min = std::min(det_min, determinant(J));
          }
        if (!(det_min > 0))
          {
            std::ostringstream where;
            where << cell->center();
            reader.fail("Mesh file",
                        "a mesh without inverted or twisted cells (the cell "
                        "at " +
                          where.str() + " is)");
          }
      }
    before(serial.n_active_cells(), BoundingBox<dim>(serial.get_vertices()));
    mesh.copy_triangulation(serial);
    return 0;
  }

  template void
  declare_mesh_entries<2>(ParameterHandler &);
  template void
  declare_mesh_entries<3>(ParameterHandler &);
  template unsigned int
  read_coarse_mesh(const SceneReader &,
                   Triangulation<2> &,
                   const std::function<void(double, const BoundingBox<2> &)> &,
                   unsigned int,
                   double);
  template unsigned int
  read_coarse_mesh(const SceneReader &,
                   Triangulation<3> &,
                   const std::function<void(double, const BoundingBox<3> &)> &,
                   unsigned int,
                   double);
} // namespace dealmpm
