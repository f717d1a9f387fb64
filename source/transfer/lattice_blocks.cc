#include <dealmpm/transfer/lattice_blocks.h>

namespace dealmpm
{
  namespace
  {
    /** Whether @p c is a box of the edge lengths @p h (to round-off)
     * without constrained vertices. */
    template <int dim>
    bool
    is_plain_box_of(const GridCell<dim> &c, const Tensor<1, dim> &h)
    {
      if (c.first_weight != numbers::invalid_unsigned_int || !c.affine)
        return false;
      for (unsigned int d = 0; d < dim; ++d)
        if (std::abs(c.far_corner[d] - c.origin[d] - h[d]) > 1e-10 * h[d])
          return false;
      return true;
    }

    /** The lattice of owned cell @p i into @p block (nodes no cell of
     * the patch has: invalid), and which of the 3^dim cells of its patch
     * exist; 0 where those that exist are not equal boxes without hanging
     * nodes whose nodes lie on the lattice. */
    template <int dim>
    std::uint32_t
    fill_block(const BackgroundGrid<dim> &grid,
               const unsigned int         i,
               unsigned int              *block)
    {
      constexpr unsigned int n_vertices = GridCell<dim>::n_vertices;
      const GridCell<dim>   &own        = grid.cells[i];
      Tensor<1, dim>         h;
      for (unsigned int d = 0; d < dim; ++d)
        h[d] = own.far_corner[d] - own.origin[d];
      std::uint32_t present   = 0;
      unsigned int  n_present = 0;
      for (unsigned int s = 0; s < Utilities::pow(3, dim); ++s)
        if (const GridCell<dim> *c = grid.side_neighbor(i, s))
          {
            if (!is_plain_box_of(*c, h))
              return 0;
            present |= std::uint32_t(1) << s;
            ++n_present;
          }
      // More neighbours than sides: smaller cells next to the patch.
      if (grid.neighbors_of(i).size() != n_present)
        return 0;
      for (unsigned int n = 0; n < Utilities::pow(4, dim); ++n)
        {
          // Lattice node n_d is vertex n_d - side_d of a cell on side
          // side_d (0 below, 1 level, 2 above) of the own cell, for side_d
          // = n_d - 1 or n_d: the first of those cells that exists.
          block[n] = numbers::invalid_unsigned_int;
          Point<dim> expected;
          for (unsigned int d = 0; d < dim; ++d)
            expected[d] =
              own.origin[d] + (double((n >> (2 * d)) & 3u) - 1.) * h[d];
          for (unsigned int choice = 0; choice < n_vertices; ++choice)
            {
              unsigned int side_index = 0, vertex = 0, stride = 1;
              bool         valid = true;
              for (unsigned int d = 0; d < dim; ++d, stride *= 3)
                {
                  const int n_d  = (n >> (2 * d)) & 3u;
                  const int side = n_d - int((choice >> d) & 1u);
                  valid          = valid && side >= 0 && side <= 2;
                  side_index += std::max(side, 0) * stride;
                  vertex |= (n_d - side == 1 ? 1u : 0u) << d;
                }
              if (!valid || !((present >> side_index) & 1u))
                continue;
              const GridCell<dim> &c = *grid.side_neighbor(i, side_index);
              block[n]               = grid.cell_nodes[c.first_node + vertex];
              if (grid.node_positions[block[n]].distance(expected) >
                  1e-10 * h.norm())
                return 0;
              break;
            }
        }
      return present;
    }

    /** Whether the cells of a patch that exist (@p present, bit sum_d
     * side_d 3^d) are those that exist along each direction alone (a cell
     * is missing only where its row is), and each direction has a
     * neighbour on one side at least. */
    template <int dim>
    bool
    window_fits(const std::uint32_t present)
    {
      constexpr unsigned int level = dim == 2 ? 4 : 13; // sides 1, 1 (, 1)
      bool                   along[dim][3];
      unsigned int           step = 1;
      for (unsigned int d = 0; d < dim; ++d, step *= 3)
        {
          for (unsigned int side = 0; side < 3; ++side)
            along[d][side] = (present >> (level + side * step - step)) & 1u;
          if (!along[d][0] && !along[d][2])
            return false;
        }
      for (unsigned int s = 0; s < Utilities::pow(3, dim); ++s)
        {
          bool         expected = true;
          unsigned int rest     = s;
          for (unsigned int d = 0; d < dim; ++d, rest /= 3)
            expected = expected && along[d][rest % 3];
          if (bool((present >> s) & 1u) != expected)
            return false;
        }
      return true;
    }
  } // namespace

  template <int dim>
  void
  LatticeBlocks<dim>::setup(const BackgroundGrid<dim> &grid)
  {
    present.assign(grid.cells.size(), 0);
    nodes.assign(grid.cells.size() * block_size, 0);
    all_windows_fit = false;
    if (!grid.cartesian || !grid.has_side_neighbors())
      return;
    all_windows_fit = true;
    for (unsigned int i = 0; i < grid.cells.size(); ++i)
      {
        present[i]      = fill_block(grid, i, &nodes[i * block_size]);
        all_windows_fit = all_windows_fit && window_fits<dim>(present[i]);
      }
  }

  template class LatticeBlocks<2>;
  template class LatticeBlocks<3>;
} // namespace dealmpm
