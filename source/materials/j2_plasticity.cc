#include <dealmpm/materials/j2_plasticity.h>

#include <cmath>
#include <limits>

namespace dealmpm
{
  double
  IsotropicHardening::flow_stress(const double alpha) const
  {
    return yield_stress + modulus * alpha +
           (coefficient > 0 ? coefficient * std::pow(alpha, exponent) : 0.);
  }

  double
  IsotropicHardening::slope(const double alpha) const
  {
    if (coefficient == 0)
      return modulus;
    if (alpha == 0 && exponent < 1)
      return std::numeric_limits<double>::infinity();
    return modulus + coefficient * exponent * std::pow(alpha, exponent - 1);
  }

  namespace
  {
    /**
     * The plastic multiplier d_gamma of the radial return:
     * q_trial - 3 G d_gamma = flow(d_gamma)[0]. Newton's method kept inside
     * the bracket [0, q_trial / (3G)] (the residual is positive at 0 and not
     * positive at the top) by bisection, so that it converges for any
     * increasing flow stress, also where its slope is infinite (a power law
     * at alpha = 0, the rate term at rest). @p flow gives the flow stress
     * and its derivative in d_gamma.
     */
    template <class Flow>
    double
    plastic_multiplier(const double q_trial, const double G, const Flow &flow)
    {
      double low = 0, high = q_trial / (3. * G), g = 0;
      for (unsigned int it = 0; it < 200; ++it)
        {
          const auto [stress, slope] = flow(g);
          const double r             = q_trial - 3. * G * g - stress;
          if (std::abs(r) <= 1e-13 * q_trial)
            return g;
          (r > 0 ? low : high) = g;
          const double next    = g + r / (3. * G + slope);
          g = (next > low && next < high) ? next : 0.5 * (low + high);
        }
      // Not converged: NaN stops the run at this particle (finiteness check).
      return std::numeric_limits<double>::quiet_NaN();
    }
  } // namespace

  template <int dim>
  J2Plasticity<dim>::J2Plasticity(const LameParameters     &lame,
                                  const IsotropicHardening &hardening)
    : HenckyPlasticity<dim>(lame)
    , hardening(hardening)
  {}

  template <int dim>
  double
  J2Plasticity<dim>::return_to_surface(std::array<double, 3> &strain,
                                       const double           dt,
                                       ArrayView<double>      internal) const
  {
    const double volumetric = strain[0] + strain[1] + strain[2];
    double       norm       = 0;
    for (unsigned int a = 0; a < 3; ++a)
      norm += std::pow(strain[a] - volumetric / 3., 2);
    const double                  G       = this->shear_modulus;
    const double                  q_trial = 2. * G * std::sqrt(1.5 * norm);
    const double                  alpha   = this->plastic_strain(internal);
    const ArrayView<const double> state(internal.data(), internal.size());
    if (!(q_trial > flow_stress(alpha, 0, dt, state)[0]))
      return 0;
    const double d_gamma = plastic_multiplier(q_trial, G, [&](const double g) {
      return flow_stress(alpha, g, dt, state);
    });
    // Radial return: the deviator shrinks, the volume stays elastic.
    const double scale = 1. - 3. * G * d_gamma / q_trial;
    for (unsigned int a = 0; a < 3; ++a)
      strain[a] = scale * (strain[a] - volumetric / 3.) + volumetric / 3.;
    after_plastic_step(d_gamma,
                       dt,
                       flow_stress(alpha, d_gamma, dt, state)[0],
                       this->bulk_modulus * volumetric,
                       internal);
    return d_gamma;
  }

  template <int dim>
  std::array<double, 2>
  J2Plasticity<dim>::flow_stress(const double alpha,
                                 const double d_gamma,
                                 const double,
                                 ArrayView<const double>) const
  {
    return {{hardening.flow_stress(alpha + d_gamma),
             hardening.slope(alpha + d_gamma)}};
  }

  template class J2Plasticity<2>;
  template class J2Plasticity<3>;

  namespace
  {
    void
    declare_j2_parameters(ParameterHandler &prm)
    {
      declare_elastic_constants(prm, 200e9, 0.3);
      prm.declare_entry("Yield stress",
                        "250e6",
                        Patterns::Double(),
                        "Initial yield stress sigma_y0 (Pa), > 0.");
      prm.declare_entry("Hardening modulus",
                        "0",
                        Patterns::Double(),
                        "Linear hardening modulus H (Pa), >= 0.");
      prm.declare_entry("Hardening coefficient",
                        "0",
                        Patterns::Double(),
                        "Power-law hardening coefficient B (Pa), >= 0.");
      prm.declare_entry("Hardening exponent",
                        "1",
                        Patterns::Double(),
                        "Power-law hardening exponent n, in (0, 1].");
    }

    IsotropicHardening
    read_j2_hardening(SceneReader &reader)
    {
      IsotropicHardening h;
      h.yield_stress = reader.get_positive("Yield stress");
      h.modulus      = reader.get_nonnegative("Hardening modulus");
      h.coefficient  = reader.get_nonnegative("Hardening coefficient");
      h.exponent     = reader.get_positive("Hardening exponent");
      if (h.exponent > 1)
        reader.fail("Hardening exponent", "a number in (0, 1]");
      return h;
    }
  } // namespace

  template <int dim>
  void
  add_j2_plasticity_material(Registry<Material<dim>> &registry)
  {
    registry.add(
      "J2 plasticity",
      "finite-strain von Mises plasticity (Simo 1992): Hencky "
      "elasticity in the logarithmic elastic strain, radial return, "
      "isotropic hardening sigma_y = Yield stress + Hardening modulus "
      "alpha + Hardening coefficient alpha^Hardening exponent (Young's "
      "modulus, Poisson's ratio, Yield stress, Hardening modulus, "
      "Hardening coefficient, Hardening exponent).",
      declare_j2_parameters,
      [](SceneReader &reader) -> std::unique_ptr<Material<dim>> {
        const LameParameters lame = read_elastic_constants(reader);
        return std::make_unique<J2Plasticity<dim>>(lame,
                                                   read_j2_hardening(reader));
      });
  }

  template void
  add_j2_plasticity_material(Registry<Material<2>> &);
  template void
  add_j2_plasticity_material(Registry<Material<3>> &);
} // namespace dealmpm
