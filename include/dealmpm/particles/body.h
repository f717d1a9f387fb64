#pragma once

#include <deal.II/base/bounding_box.h>
#include <deal.II/grid/tria.h>

#include <dealmpm/core/scene_reader.h>
#include <dealmpm/grid/background_grid.h>
#include <dealmpm/particles/particle_set.h>

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

    /** Declare the entries of "Body N". */
    static void
    declare_parameters(ParameterHandler &prm);

    /** Read the current "Body N" section; material numbers are 1-based in
     * the scene and must be <= n_materials. */
    static Body<dim>
    read(SceneReader &reader, const unsigned int n_materials);
  };

  /**
   * Fill the locally owned cells with the particles of body number
   * @p body_index. Ids depend only on the body, the cell's global index and
   * the pattern, so they are the same on any number of ranks;
   * @p id_stride, the most particles per cell of any body of the scene,
   * keeps them apart. Returns the number of particles created on this rank.
   */
  template <int dim>
  std::size_t
  generate_particles(const Body<dim>           &body,
                     const unsigned int         body_index,
                     const double               density,
                     const BackgroundGrid<dim> &grid,
                     ParticleSet<dim>          &particles,
                     const std::vector<double> &initial_internal_variables,
                     const unsigned int         id_stride);
} // namespace dealmpm
