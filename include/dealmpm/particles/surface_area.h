#pragma once

#include <dealmpm/grid/background_grid.h>
#include <dealmpm/particles/body.h>

namespace dealmpm
{
  /** The surface faces of one particle's sub-cell, lumped. */
  template <int dim>
  struct SurfaceFaces
  {
    /** Sum of the faces' outward area vectors; zero inside the body. */
    Tensor<1, dim> area;
    /** Mean of the faces' centres relative to the particle, weighted by
     * their areas: where a load on them acts. */
    Tensor<1, dim> offset;
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
   */
  template <int dim>
  SurfaceFaces<dim>
  surface_faces(const GridCell<dim> &c,
                const Point<dim>    &xi,
                const unsigned int   n,
                const Shape<dim>    &shape,
                const double         volume);
} // namespace dealmpm
