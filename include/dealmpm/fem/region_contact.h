#pragma once

#include <dealmpm/effects/dissipates_at_nodes.h>
#include <dealmpm/fem/nodes_on_grid.h>
#include <dealmpm/fem/solid_region.h>
#include <dealmpm/grid/background_grid.h>
#include <dealmpm/grid/nodal_field_set.h>
#include <dealmpm/grid/nodal_fields.h>
#include <dealmpm/particles/particle_set.h>
#include <dealmpm/transfer/stencil.h>

#include <map>
#include <set>
#include <vector>

namespace dealmpm
{
  /**
   * Frictional contact between an FEM region's surface and the MPM
   * material, through the background grid (doc/research.md 1.3, CFEMP with
   * Bardenhagen's multi-velocity-field contact): the region is a velocity
   * field of its own. Its contact nodes give the grid their mass, their
   * predicted momentum m (v + dt f / m) and their outward normals times
   * area (from the current surface, not from mass gradients). At each
   * node where both the MPM material (the core fields; each body's field
   * in turn when bodies have their own, for contact between them) and
   * the region have mass, the MPM material approaches the surface,
   * (v_mpm - v_fe) . n < 0, and the two meet there within the step (the
   * gap check below), the pair's relative normal velocity is
   * removed at their centre of mass and Coulomb friction takes up to mu
   * times it of the slip; the MPM side's change goes to v* and its
   * increment (so FLIP particles feel it), the region's side's,
   * dv_fe = -m_mpm dv_mpm / m_fe, comes back to its nodes as
   * sum_I N_I(x_i) dv_fe,I, which keeps the total momentum to round-off.
   * Contact nodes outside the grid (where no MPM material can be) are
   * left alone.
   *
   * The gap check: a node shares both bodies' mass from a cell or more
   * before they touch (the MPM material's shape functions reach a cell
   * and, with GIMP, half a particle past it), and correcting there makes
   * a dashpot across the gap that took 84 % of the energy of two elastic
   * bars meeting across two cells. So at each node the gap between the
   * region's surface (its contact nodes' mass-weighted position there)
   * and the nearest particle domain of the MPM field, measured along the
   * surface's normal (Huang et al. 2011's distance check), must close
   * within the step, gap + (v_mpm - v_fe) . n dt < 0; a particle's
   * domain is its initial volume's cube carried by F.
   *
   * The work friction dissipates in a step is listed at the grid's nodes
   * where it acts (DissipatesAtNodes), for heat conduction to heat the
   * MPM material there.
   */
  template <int dim>
  class RegionContact : public DissipatesAtNodes
  {
  public:
    /** The nodes of @p region on the ids of @p friction (id -> mu). */
    RegionContact(SolidRegion<dim>                           &region,
                  const std::map<types::boundary_id, double> &friction);

    /** After the grid changed: the search tree and the nodal vectors. */
    void
    grid_changed(const BackgroundGrid<dim> &grid);

    /** The coupling nodes on the grid (their publication and failures,
     * for the step's reduction). */
    NodesOnGrid<dim> &
    nodes_on_grid()
    {
      return points;
    }

    /** After the grid update (v* on the core fields, with their walls)
     * and the region's forces: correct both sides where the MPM material
     * of @p particles (its weights in @p stencil) meets the region.
     * Collective. */
    void
    apply(const BackgroundGrid<dim> &grid,
          NodalFieldSet<dim>        &fields,
          const ParticleSet<dim>    &particles,
          const Stencil<dim>        &stencil,
          const double               mass_threshold,
          const double               dt);

    /** Work of the contact forces so far on this rank's nodes (the
     * normal parts cancel; what is left is friction's, <= 0). */
    double
    work() const
    {
      return work_done;
    }
    /** Friction's part of it. */
    double
    friction_work() const
    {
      return friction_done;
    }
    /** For a saved run: this rank's work and friction work, which
     * restore_work() sets (on one rank, the sums). */
    void
    restore_work(const double work, const double friction)
    {
      work_done     = work;
      friction_done = friction;
    }

  private:
    /** Values per node for NodesOnGrid: x, m, m v, a n, mu. */
    static constexpr unsigned int n_values = 3 * dim + 2;

    /** Per contact node of this rank: x, m, the predicted momentum
     * m (v + dt f / m) (free nodes; m v else), the area normal of its
     * contact faces and its mu. Collective (the area normals). */
    std::vector<double>
    node_values(const double dt) const;

    /** The region's field on the grid from the placed nodes: mass,
     * mass-weighted mu and position, momentum and area normals; no
     * change yet. Mass, positions and normals also on the ghost nodes. */
    void
    spread_to_grid();

    /** Per MPM field (@p n_fields: each body's when more than one, else
     * the core's), the gap at each node between the region's surface and
     * the nearest particle domain whose shape functions reach the node,
     * along the surface's normal (negative where they overlap; the largest
     * double where no particle reaches a node of the region). Collective. */
    void
    measure_gaps(const BackgroundGrid<dim> &grid,
                 const ParticleSet<dim>    &particles,
                 const Stencil<dim>        &stencil,
                 const unsigned int         n_fields);

    /** Correct each pair of an MPM field of @p set (each body's when
     * bodies have their own, else the core) and the region's field, at
     * every owned grid node where they meet within @p dt. */
    void
    correct_all(NodalFieldSet<dim> &set,
                const double        mass_threshold,
                const double        dt);

    /** The region's nodes take their field's change (summed to the
     * nodes' owners) as velocity corrections for its next advance().
     * Collective. */
    void
    pass_back_changes(const BackgroundGrid<dim> &grid);

    /** The pair (MPM field @p fields, the region's field) at owned node
     * @p i: the correction when the MPM side approaches and closes
     * @p gap (the field's, at i) within @p dt. */
    void
    correct(NodalFields<dim>  &fields,
            const unsigned int i,
            const double       gap,
            const double       mass_threshold,
            const double       dt);

    SolidRegion<dim>            &region;
    std::set<types::boundary_id> ids;
    /** Per local contact node (index into region.get_nodes()): its mu. */
    std::vector<unsigned int> local;
    std::vector<double>       local_mu;
    NodesOnGrid<dim>          points;
    /** The region's field on the grid: mass, momentum, area normal,
     * mass-weighted mu and position; the change of its velocity. */
    NodalVector                  mass, mu;
    std::array<NodalVector, dim> momentum, normal, position, change;
    /** Per MPM field: the gap at each node (measure_gaps()). */
    std::vector<NodalVector> gap;
    double                   work_done = 0, friction_done = 0;
  };
} // namespace dealmpm
