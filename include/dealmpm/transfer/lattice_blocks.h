#pragma once

#include <dealmpm/grid/background_grid.h>

#include <cstdint>
#include <vector>

namespace dealmpm
{
  /**
   * Per locally owned cell whose patch (itself and the cells around it, at
   * most 3^dim) is made of equal axis-aligned boxes without hanging nodes:
   * the 4^dim nodes of the patch as a lattice (node (n_0, ..., n_dim-1) at
   * own.vertices[0] + (n - 1) h, at index sum_d n_d 4^d), and which cells
   * of the patch exist (at the grid's edge some do not). A particle domain
   * inside cells that exist then has weights that are products of 1D ones
   * on this lattice, with no search for shared nodes; kernels use it where
   * a cell has one and their general path elsewhere (refined patches,
   * domains reaching past the grid). Built by setup() after the grid
   * changes; grid.find_neighbors() must have run.
   */
  template <int dim>
  class LatticeBlocks
  {
  public:
    static constexpr unsigned int block_size = Utilities::pow(4, dim);

    void
    setup(const BackgroundGrid<dim> &grid);

    /** The lattice of owned cell @p i (its index in grid.cells), or
     * nullptr where the cell has none. */
    const unsigned int *
    of(const unsigned int i) const
    {
      return present.empty() || present[i] == 0 ? nullptr :
                                                  &nodes[i * block_size];
    }

    /** Bit sum_d side_d 3^d is set where the cell on side side_d (0
     * below, 1 level, 2 above) of owned cell @p i exists (with of(i)). */
    std::uint32_t
    cells_present(const unsigned int i) const
    {
      return present[i];
    }

    /** Whether every owned cell has a lattice, the cells its patch lacks
     * are whole rows (so the covered part of a particle domain is a box)
     * and no direction lacks both neighbours (so a three-node window
     * fits): GimpWindows can then be used. On this rank only. */
    bool
    windows_fit() const
    {
      return all_windows_fit;
    }

  private:
    std::vector<std::uint32_t> present;
    bool                       all_windows_fit = false;
    std::vector<unsigned int>  nodes; ///< cells x 4^dim
  };
} // namespace dealmpm
