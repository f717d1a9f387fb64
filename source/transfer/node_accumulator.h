#pragma once

#include <dealmpm/transfer/particle_weights.h>
#include <dealmpm/transfer/stencil.h>

#include <algorithm>
#include <vector>

#include "stencil_entries.h"

namespace dealmpm
{
  /**
   * One particle's weights while a kernel gathers them from several cells:
   * entries for the same node are merged, hanging nodes are resolved through
   * each cell's effective nodes. Private to the stencil kernels.
   */
  template <int dim>
  struct NodeAccumulator
  {
    static constexpr unsigned int n_vertices = GridCell<dim>::n_vertices;

    std::vector<unsigned int>   nodes;
    std::vector<double>         N;
    std::vector<Tensor<1, dim>> grad_N;

    void
    clear()
    {
      nodes.clear();
      N.clear();
      grad_N.clear();
    }

    void
    add(const unsigned int node, const double value, const Tensor<1, dim> &g)
    {
      const auto it = std::find(nodes.begin(), nodes.end(), node);
      if (it == nodes.end())
        {
          nodes.push_back(node);
          N.push_back(value);
          grad_N.push_back(g);
        }
      else
        {
          N[it - nodes.begin()] += value;
          grad_N[it - nodes.begin()] += g;
        }
    }

    /** Add per-vertex contributions of cell @p c onto its effective nodes. */
    void
    add_cell(const BackgroundGrid<dim> &grid,
             const GridCell<dim>       &c,
             const double              *vertex_value,
             const Tensor<1, dim>      *vertex_gradient)
    {
      const unsigned int *cell_nodes = &grid.cell_nodes[c.first_node];
      if (c.first_weight == numbers::invalid_unsigned_int)
        {
          if (nodes.empty()) // the first cell: nothing to merge with
            {
              nodes.assign(cell_nodes, cell_nodes + n_vertices);
              N.assign(vertex_value, vertex_value + n_vertices);
              grad_N.assign(vertex_gradient, vertex_gradient + n_vertices);
              return;
            }
          for (unsigned int v = 0; v < n_vertices; ++v)
            add(cell_nodes[v], vertex_value[v], vertex_gradient[v]);
          return;
        }
      const double *W = &grid.cell_node_weights[c.first_weight];
      for (unsigned int n = 0; n < c.n_nodes; ++n)
        {
          double         value = 0;
          Tensor<1, dim> g;
          for (unsigned int v = 0; v < n_vertices; ++v)
            if (W[n * n_vertices + v] != 0.)
              {
                value += W[n * n_vertices + v] * vertex_value[v];
                g += W[n * n_vertices + v] * vertex_gradient[v];
              }
          add(cell_nodes[n], value, g);
        }
    }

    /** Append the gathered entries, times @p scale, as particle k's. */
    void
    append_to(Stencil<dim>     &stencil,
              const std::size_t k,
              std::size_t      &e,
              const double      scale = 1.) const
    {
      stencil.begin[k] = e;
      make_room_for_entries(stencil, e + nodes.size());
      for (unsigned int n = 0; n < nodes.size(); ++n, ++e)
        {
          stencil.node[e]   = nodes[n];
          stencil.N[e]      = N[n] * scale;
          stencil.grad_N[e] = grad_N[n] * scale;
        }
    }
  };
} // namespace dealmpm
