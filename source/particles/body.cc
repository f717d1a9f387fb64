#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/grid_tools_cache.h>

#include <dealmpm/base/errors.h>
#include <dealmpm/particles/body.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <vector>

namespace dealmpm
{
  namespace
  {
    template <int dim>
    class BoxShape : public Shape<dim>
    {
    public:
      BoxShape(const Point<dim> &lower, const Point<dim> &upper)
        : box({lower, upper})
      {}
      bool
      contains(const Point<dim> &p) const override
      {
        return box.point_inside(p);
      }
      BoundingBox<dim>
      bounding_box() const override
      {
        return box;
      }

    private:
      BoundingBox<dim> box;
    };

    template <int dim>
    class BallShape : public Shape<dim>
    {
    public:
      BallShape(const Point<dim> &center,
                const double      radius,
                const double      inner_radius)
        : center(center)
        , radius(radius)
        , inner_radius(inner_radius)
      {}
      bool
      contains(const Point<dim> &p) const override
      {
        const double r = p.distance(center);
        return r <= radius && r >= inner_radius;
      }
      BoundingBox<dim>
      bounding_box() const override
      {
        Point<dim> lower = center, upper = center;
        for (unsigned int d = 0; d < dim; ++d)
          {
            lower[d] -= radius;
            upper[d] += radius;
          }
        return BoundingBox<dim>({lower, upper});
      }

    private:
      Point<dim> center;
      double     radius;
      double     inner_radius;
    };

    /** 3D: a circular cylinder along a coordinate axis, centred at center. */
    template <int dim>
    class CylinderShape : public Shape<dim>
    {
    public:
      CylinderShape(const Point<dim>  &center,
                    const double       radius,
                    const unsigned int axis,
                    const double       height)
        : center(center)
        , radius(radius)
        , axis(axis)
        , height(height)
      {}
      bool
      contains(const Point<dim> &p) const override
      {
        Tensor<1, dim> r     = p - center;
        const double   along = r[axis];
        r[axis]              = 0;
        return std::abs(along) <= 0.5 * height && r.norm() <= radius;
      }
      BoundingBox<dim>
      bounding_box() const override
      {
        Point<dim> lower = center, upper = center;
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double half = (d == axis) ? 0.5 * height : radius;
            lower[d] -= half;
            upper[d] += half;
          }
        return BoundingBox<dim>({lower, upper});
      }

    private:
      Point<dim>   center;
      double       radius;
      unsigned int axis;
      double       height;
    };

