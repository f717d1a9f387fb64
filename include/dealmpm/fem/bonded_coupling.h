#pragma once

#include <dealmpm/fem/nodes_on_grid.h>
#include <dealmpm/fem/solid_region.h>
#include <dealmpm/grid/background_grid.h>
#include <dealmpm/grid/nodal_field_set.h>

#include <utility>
#include <vector>

namespace dealmpm
{
  /**
   * The bonded nodes of a solid region (doc/research.md 1.2, the FEMP/AFEMP
   * coupling): they are not integrated by the region; their mass, momentum
   * and force go to the background grid with the linear kernel, and they
   * take the grid's velocity v* back, so that they move with the MPM
   * material they touch and linear momentum is exact (the weights sum to
   * one). The region's and the grid's partitions need not agree
   * (NodesOnGrid).
   */
  template <int dim>
  class BondedCoupling
  {
  public:
    /** The bonded nodes of @p region; with per-body fields their mass
     * goes to body @p body's too. */
    BondedCoupling(SolidRegion<dim> &region, const unsigned int body);

    /** APIC for the bonded nodes, as for the particles (scenes with
     * 'Velocity update = APIC'): each node keeps B = sum N v*_I (x)
     * (x_I - x) from the read-back and gives the grid the affine field
     * v + B D^+ (x_I - x) (D = sum N (x_I - x) (x) (x_I - x), its
     * pseudo-inverse for a node on a grid line), so that the coupled
     * system keeps its angular momentum (Jiang et al. 2015). */
    void
    use_affine();

    /** Send each node's heat capacity C, heat C T and conducted heat Q
     * along (the region carries heat, fem/region_heat.h): the values
     * heat_value() reads after deposit(). */
    void
    carry_heat()
    {
      heat = true;
    }

    /** Value @p k (0: C, 1: C T, 2: Q) of placed point @p p, as
     * deposit() sent it. */
    double
    heat_value(const typename NodesOnGrid<dim>::Placed &p,
               const unsigned int                       k) const
    {
      return points.value(p.point, n_values() - 3 + k);
    }

    /** The indices into region.get_nodes() of this rank's bonded nodes,
     * in the order of NodesOnGrid::sum_to_owners()'s answer. */
    const std::vector<unsigned int> &
    bonded_nodes() const
    {
      return local;
    }

    /** After the grid changed: its cells' search tree. */
    void
    grid_changed(const BackgroundGrid<dim> &grid);

    /** The coupling nodes on the grid (their publication and failures,
     * for the step's reduction). */
    NodesOnGrid<dim> &
    nodes_on_grid()
    {
      return points;
    }

    /** Send the nodes to the ranks that place them and add m, m v and f
     * (the region's forces of this step) to the nodal fields. All ranks
     * call it together; a node in no cell of the grid is a failure of
     * nodes_on_grid(). */
    void
    deposit(const BackgroundGrid<dim> &grid, NodalFieldSet<dim> &fields);

    /** v_i = sum_I N_I(x_i) v*_I into the region's bonded nodes.
     * Collective. */
    void
    read_back(const BackgroundGrid<dim> &grid,
              const NodalFieldSet<dim>  &fields);

    /** The region's bonded nodes on all ranks. */
    std::size_t
    n_nodes() const
    {
      return n_global;
    }

  private:
    /** Values per node: x, m, m v, f, (B), (C, C T, Q). */
    unsigned int
    n_values() const
    {
      return 3 * dim + 1 + (affine ? dim * dim : 0) + (heat ? 3 : 0);
    }

    /** Per bonded node of this rank: x, m, m v, f (and B column by
     * column, and its heat), the values deposit() gathers. */
    std::vector<double>
    node_values() const;

    /** m C = m B D^+ of placed point @p p at @p x (APIC): D from the
     * grid nodes it touches. */
    Tensor<2, dim>
    affine_momentum(const typename NodesOnGrid<dim>::Placed &p,
                    const Point<dim>                        &x,
                    const BackgroundGrid<dim>               &grid) const;

    /** Add the placed points' m, momentum (with its affine part) and f
     * to @p fields. Collective. */
    void
    add_to(NodalFields<dim> &fields, const BackgroundGrid<dim> &grid) const;

    /** The grid's velocity (and B) at the placed points, summed to the
     * points' owners: per node of this rank, v (and B column by
     * column). Point to point. */
    std::vector<double>
    grid_velocities(const BackgroundGrid<dim> &grid,
                    const NodalFields<dim>    &fields);

    SolidRegion<dim> &region;
    unsigned int      body;
    /** Indices into region.get_nodes() of this rank's bonded nodes. */
    std::vector<unsigned int> local;
    std::size_t               n_global = 0;
    NodesOnGrid<dim>          points;
    bool                      affine = false;
    bool                      heat   = false;
  };
} // namespace dealmpm
