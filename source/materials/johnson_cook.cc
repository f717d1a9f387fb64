#include <dealmpm/materials/johnson_cook.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace dealmpm
{
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
                                       const double      flow,
                                       ArrayView<double> internal) const
  {
    internal[this->model_index] +=
      jc.taylor_quinney * flow * d_gamma / (this->density * jc.specific_heat);
  }

  template class JohnsonCook<2>;
  template class JohnsonCook<3>;
} // namespace dealmpm
