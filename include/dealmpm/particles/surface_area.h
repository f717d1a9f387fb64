#pragma once

#include <dealmpm/grid/background_grid.h>
#include <dealmpm/particles/body.h>

#include <array>

namespace dealmpm
{
  /** The loaded surface faces of one particle's sub-cell, lumped. */
  template <int dim>
  struct SurfaceFaces
  {
    /** Sum of the loaded faces' outward area vectors (each projected on
     * the face normal when one is given): what a pressure pushes on. Zero
     * inside the body. */
    Tensor<1, dim> area;
    /** Sum of their areas: what a traction acts on. */
    double size = 0;
    /** Mean of their centres relative to the particle, weighted by their
     * areas: where a load on them acts. */
    Tensor<1, dim> offset;
    /** The area of all the particle's surface faces by the direction they
     * face in the cell's frame: -e_0, +e_0, -e_1, ... */
    std::array<double, 2 * dim> by_direction{};
  };

  /**
   * The surface faces of a particle at unit-cell point @p xi of cell @p c,
   * one of n per direction, which owns the sub-cell around it (volume
   * @p volume): each face of that sub-cell whose neighbour sub-cell centre
   * (xi +- e_d / n) lies outside @p shape is on the body's surface, with
   * area vector +- volume n J^-T e_d. Summed over a body's particles the
   * faces form a closed staircase, so a uniform pressure on them is in
   * equilibrium, and their projections on any direction are exact for a
   * body aligned with the grid.
   *
   * A zero @p face_normal loads them all. Otherwise only those whose
   * outward normal has a positive component along it, each counted by its
   * projection on it: a flat face of any orientation then gets its own
   * area, also where its staircase turns a corner, and no side face of a
   * corner particle is loaded.
   */
  template <int dim>
  SurfaceFaces<dim>
  surface_faces(const GridCell<dim>  &c,
                const Point<dim>     &xi,
                const unsigned int    n,
                const Shape<dim>     &shape,
                const double          volume,
                const Tensor<1, dim> &face_normal);
} // namespace dealmpm
