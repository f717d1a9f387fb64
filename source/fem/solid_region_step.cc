#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <dealmpm/base/errors.h>
#include <dealmpm/base/smallest_stretch.h>
#include <dealmpm/fem/solid_region.h>
#include <dealmpm/grid/nodal_exchange.h>

#include <algorithm>
#include <array>
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

  namespace
  {
    /** A cell's signal rate from its points' deformation gradients @p F
     * and internal variables @p internal: the largest wave speed over the
     * smallest node spacing, in the current configuration's scale (the smallest
     * stretch). Gauss-Lobatto points of degree k are closer than h / k near the
     * vertices (the factor for k = 1, 2 is 1). */
    template <int dim>
    double
    cell_signal_rate(const Material<dim>                   &material,
                     const ArrayView<const Tensor<2, dim>> &F,
                     const ArrayView<const double>         &internal,
                     const unsigned int                     degree,
                     const double                           min_vertex_distance)
    {
      double squared = 1;
      for (const Tensor<2, dim> &f : F)
        squared = std::min(squared, smallest_stretch_squared(f));
      return material.max_wave_speed(F, internal) * degree /
             (std::sqrt(squared) * min_vertex_distance);
    }
  } // namespace

  template <int dim>
  void
  SolidRegion<dim>::update_signal_rate()
  {
    const ReferenceData &r = reference;
    signal_rate            = 0;
    for (std::size_t c = 0; c < r.centre.size(); ++c)
      signal_rate = std::max(
        signal_rate,
        cell_signal_rate(
          material,
          ArrayView<const Tensor<2, dim>>(&deformation[c * r.n_q], r.n_q),
          ArrayView<const double>(internal.data() + c * r.n_q * n_internal,
                                  r.n_q * n_internal),
          fe.degree,
          r.min_vertex_distance[c]));
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
  SolidRegion<dim>::report_inverted(const double       J,
                                    const unsigned int cell) const
  {
    std::ostringstream message;
    message << "an FEM region's cell at reference position ("
            << reference.centre[cell] << ") turned inside out (J = " << J
            << "); a smaller time step or a finer mesh there may help";
    throw RunError(message.str());
  }

  template <int dim>
  void
  SolidRegion<dim>::internal_force(const double dt)
  {
    NodalExchange().add(displacement).add(velocity).copy_owners_to_ghosts();
    force                  = 0;
    const ReferenceData &r = reference;
    signal_rate            = 0;
    for (std::size_t c = 0; c < r.centre.size(); ++c)
      signal_rate =
        std::max(signal_rate,
                 fe.degree == 1 ? cell_force<Utilities::pow(2, dim)>(c, dt) :
                                  cell_force<Utilities::pow(3, dim)>(c, dt));
    force.compress(VectorOperation::add);
  }

  namespace
  {
    /** A cell's arrays in the force loop with n nodes and n quadrature
     * points, the last index the one the compiler vectorizes over (the
     * point, or the node). Each sum keeps the order of the plain loops
     * (no fused multiply-adds in this library): the same numbers. */
    template <int dim, int n>
    struct CellArrays
    {
      /** Nodal displacement and velocity [component][node]. */
      double u[dim][n], v[dim][n];
      /** Their reference gradients at the points [a][b][point]. */
      double grad_u[dim][dim][n], grad_v[dim][dim][n];
      /** The first Piola-Kirchhoff stress at the points. */
      double P[dim][dim][n];
      /** Each point's share of each node's force [a][node][point]. */
      double share[dim][n][n];

      /** grad_u, grad_v from the cell's shape gradients grad[b][node][q].
       * The sums in local arrays, which alias nothing: the compiler keeps
       * them in vector registers. */
      void
      interpolate_gradients(const double *__restrict grad)
      {
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            {
              double gu[n] = {}, gv[n] = {};
              for (unsigned int s = 0; s < n; ++s)
                {
                  const double  us = u[a][s], vs = v[a][s];
                  const double *dN = grad + (b * n + s) * n;
                  for (unsigned int q = 0; q < n; ++q)
                    {
                      gu[q] += us * dN[q];
                      gv[q] += vs * dN[q];
                    }
                }
              for (unsigned int q = 0; q < n; ++q)
                {
                  grad_u[a][b][q] = gu[q];
                  grad_v[a][b][q] = gv[q];
                }
            }
      }

      /** share[a][s][q] = (P[a] . grad N_s)(q) JxW(q). */
      void
      make_shares(const double *__restrict grad, const double *__restrict JxW)
      {
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int s = 0; s < n; ++s)
            {
              double dot[n];
              for (unsigned int q = 0; q < n; ++q)
                dot[q] = P[a][0][q] * grad[s * n + q];
              for (unsigned int b = 1; b < dim; ++b)
                for (unsigned int q = 0; q < n; ++q)
                  dot[q] += P[a][b][q] * grad[(b * n + s) * n + q];
              for (unsigned int q = 0; q < n; ++q)
                share[a][s][q] = dot[q] * JxW[q];
            }
      }
    };

    /** F-bar kinematics (de Souza Neto et al. 1996, with the mean of the
     * mean-dilatation method): a cell's points keep their own shape change
     * and share the cell's volume change Jbar = sum w J / sum w (w = JxW,
     * the reference volumes): Fbar = (Jbar / J)^(1/dim) F, and L with its
     * trace replaced by the cell's rate of volume change sum w J tr L /
     * sum w J (the rate of Jbar over Jbar). Returns Jbar. */
    template <int dim, std::size_t n>
    double
    f_bar_kinematics(const double                  *JxW,
                     const std::array<double, n>   &J,
                     std::array<Tensor<2, dim>, n> &F,
                     std::array<Tensor<2, dim>, n> &L)
    {
      double reference_volume = 0, volume = 0, volume_rate = 0;
      for (unsigned int q = 0; q < n; ++q)
        {
          reference_volume += JxW[q];
          volume += JxW[q] * J[q];
          volume_rate += JxW[q] * J[q] * trace(L[q]);
        }
      const double J_bar = volume / reference_volume;
      const double rate  = volume_rate / volume;
      for (unsigned int q = 0; q < n; ++q)
        {
          F[q] *= std::pow(J_bar / J[q], 1. / dim);
          const double shift = (rate - trace(L[q])) / dim;
          for (unsigned int d = 0; d < dim; ++d)
            L[q][d][d] += shift;
        }
      return J_bar;
    }

    /** F-bar's first Piola-Kirchhoff stresses into the cell's @p P from the
     * points' Cauchy stresses @p sigma of Fbar, and Fbar into
     * @p deformation: P = tau' F^-T with tau' = tau - p I + (J / Jbar) pbar
     * I, tau = Jbar sigma the Kirchhoff stress, p = tr tau / dim and pbar =
     * sum w p / sum w. That is the derivative of the strain energy sum w
     * W(Fbar) with respect to the nodal displacements (a point's own
     * pressure with its own J would not be, and an elastic region would not
     * keep its energy). A function of its own: in the force loop, its
     * arrays slowed the loop without F-bar by a third. */
    template <int dim, std::size_t n>
    void
    store_f_bar_stresses(double (&P)[dim][dim][n],
                         const double                        *JxW,
                         const std::array<double, n>         &J,
                         const double                         J_bar,
                         const std::array<Tensor<2, dim>, n> &F,
                         const std::array<Tensor<2, dim>, n> &F_inverse,
                         const SymmetricTensor<2, dim>       *sigma,
                         Tensor<2, dim>                      *deformation)
    {
      double weight = 0, mean_pressure = 0;
      for (unsigned int q = 0; q < n; ++q)
        {
          weight += JxW[q];
          mean_pressure += JxW[q] * J_bar * trace(sigma[q]) / dim;
        }
      mean_pressure /= weight;
      for (unsigned int q = 0; q < n; ++q)
        {
          deformation[q]     = F[q];
          Tensor<2, dim> tau = J_bar * Tensor<2, dim>(sigma[q]);
          const double shift = J[q] / J_bar * mean_pressure - trace(tau) / dim;
          for (unsigned int d = 0; d < dim; ++d)
            tau[d][d] += shift;
          const Tensor<2, dim> P_q = tau * transpose(F_inverse[q]);
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int b = 0; b < dim; ++b)
              P[a][b][q] = P_q[a][b];
        }
    }
  } // namespace

  template <int dim>
  template <int n>
  double
  SolidRegion<dim>::cell_force(const unsigned int c, const double dt)
  {
    const ReferenceData &r    = reference;
    const unsigned int  *dofs = &r.local_dofs[c * r.n_dofs];
    const double        *grad = r.gradients(c);
    CellArrays<dim, n>   cell;
    for (unsigned int s = 0; s < n; ++s)
      for (unsigned int a = 0; a < dim; ++a)
        {
          cell.u[a][s] = displacement.local_element(dofs[s * dim + a]);
          cell.v[a][s] = velocity.local_element(dofs[s * dim + a]);
        }
    cell.interpolate_gradients(grad);
    // Every point's F and L first: the material then updates the cell's
    // points in one call.
    std::array<Tensor<2, dim>, n> F, F_inverse, L;
    std::array<double, n>         J;
    for (unsigned int q = 0; q < n; ++q)
      {
        Tensor<2, dim> grad_v;
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            {
              F[q][a][b]   = cell.grad_u[a][b][q] + (a == b ? 1. : 0.);
              grad_v[a][b] = cell.grad_v[a][b][q];
            }
        J[q] = determinant(F[q]);
        check_orientation(J[q], c);
        F_inverse[q] = invert(F[q]);
        // The half step that made F: F - F_old = dt grad_X v.
        L[q] = grad_v * F_inverse[q];
      }
    const std::size_t k = std::size_t(c) * n; // the cell's first point
    const double J_bar  = f_bar ? f_bar_kinematics<dim>(&r.JxW[k], J, F, L) : 1;
    if (dt > 0)
      material.update_stresses(
        ArrayView<const Tensor<2, dim>>(L.data(), n),
        ArrayView<const Tensor<2, dim>>(F.data(), n),
        dt,
        ArrayView<SymmetricTensor<2, dim>>(&stress[k], n),
        ArrayView<double>(internal.data() + k * n_internal, n * n_internal));
    if (f_bar)
      store_f_bar_stresses<dim>(cell.P,
                                &r.JxW[k],
                                J,
                                J_bar,
                                F, // Fbar: the stress's F
                                F_inverse,
                                &stress[k],
                                &deformation[k]);
    else
      for (unsigned int q = 0; q < n; ++q)
        {
          deformation[k + q] = F[q];
          const Tensor<2, dim> P =
            J[q] * Tensor<2, dim>(stress[k + q]) * transpose(F_inverse[q]);
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int b = 0; b < dim; ++b)
              cell.P[a][b][q] = P[a][b];
        }
    cell.make_shares(grad, &r.JxW[k]);
    for (unsigned int s = 0; s < n; ++s)
      for (unsigned int a = 0; a < dim; ++a)
        {
          double f = 0;
          for (unsigned int q = 0; q < n; ++q)
            f -= cell.share[a][s][q];
          force.local_element(dofs[s * dim + a]) += f;
        }
    // The rate of the F made here is the next step's (the same F as
    // update_signal_rate() would read back).
    return cell_signal_rate(
      material,
      ArrayView<const Tensor<2, dim>>(F.data(), n),
      ArrayView<const double>(internal.data() + k * n_internal, n * n_internal),
      fe.degree,
      r.min_vertex_distance[c]);
  }

  template <int dim>
  void
  SolidRegion<dim>::compute_forces(const double          time,
                                   const double          dt,
                                   const BodyForce<dim> &body_force,
                                   const bool            uniform)
  {
    internal_force(last_dt);
    const double t_mid = time + 0.5 * dt;
    if (!conditions.traction.empty())
      force.add(conditions.traction_curve(t_mid), traction_force);
    const Tensor<1, dim> b_uniform =
      uniform && body_force ?
        body_force(Point<dim>(), Point<dim>(), Tensor<1, dim>(), t_mid) :
        Tensor<1, dim>();
    if (body_force)
      for (const Node &node : nodes)
        {
          const Tensor<1, dim> b = uniform ?
                                     b_uniform :
                                     body_force(node.X,
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
          v = free_velocity(k, dt);
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
        case Kind::shaken:
          v = conditions.base->base_velocity(node.value,
                                             mass.local_element(node.dof[0]),
                                             free_velocity(k, dt),
                                             conditions.base->velocity(
                                               time + 0.5 * dt),
                                             dt);
          break;
      }
    return v;
  }

  template <int dim>
  Tensor<1, dim>
  SolidRegion<dim>::free_velocity(const unsigned int k, const double dt) const
  {
    const Node    &node = nodes[k];
    Tensor<1, dim> v;
    for (unsigned int d = 0; d < dim; ++d)
      v[d] =
        velocity.local_element(node.dof[d]) +
        dt * force.local_element(node.dof[d]) / mass.local_element(node.dof[d]);
    if (!velocity_correction.empty())
      v += velocity_correction[k];
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
        if (node.kind != Kind::free && node.kind != Kind::bonded)
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

#define DEALMPM_INSTANTIATE(dim)                                           \
  template double SolidRegion<dim>::stable_time_step(const double) const;  \
  template void   SolidRegion<dim>::compute_forces(const double,           \
                                                 const double,           \
                                                 const BodyForce<dim> &, \
                                                 const bool);            \
  template void   SolidRegion<dim>::advance(const double, const double);   \
  template void   SolidRegion<dim>::update_signal_rate();                  \
  template void   SolidRegion<dim>::step(const double,                     \
                                       const double,                     \
                                       const BodyForce<dim> &);          \
  template Tensor<2, dim> SolidRegion<dim>::reference_gradient(            \
    const LinearAlgebra::distributed::Vector<double> &,                    \
    const unsigned int,                                                    \
    const Tensor<1, dim> *) const;
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
