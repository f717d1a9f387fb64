#include <dealmpm/materials/thermal_expansion.h>

#include <cmath>
#include <vector>

namespace dealmpm
{
  template <int dim>
  std::optional<LameParameters>
  initial_elastic_constants(const Material<dim> &model)
  {
    unsigned int n = 0;
    for (const FieldDescription &f : model.internal_variables())
      n += f.n_components;
    // The stress of the unstrained state (a reference pressure's), then
    // of the strained one, each from the initial state.
    const auto stress_at = [&](const double strain) {
      std::vector<double> internal(n);
      model.initialize_internal_variables(make_array_view(internal));
      Tensor<2, dim> F = unit_symmetric_tensor<dim>();
      Tensor<2, dim> L;
      F[0][0] += strain;
      L[0][0] = strain; // over dt = 1
      SymmetricTensor<2, dim> stress;
      model.update_stress(L, F, 1., stress, make_array_view(internal));
      return stress;
    };
    // Compressed: a fluid with a tension cut-off answers only to that.
    const double                  strain = -1e-7;
    const SymmetricTensor<2, dim> change = stress_at(strain) - stress_at(0);
    const double                  lambda = change[1][1] / strain;
    const double mu = (change[0][0] - change[1][1]) / (2 * strain);
    if (!std::isfinite(lambda + mu) || !(lambda + 2 * mu > 0) || mu < 0)
      return std::nullopt;
    const double nu = lambda / (2 * (lambda + mu));
    if (!(nu > -1 - 1e-6 && nu < 0.5 + 1e-6))
      return std::nullopt;
    return LameParameters{lambda, mu};
  }

  template <int dim>
  ThermallyExpanding<dim>::ThermallyExpanding(
    std::unique_ptr<Material<dim>> inner_model,
    const double                   alpha,
    const std::string             &suffix)
    : inner(std::move(inner_model))
    , suffix(suffix)
    , inner_dissipates(inner->dissipates())
    , per_kelvin(alpha)
  {
    this->density = inner->density;
    for (const FieldDescription &f : inner->internal_variables())
      n_inner += f.n_components;
    if constexpr (dim == 2)
      {
        // The caller refuses a model without an elastic response.
        const LameParameters lame = initial_elastic_constants(*inner).value();
        per_kelvin *= 1. + lame.lambda / (2. * (lame.lambda + lame.mu));
        two_mu = 2. * lame.mu;
      }
  }

  template <int dim>
  std::vector<FieldDescription>
  ThermallyExpanding<dim>::internal_variables() const
  {
    std::vector<FieldDescription> list = inner->internal_variables();
    list.push_back({"thermal_stretch" + suffix, 1});
    list.push_back({"stretch_at_update" + suffix, 1});
    list.push_back({"thermal_work" + suffix, 1});
    return list;
  }

  template <int dim>
  void
  ThermallyExpanding<dim>::initialize_internal_variables(
    ArrayView<double> internal) const
  {
    inner->initialize_internal_variables(
      make_array_view(internal.begin(), internal.begin() + n_inner));
    internal[n_inner]     = 1.;
    internal[n_inner + 1] = 1.;
    internal[n_inner + 2] = 0.;
  }

  template <int dim>
  void
  ThermallyExpanding<dim>::update_stress(const Tensor<2, dim>    &L,
                                         const Tensor<2, dim>    &F,
                                         const double             dt,
                                         SymmetricTensor<2, dim> &stress,
                                         ArrayView<double> internal) const
  {
    const ArrayView<double> model =
      make_array_view(internal.begin(), internal.begin() + n_inner);
    const double   theta      = internal[n_inner];
    const double   theta_old  = internal[n_inner + 1];
    const double   log_growth = std::log(theta / theta_old);
    Tensor<2, dim> L_m        = L;
    for (unsigned int d = 0; d < dim; ++d)
      L_m[d][d] -= log_growth / dt;
    const Tensor<2, dim>          F_m        = F / theta;
    const SymmetricTensor<2, dim> stress_old = stress;
    inner->update_stress(L_m, F_m, dt, stress, model);
    // The stress's work on the thermal stretch (mid-step stress), less the
    // change of the stored energy's reference volume theta^dim: what the
    // grid's work puts in beyond the stored energy's change.
    if (log_growth != 0.)
      internal[n_inner + 2] +=
        determinant(F) * 0.5 * trace(stress_old + stress) * log_growth -
        inner->strain_energy_density(F_m, stress, model) *
          (std::pow(theta, dim) - std::pow(theta_old, dim));
    internal[n_inner + 1] = theta;
  }

  template <int dim>
  double
  ThermallyExpanding<dim>::out_of_plane_stress(
    const Tensor<2, dim>          &F,
    const SymmetricTensor<2, dim> &stress,
    ArrayView<const double>        internal) const
  {
    const double theta = internal[n_inner];
    return inner->out_of_plane_stress(F / theta, stress, own(internal)) -
           two_mu * (theta - 1.);
  }

  template <int dim>
  double
  ThermallyExpanding<dim>::strain_energy_density(
    const Tensor<2, dim>          &F,
    const SymmetricTensor<2, dim> &stress,
    ArrayView<const double>        internal) const
  {
    const double theta = internal[n_inner];
    return std::pow(theta, dim) *
           inner->strain_energy_density(F / theta, stress, own(internal));
  }

  template <int dim>
  double
  ThermallyExpanding<dim>::dissipated_energy_density(
    ArrayView<const double> internal) const
  {
    // The model's own dissipation per unit volume of the stress-free
    // state, scaled by today's theta^dim (exact while theta is steady,
    // first order in its change otherwise).
    const double model = inner_dissipates ?
                           std::pow(internal[n_inner], dim) *
                             inner->dissipated_energy_density(own(internal)) :
                           0.;
    return internal[n_inner + 2] + model;
  }

  template std::optional<LameParameters>
  initial_elastic_constants(const Material<2> &);
  template std::optional<LameParameters>
  initial_elastic_constants(const Material<3> &);
  template class ThermallyExpanding<2>;
  template class ThermallyExpanding<3>;
} // namespace dealmpm
