#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <dealmpm/base/errors.h>
#include <dealmpm/base/smallest_stretch.h>
#include <dealmpm/fem/solid_region.h>
#include <dealmpm/grid/nodal_exchange.h>

#include <algorithm>
#include <limits>
#include <sstream>

namespace dealmpm
{
  template <int dim>
  double
  SolidRegion<dim>::stable_time_step(const double cfl) const
  {
    const double rate = Utilities::MPI::max(local_signal_rate(), comm);
    return rate > 0 ? cfl / rate : std::numeric_limits<double>::max();
  }

  template <int dim>
  double
  SolidRegion<dim>::local_signal_rate() const
  {
    double             rate = 0;
    const unsigned int n_q  = QGauss<dim>(fe.degree + 1).size();
    std::size_t        k    = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          double c = 0;
          for (unsigned int q = 0; q < n_q; ++q, ++k)
            c = std::max(c, material.wave_speed(deformation[k]));
          // The smallest node spacing of the cell (Gauss-Lobatto points of
          // degree k are closer than h / k near the vertices; the factor
          // for k = 1, 2 is 1), in the current configuration's scale.
          double stretch = 1;
          for (unsigned int q = 0; q < n_q; ++q)
            stretch =
              std::min(stretch, smallest_stretch(deformation[k - n_q + q]));
          rate = std::max(rate,
                          c * fe.degree /
                            (stretch * cell->minimum_vertex_distance()));
        }
    return rate;
  }

  template <int dim>
  Tensor<2, dim>
  SolidRegion<dim>::reference_gradient(
    const LinearAlgebra::distributed::Vector<double> &w,
    const unsigned int                                cell,
    const Tensor<1, dim>                             *grad) const
  {
    Tensor<2, dim>      g;
    const unsigned int *dofs = &reference.local_dofs[cell * reference.n_dofs];
    for (unsigned int i = 0; i < reference.n_dofs; ++i)
      {
        const double          value = w.local_element(dofs[i]);
        const Tensor<1, dim> &dN    = grad[reference.scalar[i]];
        const unsigned int    a     = reference.component[i];
        for (unsigned int b = 0; b < dim; ++b)
          g[a][b] += value * dN[b];
      }
    return g;
  }

  template <int dim>
  void
  SolidRegion<dim>::check_orientation(const double       J,
                                      const unsigned int cell) const
  {
    if (!(J > 0))
      {
        std::ostringstream message;
        message << "an FEM region's cell at reference position ("
                << reference.centre[cell] << ") turned inside out (J = " << J
                << "); a smaller time step or a finer mesh there "
                   "may help";
        throw RunError(message.str());
      }
  }

  template <int dim>
  void
  SolidRegion<dim>::internal_force(const double dt)
  {
    NodalExchange().add(displacement).add(velocity).copy_owners_to_ghosts();
    force                  = 0;
    const ReferenceData &r = reference;
    std::vector<double>  local(r.n_dofs);
    const std::size_t    n_cells = r.centre.size();
    for (std::size_t c = 0, k = 0; c < n_cells; ++c)
      {
        std::fill(local.begin(), local.end(), 0.);
        for (unsigned int q = 0; q < r.n_q; ++q, ++k)
          {
            const Tensor<1, dim> *grad = &r.grad[k * r.n_scalar];
            const Tensor<2, dim>  F    = unit_symmetric_tensor<dim>() +
                                     reference_gradient(displacement, c, grad);
            const double J = determinant(F);
            check_orientation(J, c);
            // The half step that made F: F - F_old = dt grad_X v.
            if (dt > 0)
              material.update_stress(
                reference_gradient(velocity, c, grad) * invert(F),
                F,
                dt,
                stress[k],
                ArrayView<double>(internal.data() + k * n_internal,
                                  n_internal));
            deformation[k] = F;
            const Tensor<2, dim> P =
              J * Tensor<2, dim>(stress[k]) * transpose(invert(F));
            for (unsigned int i = 0; i < r.n_dofs; ++i)
              local[i] -= (P[r.component[i]] * grad[r.scalar[i]]) * r.JxW[k];
          }
        const unsigned int *dofs = &r.local_dofs[c * r.n_dofs];
        for (unsigned int i = 0; i < r.n_dofs; ++i)
          force.local_element(dofs[i]) += local[i];
      }
    force.compress(VectorOperation::add);
  }

  template <int dim>
  void
  SolidRegion<dim>::compute_forces(const double          time,
                                   const double          dt,
                                   const BodyForce<dim> &body_force)
  {
    internal_force(last_dt);
    const double t_mid = time + 0.5 * dt;
    if (!conditions.traction.empty())
      force.add(conditions.traction_curve(t_mid), traction_force);
    if (body_force)
      for (const Node &node : nodes)
        {
          const Tensor<1, dim> b = body_force(node.X,
                                              position(node),
                                              node_vector(velocity, node),
                                              t_mid);
          const double         m = mass.local_element(node.dof[0]);
          for (unsigned int d = 0; d < dim; ++d)
            force.local_element(node.dof[d]) += m * b[d];
        }
  }

  template <int dim>
  Tensor<1, dim>
  SolidRegion<dim>::new_velocity(const unsigned int k,
                                 const double       time,
                                 const double       dt) const
  {
    using Kind          = typename Node::Kind;
    const Node    &node = nodes[k];
    Tensor<1, dim> v;
    switch (node.kind)
      {
        case Kind::free:
          for (unsigned int d = 0; d < dim; ++d)
            v[d] = velocity.local_element(node.dof[d]) +
                   dt * force.local_element(node.dof[d]) /
                     mass.local_element(node.dof[d]);
          if (!velocity_correction.empty())
            v += velocity_correction[k];
          break;
        case Kind::fixed:
          break;
        case Kind::displacement:
          v = node.value *
              (conditions.displacement_curve(time + dt) -
               conditions.displacement_curve(time)) /
              dt;
          break;
        case Kind::velocity:
          v = node.value * conditions.velocity_curve(time + 0.5 * dt);
          break;
        case Kind::bonded:
          v = node_vector(velocity, node);
          break;
      }
    return v;
  }

  template <int dim>
  void
  SolidRegion<dim>::add_support_reaction(const Node           &node,
                                         const Tensor<1, dim> &v,
                                         const double          dt)
  {
    // The work of what holds a prescribed node: the force beyond what
    // the node's own inertia takes, times its path.
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double m   = mass.local_element(node.dof[d]);
        const double v0  = velocity.local_element(node.dof[d]);
        const double f   = force.local_element(node.dof[d]);
        const double Rxn = m * (v[d] - v0) / dt - f;
        work += Rxn * dt * 0.5 * (v[d] + v0);
        support_reaction[d] += Rxn;
        row_impulse[d] += dt * Rxn;
      }
  }

  template <int dim>
  void
  SolidRegion<dim>::add_traction_work(const double time, const double dt)
  {
    // f_t . v over the step.
    const double scale = conditions.traction_curve(time + 0.5 * dt);
    for (unsigned int i = 0; i < velocity.locally_owned_size(); ++i)
      work += dt * scale * traction_force.local_element(i) *
              velocity.local_element(i);
  }

  template <int dim>
  void
  SolidRegion<dim>::advance(const double time, const double dt)
  {
    using Kind = typename Node::Kind;
    velocity.zero_out_ghost_values();
    displacement.zero_out_ghost_values();
    support_reaction = Tensor<1, dim>();
    for (unsigned int k = 0; k < nodes.size(); ++k)
      {
        const Node          &node = nodes[k];
        const Tensor<1, dim> v    = new_velocity(k, time, dt);
        if (node.kind == Kind::fixed || node.kind == Kind::displacement ||
            node.kind == Kind::velocity)
          add_support_reaction(node, v, dt);
        for (unsigned int d = 0; d < dim; ++d)
          {
            velocity.local_element(node.dof[d]) = v[d];
            displacement.local_element(node.dof[d]) += dt * v[d];
          }
      }
    velocity_correction.clear();
    row_time += dt;
    if (!conditions.traction.empty())
      add_traction_work(time, dt);
    last_dt = dt;
  }

  template <int dim>
  void
  SolidRegion<dim>::step(const double          dt,
                         const double          time,
                         const BodyForce<dim> &body_force)
  {
    compute_forces(time, dt, body_force);
    advance(time, dt);
  }

#define DEALMPM_INSTANTIATE(dim)                                            \
  template double SolidRegion<dim>::stable_time_step(const double) const;   \
  template double SolidRegion<dim>::local_signal_rate() const;              \
  template void   SolidRegion<dim>::compute_forces(const double,            \
                                                 const double,            \
                                                 const BodyForce<dim> &); \
  template void   SolidRegion<dim>::advance(const double, const double);    \
  template void   SolidRegion<dim>::step(const double,                      \
                                       const double,                      \
                                       const BodyForce<dim> &);           \
  template Tensor<2, dim> SolidRegion<dim>::reference_gradient(             \
    const LinearAlgebra::distributed::Vector<double> &,                     \
    const unsigned int,                                                     \
    const Tensor<1, dim> *) const;
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
