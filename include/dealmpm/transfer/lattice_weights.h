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
} // namespace dealmpm
