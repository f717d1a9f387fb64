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

  namespace
  {
    /** The Johnson-Cook entries: name, default, documentation. */
    struct JohnsonCookEntry
    {
      const char *name;
      double JohnsonCookParameters::*member;
      const char                    *documentation;
    };
    const JohnsonCookEntry johnson_cook_entries[] = {
      {"A", &JohnsonCookParameters::A, "Yield stress A (Pa), > 0."},
      {"B", &JohnsonCookParameters::B, "Hardening coefficient B (Pa), >= 0."},
      {"n", &JohnsonCookParameters::n, "Hardening exponent n, in (0, 1]."},
      {"C", &JohnsonCookParameters::C, "Strain-rate coefficient C, >= 0."},
      {"Reference strain rate",
       &JohnsonCookParameters::reference_rate,
       "Reference equivalent plastic strain rate (1/s), > 0."},
      {"m", &JohnsonCookParameters::m, "Thermal softening exponent m, > 0."},
      {"Room temperature",
       &JohnsonCookParameters::room_temperature,
       "Room (and initial) temperature (K), > 0."},
      {"Melting temperature",
       &JohnsonCookParameters::melting_temperature,
       "Melting temperature (K), > Room temperature."},
      {"Specific heat",
       &JohnsonCookParameters::specific_heat,
       "Specific heat c_p (J/(kg K)), > 0."},
      {"Taylor-Quinney coefficient",
       &JohnsonCookParameters::taylor_quinney,
       "Fraction of the plastic work that heats the material, in [0, 1]; "
       "0: no heating."},
      {"D1",
       &JohnsonCookParameters::D1,
       "Damage constant D1 (with Damage indicator)."},
      {"D2", &JohnsonCookParameters::D2, "Damage constant D2."},
      {"D3", &JohnsonCookParameters::D3, "Damage constant D3 (triaxiality)."},
      {"D4", &JohnsonCookParameters::D4, "Damage constant D4 (strain rate)."},
      {"D5", &JohnsonCookParameters::D5, "Damage constant D5 (temperature)."}};

    void
    declare_johnson_cook_parameters(ParameterHandler &prm)
    {
      // OFHC copper (Johnson and Cook 1983).
      declare_elastic_constants(prm, 124e9, 0.34);
      const JohnsonCookParameters copper;
      for (const auto &e : johnson_cook_entries)
        prm.declare_entry(e.name,
                          Utilities::to_string(copper.*(e.member)),
                          Patterns::Double(),
                          e.documentation);
      prm.declare_entry(
        "Damage indicator",
        "false",
        Patterns::Bool(),
        "Accumulate Johnson and Cook's (1985) damage D = sum d eps_p / eps_f, "
        "eps_f = [D1 + D2 exp(D3 sigma*)][1 + D4 ln(rate*)][1 + D5 T*], as "
        "the particle field 'damage' (1: the model predicts fracture); the "
        "stress is not softened.");
    }

    JohnsonCookParameters
    read_johnson_cook(SceneReader &reader)
    {
      JohnsonCookParameters jc;
      for (const auto &e : johnson_cook_entries)
        jc.*(e.member) = reader.get_double(e.name);
      for (const char *positive : {"A",
                                   "Reference strain rate",
                                   "m",
                                   "Room temperature",
                                   "Specific heat"})
        reader.get_positive(positive);
      for (const char *nonnegative : {"B", "C"})
        reader.get_nonnegative(nonnegative);
      if (!(jc.n > 0 && jc.n <= 1))
        reader.fail("n", "a number in (0, 1]");
      if (!(jc.melting_temperature > jc.room_temperature))
        reader.fail("Melting temperature",
                    "a number above Room temperature (" +
                      Utilities::to_string(jc.room_temperature) + ")");
      if (!(jc.taylor_quinney >= 0 && jc.taylor_quinney <= 1))
        reader.fail("Taylor-Quinney coefficient", "a number in [0, 1]");
      jc.damage_indicator = reader.get_bool("Damage indicator");
      return jc;
    }
  } // namespace

  template <int dim>
  void
  add_johnson_cook_material(Registry<Material<dim>> &registry)
  {
    registry.add("Johnson-Cook",
                 "J2 plasticity with Johnson and Cook's flow stress (A + B "
                 "alpha^n)(1 + C ln(rate / reference))(1 - T*^m) and adiabatic "
                 "heating (temperature an internal variable); defaults: OFHC "
                 "copper.",
                 declare_johnson_cook_parameters,
                 [](SceneReader &reader) -> std::unique_ptr<Material<dim>> {
                   const LameParameters lame = read_elastic_constants(reader);
                   return std::make_unique<JohnsonCook<dim>>(
                     lame, read_johnson_cook(reader));
                 });
  }

  template void
  add_johnson_cook_material(Registry<Material<2>> &);
  template void
  add_johnson_cook_material(Registry<Material<3>> &);
} // namespace dealmpm
