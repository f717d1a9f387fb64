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
   * A particle's three nodes along one direction on its cell's lattice
   * block (positions 0 .. 3 of the four: x0 - h, x0, x1, x1 + h): block
   * positions first .. first + 2, with their 1D weights and slopes. Where
   * only two nodes carry weight, the third (@p padded: 0 or 2 in the
   * window, else 3) is a node of the block inside the grid with weight and
   * slope zero, so that the sweeps' loops along x have fixed counts
   * (WindowWeights: the quadratic B-spline and uGIMP). Along y and z the
   * sweeps visit the first @p rows nodes only: 3, or 2 where the third
   * carries no weight (uGIMP's domains inside their cell along that
   * direction; then the third may not exist).
   */
  struct NodeWindow
  {
    double       value[3];
    double       slope[3];
    unsigned int first;
    unsigned int padded;
    unsigned int rows;
  };
} // namespace dealmpm
