#pragma once

#include <deal.II/base/bounding_box.h>
#include <deal.II/grid/tria.h>

#include <dealmpm/base/scene_reader.h>
#include <dealmpm/grid/background_grid.h>
#include <dealmpm/particles/particle_set.h>

#include <algorithm>
#include <limits>
#include <memory>
#include <string>

namespace dealmpm
{
  /** The region a body fills. */
  template <int dim>
  class Shape
  {
  public:
    virtual ~Shape() = default;
    virtual bool
    contains(const Point<dim> &p) const = 0;
    virtual BoundingBox<dim>
    bounding_box() const = 0;

    /** The height of the body's material above @p p (inside it), against
     * the unit vector @p down: the overburden of a geostatic start. The
     * depth below the top of the bounding box unless a shape knows better
     * (a polygon measures along the line through @p p). */
    virtual double
    depth(const Point<dim> &p, const Tensor<1, dim> &down) const
    {
      const BoundingBox<dim> box = bounding_box();
      double                 top = -std::numeric_limits<double>::max();
      for (unsigned int v = 0; v < GeometryInfo<dim>::vertices_per_cell; ++v)
        top = std::max(top, -(down * box.vertex(v)));
      return top + down * p;
    }
  };

  /**
   * One body of a scene: a shape filled with a regular pattern of n per
   * direction particles in each background cell it covers, a material and an
   * initial velocity. Particle volume = cell volume / n^dim, mass = density x
   * volume.
   */
  template <int dim>
  struct Body
  {
    std::unique_ptr<Shape<dim>> shape;
    unsigned int                particles_per_direction = 2;
    unsigned int                material                = 0; ///< 0-based
    Tensor<1, dim>              velocity;
    /** Its particles replace those of earlier bodies where they overlap. */
    bool allow_overlap = false;
    /** Start at rest under gravity ('Initial stress = geostatic'). */
    bool geostatic = false;
    /** Lateral over vertical stress; negative: the material's own. */
    double K0 = -1;

    /** Declare the entries of "Body N". */
    static void
    declare_parameters(ParameterHandler &prm);

    /** Read the current "Body N" section; material numbers are 1-based in
     * the scene and must be <= n_materials. */
    static Body<dim>
    read(SceneReader &reader, const unsigned int n_materials);
  };

  /** What generate_particles() did on this rank. */
  struct GeneratedParticles
  {
    std::size_t n_created = 0;
    /** The first earlier body one of the particles lies in (an overlap the
     * body does not allow), or numbers::invalid_unsigned_int. */
    unsigned int overlapped_body = numbers::invalid_unsigned_int;
  };

  /**
   * Fill the locally owned cells with the particles of body number
   * @p body_index of @p bodies, leaving out the places of later bodies that
   * allow overlap (their particles replace these). Ids depend only on the
   * body, the cell's global index and the pattern, so they are the same on
   * any number of ranks; @p id_stride, the most particles per cell of any
   * body of the scene, keeps them apart.
   */
  template <int dim>
  GeneratedParticles
  generate_particles(const std::vector<Body<dim>> &bodies,
                     const unsigned int            body_index,
                     const double                  density,
                     const BackgroundGrid<dim>    &grid,
                     ParticleSet<dim>             &particles,
                     const std::vector<double>    &initial_internal_variables,
                     const unsigned int            id_stride);
} // namespace dealmpm
