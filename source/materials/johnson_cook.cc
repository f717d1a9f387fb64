#include <dealmpm/materials/johnson_cook.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace dealmpm
{
  double
  JohnsonCookParameters::failure_strain(const double triaxiality,
                                        const double rate,
                                        const double temperature) const
  {
    const double rate_ratio = std::max(rate / reference_rate, 1.);
    const double homologous =
      std::clamp((temperature - room_temperature) /
                   (melting_temperature - room_temperature),
                 0.,
                 1.);
    return (D1 + D2 * std::exp(D3 * triaxiality)) *
           (1. + D4 * std::log(rate_ratio)) * (1. + D5 * homologous);
  }

  template <int dim>
  JohnsonCook<dim>::JohnsonCook(const LameParameters        &lame,
                                const JohnsonCookParameters &jc)
    : J2Plasticity<dim>(lame, IsotropicHardening())
    , jc(jc)
  {}

  template <int dim>
  void
  JohnsonCook<dim>::initialize_internal_variables(
    ArrayView<double> internal) const
  {
    J2Plasticity<dim>::initialize_internal_variables(internal);
    internal[this->model_index] = jc.room_temperature;
  }

  template <int dim>
  std::array<double, 2>
  JohnsonCook<dim>::flow_stress(const double            alpha,
                                const double            d_gamma,
                                const double            dt,
                                ArrayView<const double> internal) const
  {
    const double a = alpha + d_gamma;
    // Strain hardening and its slope (infinite at 0 for n < 1).
    const double hardening = jc.A + jc.B * std::pow(a, jc.n);
    const double hardening_slope =
      a > 0 ?
        jc.B * jc.n * std::pow(a, jc.n - 1) :
        (jc.n < 1 ? std::numeric_limits<double>::infinity() : jc.B * jc.n);
    // Rate factor: 1 below the reference rate.
    const double rate      = d_gamma / dt;
    const bool   rate_term = rate > jc.reference_rate;
    const double rate_scale =
      rate_term ? 1. + jc.C * std::log(rate / jc.reference_rate) : 1.;
    const double rate_slope = rate_term ? jc.C / d_gamma : 0.;
    // Thermal softening at the step's starting temperature.
    const double homologous =
      std::clamp((temperature(internal) - jc.room_temperature) /
                   (jc.melting_temperature - jc.room_temperature),
                 0.,
                 1.);
    const double thermal = 1. - std::pow(homologous, jc.m);
    return {
      {hardening * rate_scale * thermal,
       (hardening_slope * rate_scale + hardening * rate_slope) * thermal}};
  }

  template <int dim>
  void
  JohnsonCook<dim>::after_plastic_step(const double      d_gamma,
                                       const double      dt,
                                       const double      flow,
                                       const double      mean_stress,
                                       ArrayView<double> internal) const
  {
    // Damage at the step's starting temperature, like the flow stress.
    if (jc.damage_indicator)
      internal[this->model_index + 1] +=
        d_gamma / jc.failure_strain(mean_stress / flow,
                                    d_gamma / dt,
                                    temperature(internal));
    internal[this->model_index] +=
      jc.taylor_quinney * flow * d_gamma / (this->density * jc.specific_heat);
  }

  template class JohnsonCook<2>;
  template class JohnsonCook<3>;
} // namespace dealmpm
