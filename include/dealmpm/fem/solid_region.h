#pragma once

#include <deal.II/base/function.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <dealmpm/materials/material.h>

#include <set>
#include <vector>

namespace dealmpm
{
  using namespace dealii;

  /**
   * A finite element solid region (issue 15, first part: the region
   * alone): its own distributed triangulation in the reference
   * configuration, vector FE_Q(k) displacement, Gauss-Lobatto lumped mass
   * and total-Lagrangian explicit dynamics by central differences
   * (leapfrog: v at half steps, u at whole steps). The stress at each
   * quadrature point comes from a dealmpm Material, which keeps its
   * internal variables there: L = grad_X v F^-1 of the half step that
   * made F, so incremental (hypoelastic, plastic) models see the same
   * step as on particles. Boundaries: fixed ids (zero displacement), the
   * others free. RESEARCH.md section 1.4.
   */
  template <int dim>
  class SolidRegion
  {
  public:
    SolidRegion(const MPI_Comm       comm,
                const Material<dim> &material,
                const unsigned int   degree);

    /** After the triangulation is made: DoFs, the lumped mass, the fixed
     * nodes on boundary ids @p fixed, the quadrature-point state. */
    void
    setup(const std::set<types::boundary_id> &fixed);

    /** v = @p velocity at the nodes (at t = 0, the first half step's). */
    void
    set_velocity(const Function<dim> &velocity);

    /** The largest stable step times @p cfl: the smallest node spacing
     * (h / k) over the dilatational wave speed. Collective. */
    double
    stable_time_step(const double cfl) const;

    /** One central-difference step of size dt. Collective. */
    void
    step(const double dt);

    double
    kinetic_energy() const;
    double
    strain_energy() const;
    Tensor<1, dim>
    momentum() const;

    /** Component @p component of the velocity of the node at @p x (within
     * 1e-10 of the region's size), on every rank; NaN if there is none. */
    double
    node_velocity(const Point<dim> &x, const unsigned int component) const;

    MPI_Comm                                  comm;
    parallel::distributed::Triangulation<dim> triangulation;
    FESystem<dim>                             fe;
    DoFHandler<dim>                           dof_handler;
    MappingQ1<dim>                            mapping;
    /** Owned, with the ghosts the cells need. */
    LinearAlgebra::distributed::Vector<double> displacement, velocity, mass;

  private:
    /** f = -int grad N : P (F) with the stress advanced over dt. */
    void
    internal_force(const double dt);

    const Material<dim>                       &material;
    LinearAlgebra::distributed::Vector<double> force;
    std::vector<types::global_dof_index>       fixed_dofs; ///< owned ones
    /** Per owned cell and quadrature point: the stress, F and the
     * material's internal variables. */
    std::vector<SymmetricTensor<2, dim>> stress;
    std::vector<Tensor<2, dim>>          deformation;
    std::vector<double>                  internal;
    unsigned int                         n_internal = 0;
    double last_dt = 0; ///< the step that made the current displacement
  };
} // namespace dealmpm
