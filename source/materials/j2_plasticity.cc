#include <dealmpm/materials/hencky.h>
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
    /** Where each stored component of C_p^-1 sits in the 3 x 3 tensor. */
    constexpr unsigned int stored_row[6] = {0, 1, 2, 0, 0, 1};
    constexpr unsigned int stored_col[6] = {0, 1, 2, 1, 2, 2};

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
    : hardening(hardening)
    , bulk_modulus(lame.lambda + 2. / 3. * lame.mu)
    , shear_modulus(lame.mu)
  {}

  template <int dim>
  std::vector<FieldDescription>
  J2Plasticity<dim>::internal_variables() const
  {
    std::vector<FieldDescription> fields = {{"inverse_plastic_cauchy_green",
                                             n_inverse_plastic},
                                            {"plastic_strain", 1},
                                            {"plastic_work", 1}};
    if (dim == 2)
      fields.push_back({"stress_zz", 1});
    return fields;
  }

  template <int dim>
  void
  J2Plasticity<dim>::initialize_internal_variables(
    ArrayView<double> internal) const
  {
    for (unsigned int c = 0; c < internal.size(); ++c)
      internal[c] = c < 3 ? 1. : 0.;
  }

  template <int dim>
  void
  J2Plasticity<dim>::update_stress(const Tensor<2, dim> &,
                                   const Tensor<2, dim>    &F,
                                   const double             dt,
                                   SymmetricTensor<2, dim> &stress,
                                   ArrayView<double>        internal) const
  {
    const Tensor<2, 3>    F3 = embed_deformation<dim>(F);
    SymmetricTensor<2, 3> inverse_plastic;
    for (unsigned int c = 0; c < n_inverse_plastic; ++c)
      inverse_plastic[stored_row[c]][stored_col[c]] = internal[c];
    const PrincipalStrain trial = principal_log_strain(
      symmetrize(F3 * Tensor<2, 3>(inverse_plastic) * transpose(F3)));

    // Radial return of the Kirchhoff deviator 2 G dev(eps).
    const double volumetric =
      trial.strain[0] + trial.strain[1] + trial.strain[2];
    std::array<double, 3> deviator;
    double                norm = 0;
    for (unsigned int a = 0; a < 3; ++a)
      {
        deviator[a] = trial.strain[a] - volumetric / 3.;
        norm += deviator[a] * deviator[a];
      }
    const double                  G       = shear_modulus;
    const double                  q_trial = 2. * G * std::sqrt(1.5 * norm);
    double                       &alpha   = internal[n_inverse_plastic];
    double                        scale   = 1;
    const ArrayView<const double> state(internal.data(), internal.size());
    if (q_trial > flow_stress(alpha, 0, dt, state)[0])
      {
        const double d_gamma =
          plastic_multiplier(q_trial, G, [&](const double g) {
            return flow_stress(alpha, g, dt, state);
          });
        const double flow = flow_stress(alpha, d_gamma, dt, state)[0];
        scale             = 1. - 3. * G * d_gamma / q_trial;
        alpha += d_gamma;
        internal[n_inverse_plastic + 1] += flow * d_gamma;
        after_plastic_step(d_gamma, flow, internal);
      }

    // Kirchhoff stress and the new elastic b_e on the trial directions.
    std::array<double, 3> tau, b_elastic;
    for (unsigned int a = 0; a < 3; ++a)
      {
        const double strain = scale * deviator[a] + volumetric / 3.;
        tau[a]       = bulk_modulus * volumetric + 2. * G * scale * deviator[a];
        b_elastic[a] = std::exp(2. * strain);
      }
    const Tensor<2, 3> F_inverse = invert(F3);
    inverse_plastic              = symmetrize(
      F_inverse * Tensor<2, 3>(from_principal(b_elastic, trial.direction)) *
      transpose(F_inverse));
    for (unsigned int c = 0; c < n_inverse_plastic; ++c)
      internal[c] = inverse_plastic[stored_row[c]][stored_col[c]];

    const SymmetricTensor<2, 3> sigma =
      from_principal(tau, trial.direction) / determinant(F3);
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        stress[i][j] = sigma[i][j];
    if constexpr (dim == 2)
      internal[n_inverse_plastic + 2] = sigma[2][2];
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

  template <int dim>
  double
  J2Plasticity<dim>::wave_speed(const Tensor<2, dim> &) const
  {
    return std::sqrt((bulk_modulus + 4. / 3. * shear_modulus) / this->density);
  }

  template <int dim>
  double
  J2Plasticity<dim>::out_of_plane_stress(const Tensor<2, dim> &,
                                         const SymmetricTensor<2, dim> &,
                                         ArrayView<const double> internal) const
  {
    return dim == 2 ? internal[n_inverse_plastic + 2] : 0.;
  }

  template <int dim>
  double
  J2Plasticity<dim>::strain_energy_density(
    const Tensor<2, dim> &F,
    const SymmetricTensor<2, dim> &,
    ArrayView<const double> internal) const
  {
    const Tensor<2, 3>    F3 = embed_deformation<dim>(F);
    SymmetricTensor<2, 3> inverse_plastic;
    for (unsigned int c = 0; c < n_inverse_plastic; ++c)
      inverse_plastic[stored_row[c]][stored_col[c]] = internal[c];
    const PrincipalStrain e = principal_log_strain(
      symmetrize(F3 * Tensor<2, 3>(inverse_plastic) * transpose(F3)));
    const double volumetric = e.strain[0] + e.strain[1] + e.strain[2];
    double       deviatoric = 0;
    for (unsigned int a = 0; a < 3; ++a)
      deviatoric += std::pow(e.strain[a] - volumetric / 3., 2);
    return 0.5 * bulk_modulus * volumetric * volumetric +
           shear_modulus * deviatoric;
  }

  template <int dim>
  double
  J2Plasticity<dim>::dissipated_energy_density(
    ArrayView<const double> internal) const
  {
    return internal[n_inverse_plastic + 1];
  }

  template class J2Plasticity<2>;
  template class J2Plasticity<3>;
} // namespace dealmpm