    /** 2D: the inside of a simple polygon (a slope's cross-section). */
    template <int dim>
    class PolygonShape : public Shape<dim>
    {
    public:
      explicit PolygonShape(const std::vector<Point<dim>> &vertices)
        : vertices(vertices)
        , box(vertices)
      {}
      bool
      contains(const Point<dim> &p) const override
      {
        // Even-odd rule on a ray along +x.
        bool inside = false;
        for (std::size_t i = 0, j = vertices.size() - 1; i < vertices.size();
             j = i++)
          {
            const Point<dim> &a = vertices[i], &b = vertices[j];
            if ((a[1] > p[1]) != (b[1] > p[1]) &&
                p[0] < a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]))
              inside = !inside;
          }
        return inside;
      }
      BoundingBox<dim>
      bounding_box() const override
      {
        return box;
      }
      /** The lengths inside the polygon of the line from @p p up (against
       * @p down): the material above, also under a slope's face. */
      double
      depth(const Point<dim> &p, const Tensor<1, dim> &down) const override
      {
        std::vector<double> crossings; // distances up from p
        for (std::size_t i = 0, j = vertices.size() - 1; i < vertices.size();
             j = i++)
          {
            const Tensor<1, dim> edge = vertices[j] - vertices[i];
            const Tensor<1, dim> to_a = vertices[i] - p;
            // p - t down = a + s edge: solve for t and s.
            const double det = edge[0] * down[1] - edge[1] * down[0];
            if (det == 0)
              continue; // a vertical edge: the neighbours cross
            const double s = (to_a[1] * down[0] - to_a[0] * down[1]) / det;
            const double t = (to_a[0] * edge[1] - to_a[1] * edge[0]) / det;
            if (s >= 0 && s < 1 && t > 0)
              crossings.push_back(t);
          }
        std::sort(crossings.begin(), crossings.end());
        double inside = 0, from = 0;
        for (std::size_t k = 0; k < crossings.size(); ++k)
          if (k % 2 == 0)
            inside += crossings[k] - from;
          else
            from = crossings[k];
        return inside;
      }

    private:
      std::vector<Point<dim>> vertices;
      BoundingBox<dim>        box;
    };

    /** Whether the segments ab and cd cross or touch. */
    template <int dim>
    bool
    segments_meet(const Point<dim> &a,
                  const Point<dim> &b,
                  const Point<dim> &c,
                  const Point<dim> &d)
    {
      const auto side =
        [](const Point<dim> &o, const Point<dim> &p, const Point<dim> &q) {
          const double cross =
            (p[0] - o[0]) * (q[1] - o[1]) - (p[1] - o[1]) * (q[0] - o[0]);
          return (cross > 0) - (cross < 0);
        };
      return side(a, b, c) * side(a, b, d) <= 0 &&
             side(c, d, a) * side(c, d, b) <= 0;
    }

    /** Polygon's 'Vertices': 2D, three or more, edges that do not cross,
     * an area. */
    template <int dim>
    std::vector<Point<dim>>
    read_polygon(SceneReader &reader)
    {
      if (dim != 2)
        reader.fail("Shape",
                    "box, ball, cylinder or mesh in 3D (a polygon "
                    "is 2D)");
      const std::string expected =
        "three or more corners 'x0, y0; x1, y1; ...' of a polygon whose "
        "edges do not cross";
      std::vector<Point<dim>> vertices;
      for (const std::string &corner :
           Utilities::split_string_list(reader.get("Vertices"), ';'))
        {
          const auto xy = Utilities::split_string_list(corner, ',');
          if (xy.size() != 2)
            reader.fail("Vertices", expected);
          Point<dim> v;
          for (unsigned int d = 0; d < 2; ++d)
            {
              char *end = nullptr;
              v[d]      = std::strtod(xy[d].c_str(), &end);
              if (end == xy[d].c_str() || *end != '\0' || !std::isfinite(v[d]))
                reader.fail("Vertices", expected);
            }
          vertices.push_back(v);
        }
      const std::size_t n    = vertices.size();
      double            area = 0;
      for (std::size_t i = 0; i < n; ++i)
        area += vertices[i][0] * vertices[(i + 1) % n][1] -
                vertices[(i + 1) % n][0] * vertices[i][1];
      if (n < 3 || area == 0)
        reader.fail("Vertices", expected);
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 2; j < n; ++j)
          if ((j + 1) % n != i && segments_meet(vertices[i],
                                                vertices[i + 1],
                                                vertices[j],
                                                vertices[(j + 1) % n]))
            reader.fail("Vertices",
                        expected + " (edge " + std::to_string(i + 1) +
                          " meets edge " + std::to_string(j + 1) + ")");
      return vertices;
    }

    /** The cells of a mesh file (any cell shape Gmsh and deal.II agree on). */
    template <int dim>
    class MeshShape : public Shape<dim>
    {
    public:
      explicit MeshShape(std::istream &in)
      {
        GridIn<dim> grid_in;
        grid_in.attach_triangulation(tria);
        grid_in.read_msh(in);
        if (!tria.all_reference_cells_are_hyper_cube())
          throw std::runtime_error("simplex mesh");
        cache = std::make_unique<GridTools::Cache<dim>>(tria, mapping);
        box   = GridTools::compute_bounding_box(tria);
      }
      bool
      contains(const Point<dim> &p) const override
      {
        if (!box.point_inside(p))
          return false;
        try
          {
            const auto found =
              GridTools::find_active_cell_around_point(*cache, p);
            return found.first.state() == IteratorState::valid;
          }
        catch (...)
          {
            return false;
          }
      }
      BoundingBox<dim>
      bounding_box() const override
      {
        return box;
      }

    private:
      Triangulation<dim>                     tria;
      MappingQ1<dim>                         mapping;
      std::unique_ptr<GridTools::Cache<dim>> cache;
      BoundingBox<dim>                       box;
    };

    /** The body's shape: which one, and each shape's dimensions (an entry
     * serves every shape that names it). */
    template <int dim>
    void
    declare_shape_entries(ParameterHandler &prm)
    {
      prm.declare_entry("Shape",
                        "box",
                        Patterns::Selection("box|ball|cylinder|polygon|mesh"),
                        "'box' (Lower corner, Upper corner), 'ball' (a disk in "
                        "2D: Center, Radius), 'cylinder' (3D: Center, Radius, "
                        "Axis, Height), 'polygon' (2D: Vertices), 'mesh' (the "
                        "cells of Mesh file).");
      prm.declare_entry("Lower corner",
                        repeat_value<dim>("0"),
                        Patterns::List(Patterns::Double(), dim, dim),
                        "Box: lower corner.");
      prm.declare_entry("Upper corner",
                        repeat_value<dim>("1"),
                        Patterns::List(Patterns::Double(), dim, dim),
                        "Box: upper corner.");
      prm.declare_entry("Center",
                        repeat_value<dim>("0"),
                        Patterns::List(Patterns::Double(), dim, dim),
                        "Ball, cylinder: centre.");
      prm.declare_entry("Inner radius",
                        "0",
                        Patterns::Double(),
                        "Ball: the radius of a hole at the centre (an annulus "
                        "or hollow sphere); 0: none.");
      prm.declare_entry("Radius",
                        "0.5",
                        Patterns::Double(),
                        "Ball, cylinder: radius.");
      prm.declare_entry("Axis",
                        "z",
                        Patterns::Selection("x|y|z"),
                        "Cylinder: axis direction.");
      prm.declare_entry("Height",
                        "1",
                        Patterns::Double(),
                        "Cylinder: length along the axis.");
      prm.declare_entry(
        "Vertices",
        "",
        Patterns::Anything(),
        "Polygon (2D): its corners in order, 'x0, y0; x1, y1; ...', at least "
        "three, its edges not crossing (a slope: '0, 0; 30, 0; 30, 5; 20, 5; "
        "10, 10; 0, 10').");
      prm.declare_entry(
        "Mesh file",
        "",
        Patterns::FileName(),
        "Mesh: Gmsh .msh file whose cells the body fills (relative to the scene file's folder or absolute).");
    }

    /** What fills the shape: the particles per cell, their material and
     * velocity, and whether they may replace an earlier body's. */
    template <int dim>
    void
    declare_filling_entries(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Particles per cell",
        "2",
        Patterns::Integer(1, 10),
        "Particles per background cell and direction (n: n^dim per cell).");
      prm.declare_entry("Material",
                        "1",
                        Patterns::Integer(1),
                        "Number N of the 'Material N' section.");
      prm.declare_entry("Velocity",
                        repeat_value<dim>("0"),
                        Patterns::List(Patterns::Double(), dim, dim),
                        "Initial velocity (m/s).");
      prm.declare_entry(
        "Allow overlap",
        "false",
        Patterns::Bool(),
        "Where this body overlaps bodies listed before it, its particles "
        "replace theirs (an inclusion, a different material in a region); "
        "otherwise overlapping bodies are refused (they would be filled "
        "twice, at twice the density).");
    }

    /** The stress at t = 0: none, or geostatic with its lateral ratio K0. */
    void
    declare_initial_stress_entries(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Initial stress",
        "none",
        Patterns::Selection("none|geostatic"),
        "The body's stress at t = 0: 'none' (stress-free: under gravity it "
        "falls into its own weight and bounces) or 'geostatic' (at rest under "
        "gravity: sigma = sigma_v (n (x) n + K0 (I - n (x) n)), n the "
        "direction of gravity, sigma_v = -rho g d at depth d below the top of "
        "the body's own bounding box (a polygon's: the material on the line "
        "up from the particle, so under a slope's face the face): the "
        "weight of this body above, not of other bodies resting on it; each particle's F and internal "
        "variables are those of its material at that stress, and 'Density' "
        "is the density at rest). Needs an effect with a uniform force field "
        "(gravity); not with 'MPM/Formulation = total Lagrangian', whose "
        "reference configuration is stress-free.");
      prm.declare_entry(
        "K0",
        "elastic",
        Patterns::Anything(),
        "With 'Initial stress = geostatic': the lateral over the vertical "
        "stress, a number >= 0 (e.g. Jaky's 1 - sin(phi) for a normally "
        "consolidated soil), or 'elastic' for the material's own confined "
        "response (nu / (1 - nu) for isotropic elasticity, 1 for a fluid).");
    }
  } // namespace

  template <int dim>
  void
  Body<dim>::declare_parameters(ParameterHandler &prm)
  {
    declare_shape_entries<dim>(prm);
    declare_filling_entries<dim>(prm);
    declare_initial_stress_entries(prm);
  }

  template <int dim>
  Body<dim>
  Body<dim>::read(SceneReader &reader, const unsigned int n_materials)
  {
    Body<dim>         body;
    const std::string shape = reader.get("Shape");
    if (shape == "box")
      {
        const Point<dim> lower = reader.get_point<dim>("Lower corner");
        const Point<dim> upper = reader.get_point<dim>("Upper corner");
        for (unsigned int d = 0; d < dim; ++d)
          if (!(upper[d] > lower[d]))
            reader.fail("Upper corner",
                        "each coordinate larger than Lower corner's");
        body.shape = std::make_unique<BoxShape<dim>>(lower, upper);
      }
    else if (shape == "ball")
      {
        const double radius = reader.get_positive("Radius");
        const double inner  = reader.get_nonnegative("Inner radius");
        if (!(inner < radius))
          reader.fail("Inner radius", "a number below Radius");
        body.shape =
          std::make_unique<BallShape<dim>>(reader.get_point<dim>("Center"),
                                           radius,
                                           inner);
      }
    else if (shape == "cylinder")
      {
        if (dim != 3)
          reader.fail("Shape", "box, ball or mesh in 2D (a 2D disk is 'ball')");
        const std::string axis = reader.get("Axis");
        body.shape =
          std::make_unique<CylinderShape<dim>>(reader.get_point<dim>("Center"),
                                               reader.get_positive("Radius"),
                                               axis == "x" ?
                                                 0 :
                                                 (axis == "y" ? 1 : 2),
                                               reader.get_positive("Height"));
      }
    else if (shape == "polygon")
      body.shape =
        std::make_unique<PolygonShape<dim>>(read_polygon<dim>(reader));
    else
      {
        std::ifstream in(
          reader.get_file("Mesh file", "a readable Gmsh .msh file"));
        try
          {
            body.shape = std::make_unique<MeshShape<dim>>(in);
          }
        catch (const std::exception &)
          {
            reader.fail("Mesh file",
                        "a Gmsh .msh mesh of quadrilaterals (2D) or hexahedra "
                        "(3D) that deal.II can read");
          }
      }
    body.particles_per_direction = reader.get_integer("Particles per cell");
    const long material          = reader.get_integer("Material");
    if (material < 1 || material > static_cast<long>(n_materials))
      reader.fail("Material",
                  "a material number from 1 to Number of materials (" +
                    std::to_string(n_materials) + ")");
    body.material        = material - 1;
    body.velocity        = reader.get_vector<dim>("Velocity");
    body.allow_overlap   = reader.get_bool("Allow overlap");
    body.geostatic       = reader.get("Initial stress") == "geostatic";
    const std::string K0 = reader.get("K0");
    if (K0 != "elastic")
      {
        char *end = nullptr;
        body.K0   = std::strtod(K0.c_str(), &end);
        if (end == K0.c_str() || *end != '\0' || !std::isfinite(body.K0) ||
            !(body.K0 >= 0))
          reader.fail("K0", "'elastic' or a number >= 0");
      }
    return body;
  }

  template struct Body<2>;
  template struct Body<3>;
} // namespace dealmpm
