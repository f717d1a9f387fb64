#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <dealmpm/base/smallest_stretch.h>
#include <dealmpm/fem/solid_region.h>

#include <algorithm>
#include <limits>

namespace dealmpm
{
  template <int dim>
  void
  SolidRegion<dim>::use_heat(const HeatSettings  &settings,
                             const Function<dim> &initial)
  {
    heat.settings = settings;
    heat.rho_c    = material.density * settings.specific_heat;
    temperature.reinit(mass.get_partitioner());
    conducted.reinit(mass.get_partitioner());
    // The held nodes: on a face with a fixed id (the lowest id's value
    // where two meet); every cell at an owned node is owned or a ghost.
    std::map<types::global_dof_index, double> held;
    const IndexSet owned = dof_handler.locally_owned_dofs();
    std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        for (const unsigned int f : cell->face_indices())
          {
            const auto face = cell->face(f);
            if (!face->at_boundary() ||
                settings.fixed.count(face->boundary_id()) == 0)
              continue;
            const double T = settings.fixed.at(face->boundary_id());
            face->get_dof_indices(face_dofs);
            for (unsigned int j = 0; j < face_dofs.size(); ++j)
              if (fe.face_system_to_component_index(j).first == 0 &&
                  owned.is_element(face_dofs[j]))
                held.emplace(face_dofs[j], T); // the first id met stays
          }
    heat.fixed_nodes.clear();
    heat.debt.assign(nodes.size(), 0.);
    for (unsigned int k = 0; k < nodes.size(); ++k)
      {
        const auto found = held.find(owned.nth_index_in_set(nodes[k].dof[0]));
        // Held nodes too: they take their temperature in the first step.
        const double T = initial.value(nodes[k].X);
        if (found != held.end())
          heat.fixed_nodes.emplace_back(k, found->second);
        for (unsigned int d = 0; d < dim; ++d)
          temperature.local_element(nodes[k].dof[d]) = T;
      }
    temperature.update_ghost_values();
    // The shape functions at the force loop's points (make_reference_data).
    const QGauss<dim>  gauss(fe.degree + 1);
    const unsigned int n = reference.n_scalar;
    heat.shape_values.resize(n * reference.n_q);
    for (unsigned int s = 0; s < n; ++s)
      for (unsigned int q = 0; q < reference.n_q; ++q)
        heat.shape_values[s * reference.n_q + q] =
          fe.shape_value(reference.fe_index[s * dim], gauss.point(q));
    heat.points.clear();
    if (settings.source != nullptr)
      {
        // The owned cells in make_reference_data()'s order.
        FEValues<dim> values(mapping, fe, gauss, update_quadrature_points);
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              values.reinit(cell);
              for (unsigned int q = 0; q < reference.n_q; ++q)
                heat.points.push_back(values.quadrature_point(q));
            }
      }
    mark_work_heated();
    set_model_temperatures();
  }

  template <int dim>
  double
  SolidRegion<dim>::value_at_point(
    const LinearAlgebra::distributed::Vector<double> &v,
    const std::size_t                                 c,
    const unsigned int                                q) const
  {
    const ReferenceData &r     = reference;
    double               value = 0;
    for (unsigned int s = 0; s < r.n_scalar; ++s)
      value += heat.shape_values[s * r.n_q + q] *
               v.local_element(r.local_dofs[c * r.n_dofs + s * dim]);
    return value;
  }

  template <int dim>
  void
  SolidRegion<dim>::set_model_temperatures()
  {
    if (heat.settings.model_temperature < 0)
      return;
    for (std::size_t c = 0; c < reference.centre.size(); ++c)
      for (unsigned int q = 0; q < reference.n_q; ++q)
        internal[(c * reference.n_q + q) * n_internal +
                 heat.settings.model_temperature] =
          value_at_point(temperature, c, q);
  }

  template <int dim>
  std::vector<double>
  SolidRegion<dim>::face_shares(
    const std::map<types::boundary_id, double> &per_id) const
  {
    LinearAlgebra::distributed::Vector<double> a(conducted);
    a = 0;
    displacement.update_ghost_values();
    const ReferenceData &r = reference;
    for (std::size_t face = 0; face < r.face_cell.size(); ++face)
      if (const auto found = per_id.find(r.face_id[face]);
          found != per_id.end())
        {
          const unsigned int c = r.face_cell[face];
          for (unsigned int q = 0; q < r.n_face_q; ++q)
            {
              const std::size_t k  = face * r.n_face_q + q;
              const double      da = current_normal_area(face, q).norm();
              for (unsigned int s = 0; s < r.n_scalar; ++s)
                a.local_element(r.local_dofs[c * r.n_dofs + s * dim]) +=
                  found->second * r.face_value[k * r.n_scalar + s] * da;
            }
        }
    a.compress(VectorOperation::add);
    std::vector<double> shares(nodes.size());
    for (unsigned int k = 0; k < nodes.size(); ++k)
      shares[k] = a.local_element(nodes[k].dof[0]);
    return shares;
  }

  template <int dim>
  void
  SolidRegion<dim>::add_source(const double time, const double dt)
  {
    Function<dim> *source = heat.settings.source;
    if (source == nullptr)
      return;
    const ReferenceData &r = reference;
    const unsigned int   n = r.n_scalar;
    source->set_time(time);
    for (std::size_t c = 0; c < r.centre.size(); ++c)
      for (unsigned int q = 0; q < r.n_q; ++q)
        {
          const std::size_t   k    = c * r.n_q + q;
          const unsigned int *dofs = &r.local_dofs[c * r.n_dofs];
          // The point's current position and volume.
          Point<dim> x = heat.points[k];
          for (unsigned int s = 0; s < n; ++s)
            for (unsigned int d = 0; d < dim; ++d)
              x[d] += heat.shape_values[s * r.n_q + q] *
                      displacement.local_element(dofs[s * dim + d]);
          const double power =
            source->value(x) * determinant(deformation[k]) * r.JxW[k];
          heat.step.generated += dt * power;
          for (unsigned int s = 0; s < n; ++s)
            conducted.local_element(dofs[s * dim]) +=
              heat.shape_values[s * r.n_q + q] * power;
        }
  }

  template <int dim>
  void
  SolidRegion<dim>::add_boundary_heat(const double time, const double dt)
  {
    if (!heat.settings.fluxes.empty())
      {
        const std::vector<double> qA = face_shares(heat.settings.fluxes);
        const double factor = (*heat.settings.flux_curve)(time + 0.5 * dt);
        for (unsigned int k = 0; k < nodes.size(); ++k)
          {
            add_conducted_heat(k, factor * qA[k]);
            heat.step.given += dt * factor * qA[k];
          }
      }
    if (heat.settings.convection.empty())
      return;
    heat.convective = face_shares(heat.settings.convection);
    for (unsigned int k = 0; k < nodes.size(); ++k)
      if (nodes[k].kind == Node::Kind::bonded)
        {
          const double power =
            heat.convective[k] * (heat.ambient - heat.at_start[k]);
          add_conducted_heat(k, power);
          heat.step.given += dt * power;
        }
  }

  template <int dim>
  void
  SolidRegion<dim>::mark_work_heated()
  {
    if (heat.settings.working == nullptr)
      return;
    heat.heated_work.resize(deformation.size());
    for (std::size_t k = 0; k < deformation.size(); ++k)
      heat.heated_work[k] = heat.settings.working->dissipated_energy_density(
        ArrayView<const double>(internal.data() + k * n_internal, n_internal));
  }

  template <int dim>
  void
  SolidRegion<dim>::cell_conduction(const unsigned int c)
  {
    const ReferenceData &r    = reference;
    const unsigned int   n    = r.n_scalar;
    const unsigned int  *dofs = &r.local_dofs[c * r.n_dofs];
    const double        *grad = r.gradients(c);
    const double         k    = heat.settings.conductivity;
    for (unsigned int q = 0; q < r.n_q; ++q)
      {
        const auto dN = [&](const unsigned int s) {
          Tensor<1, dim> g;
          for (unsigned int b = 0; b < dim; ++b)
            g[b] = grad[(b * n + s) * r.n_q + q];
          return g;
        };
        Tensor<1, dim> grad_T;
        for (unsigned int s = 0; s < n; ++s)
          grad_T += temperature.local_element(dofs[s * dim]) * dN(s);
        // The current configuration's flux pulled back: k J C^-1 grad_X T.
        const Tensor<2, dim> &F     = deformation[c * r.n_q + q];
        const Tensor<2, dim>  F_inv = invert(F);
        const Tensor<1, dim>  flux =
          (k * determinant(F) * r.JxW[c * r.n_q + q]) *
          (F_inv * (grad_T * F_inv));
        for (unsigned int s = 0; s < n; ++s)
          conducted.local_element(dofs[s * dim]) -= flux * dN(s);
      }
  }

  template <int dim>
  void
  SolidRegion<dim>::conduct(const double time, const double dt)
  {
    heat.at_start.resize(nodes.size());
    for (unsigned int k = 0; k < nodes.size(); ++k)
      heat.at_start[k] = temperature_of(nodes[k]);
    heat.step         = HeatStep();
    const auto factor = [&](const LoadCurve *curve) {
      return curve == nullptr ? 1. : (*curve)(time + dt);
    };
    heat.held_factor = factor(heat.settings.temperature_curve);
    heat.ambient = heat.settings.ambient * factor(heat.settings.ambient_curve);
    conducted    = 0;
    for (std::size_t c = 0; c < reference.centre.size(); ++c)
      cell_conduction(c);
    add_source(time, dt);
    conducted.compress(VectorOperation::add);
    add_boundary_heat(time, dt);
  }

  template <int dim>
  typename SolidRegion<dim>::HeatStep
  SolidRegion<dim>::advance_temperature(const double dt)
  {
    // A held node gives what keeps it at its temperature (it starts at
    // the initial one: the first step's jump expands the material
    // there): C (T_held - T) and, unless bonded (its Q went to the grid,
    // whose increment is in T), -dt Q.
    std::vector<bool> held(nodes.size(), false);
    HeatStep          step = heat.step;
    for (const auto &[k, T_held] : heat.fixed_nodes)
      {
        const double T = heat.held_factor * T_held;
        held[k]        = true;
        step.given +=
          heat_capacity_of(nodes[k]) * (T - temperature_of(nodes[k]));
        if (nodes[k].kind != Node::Kind::bonded)
          step.given -= dt * conducted_heat_of(nodes[k]);
        for (unsigned int d = 0; d < dim; ++d)
          temperature.local_element(nodes[k].dof[d]) = T;
      }
    for (unsigned int k = 0; k < nodes.size(); ++k)
      if (!held[k] && nodes[k].kind != Node::Kind::bonded)
        {
          // Convection at the new temperature (backward Euler): stable
          // however light the node.
          const double hA = heat.convective.empty() ? 0. : heat.convective[k];
          const double to_ambient = heat.ambient - temperature_of(nodes[k]);
          const double dT         = dt *
                            (conducted_heat_of(nodes[k]) + hA * to_ambient) /
                            (heat_capacity_of(nodes[k]) + dt * hA);
          step.given += dt * hA * (to_ambient - dT);
          for (unsigned int d = 0; d < dim; ++d)
            temperature.local_element(nodes[k].dof[d]) += dT;
        }
    if (heat.settings.working != nullptr && heat.settings.taylor_quinney > 0)
      {
        // 'conducted' is free now: the work's heat per node.
        step.generated = heat_by_work();
        for (unsigned int k = 0; k < nodes.size(); ++k)
          {
            const double added = conducted_heat_of(nodes[k]);
            if (held[k])
              step.given -= added; // the held boundary takes it away
            else
              for (unsigned int d = 0; d < dim; ++d)
                temperature.local_element(nodes[k].dof[d]) +=
                  added / heat_capacity_of(nodes[k]);
          }
      }
    if (heat.settings.stretch_per_kelvin != 0)
      {
        for (unsigned int k = 0; k < nodes.size(); ++k)
          conducted.local_element(nodes[k].dof[0]) =
            temperature_of(nodes[k]) - heat.at_start[k];
        conducted.update_ghost_values();
        expand(conducted);
      }
    temperature.update_ghost_values();
    set_model_temperatures();
    return step;
  }

  template <int dim>
  double
  SolidRegion<dim>::heat_by_work()
  {
    const ReferenceData &r         = reference;
    const unsigned int   n         = r.n_scalar;
    double               generated = 0;
    conducted                      = 0;
    for (std::size_t c = 0; c < r.centre.size(); ++c)
      for (unsigned int q = 0; q < r.n_q; ++q)
        {
          const std::size_t k = c * r.n_q + q;
          const double work = heat.settings.working->dissipated_energy_density(
            ArrayView<const double>(internal.data() + k * n_internal,
                                    n_internal));
          const double heat_q = heat.settings.taylor_quinney *
                                (work - heat.heated_work[k]) * r.JxW[k];
          heat.heated_work[k] = work;
          generated += heat_q;
          for (unsigned int s = 0; s < n; ++s)
            conducted.local_element(r.local_dofs[c * r.n_dofs + s * dim]) +=
              heat.shape_values[s * r.n_q + q] * heat_q;
        }
    conducted.compress(VectorOperation::add);
    return generated;
  }

  template <int dim>
  void
  SolidRegion<dim>::expand(
    const LinearAlgebra::distributed::Vector<double> &increment)
  {
    for (std::size_t c = 0; c < reference.centre.size(); ++c)
      for (unsigned int q = 0; q < reference.n_q; ++q)
        internal[(c * reference.n_q + q) * n_internal +
                 heat.settings.stretch_index] +=
          heat.settings.stretch_per_kelvin * value_at_point(increment, c, q);
  }

  template <int dim>
  void
  SolidRegion<dim>::add_to_temperatures(
    const std::vector<unsigned int> &indices,
    const std::vector<double>       &change)
  {
    for (std::size_t j = 0; j < indices.size(); ++j)
      for (unsigned int d = 0; d < dim; ++d)
        temperature.local_element(nodes[indices[j]].dof[d]) += change[j];
    // advance_temperature() updates the ghosts.
  }

  template <int dim>
  double
  SolidRegion<dim>::stored_heat() const
  {
    double sum = 0;
    for (const Node &node : nodes)
      sum += heat_capacity_of(node) * temperature_of(node);
    return sum;
  }

  template <int dim>
  double
  SolidRegion<dim>::heat_signal_rate() const
  {
    if (!carries_heat() || heat.settings.conductivity == 0)
      return 0;
    // On the reference cells the diffusivity is k J C^-1 / (rho_0 c): at
    // most J / lambda_min^2 times k / (rho_0 c), lambda_min the smallest
    // principal stretch (a region squeezed to a tenth conducts across its
    // reference spacing 100 times faster, and took the reference
    // configuration's step before: it diverged).
    double largest = 0;
    for (std::size_t c = 0; c < reference.centre.size(); ++c)
      {
        const double h = reference.min_vertex_distance[c] / fe.degree;
        for (unsigned int q = 0; q < reference.n_q; ++q)
          {
            const Tensor<2, dim> &F = deformation[c * reference.n_q + q];
            largest =
              std::max(largest,
                       determinant(F) / (smallest_stretch_squared(F) * h * h));
          }
      }
    return 2 * dim * heat.settings.conductivity / heat.rho_c * largest;
  }

#define DEALMPM_INSTANTIATE(dim)                                     \
  template void SolidRegion<dim>::use_heat(const HeatSettings &,     \
                                           const Function<dim> &);   \
  template void SolidRegion<dim>::conduct(double, double);           \
  template typename SolidRegion<dim>::HeatStep                       \
                SolidRegion<dim>::advance_temperature(double);       \
  template void SolidRegion<dim>::add_to_temperatures(               \
    const std::vector<unsigned int> &, const std::vector<double> &); \
  template double SolidRegion<dim>::stored_heat() const;             \
  template double SolidRegion<dim>::heat_signal_rate() const;        \
  template void   SolidRegion<dim>::mark_work_heated();
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
