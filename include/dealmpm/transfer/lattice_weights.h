#pragma once

namespace dealmpm
{
  /** One direction of a particle's weights on its cell's lattice (nodes
   * x0 - h, x0, x1, x1 + h of the cell [x0, x1]): each node's 1D weight
   * (value) and its derivative along x (slope); nodes first .. first +
   * count - 1 carry them, the others are unset. */
  struct LatticeWeights1D
  {
    double       value[4];
    double       slope[4];
    unsigned int first;
    unsigned int count;
  };

  /**
   * A particle's nodes along one direction on its cell's lattice block
   * (positions 0 .. 3 of the four: x0 - h, x0, x1, x1 + h): block positions
   * first .. first + rows - 1, with their 1D weights and slopes (the
   * quadratic B-spline and GIMP, WindowWeights). @p rows is 3, or 2 where
   * a uGIMP or cpGIMP domain stays in its cell along that direction (then
   * the third entries are unset and the node beyond may not exist); the
   * sweeps visit that many nodes along every direction, with a count
   * fixed at compile time along x. The B-spline keeps three, one of them
   * padding next to a boundary (@p padded: 0 or 2 in the window, else 3:
   * a node of the block inside the grid with weight and slope zero).
   */
  struct NodeWindow
  {
    double       value[3];
    double       slope[3];
    unsigned int first;
    unsigned int padded; ///< the B-spline's only
    unsigned int rows;
  };
} // namespace dealmpm
