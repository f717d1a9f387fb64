#pragma once

#include <dealmpm/materials/hencky_plasticity.h>

#include <array>

namespace dealmpm
{
  /**
   * Isotropic hardening of the yield stress with the equivalent plastic
   * strain alpha: sigma_y = sigma_y0 + H alpha + B alpha^n (H: linear, B and
   * n: power law).
   */
  struct IsotropicHardening
  {
    double yield_stress = 1;
    double modulus      = 0; ///< H (linear)
    double coefficient  = 0; ///< B (power law)
    double exponent     = 1; ///< n (power law)

    double
    flow_stress(const double alpha) const;

    /** d sigma_y / d alpha (infinite at alpha = 0 for n < 1). */
    double
    slope(const double alpha) const;
  };

  /**
   * Finite-strain J2 (von Mises) plasticity (Simo 1992) on the Hencky frame
   * (HenckyPlasticity): radial return of the Kirchhoff deviator in principal
   * space, q = sqrt(3/2) |dev tau| <= sigma_y(alpha), with isotropic
   * hardening. The plastic multiplier is a scalar Newton solve kept inside
   * its bracket by bisection.
   */
  template <int dim>
  class J2Plasticity : public HenckyPlasticity<dim>
  {
  public:
    J2Plasticity(const LameParameters     &lame,
                 const IsotropicHardening &hardening);

  protected:
    double
    return_to_surface(std::array<double, 3> &strain,
                      const double           dt,
                      ArrayView<double>      internal) const override;

    /**
     * The flow stress after a plastic increment @p d_gamma over a step of
     * @p dt from the state @p internal, and its derivative in d_gamma. J2:
     * the hardening law at alpha + d_gamma; Johnson-Cook adds the rate and
     * the temperature.
     */
    virtual std::array<double, 2>
    flow_stress(const double            alpha,
                const double            d_gamma,
                const double            dt,
                ArrayView<const double> internal) const;

    /** After a return with @p d_gamma over @p dt at flow stress @p flow
     * and Kirchhoff mean stress @p mean_stress (Johnson-Cook: adiabatic
     * heating, damage). */
    virtual void
    after_plastic_step(const double /*d_gamma*/,
                       const double /*dt*/,
                       const double /*flow*/,
                       const double /*mean_stress*/,
                       ArrayView<double> /*internal*/) const
    {}

    const IsotropicHardening hardening;
  };

  /** Register "J2 plasticity" in the material table: its parameters (subsection
   * "J2 plasticity" of a "Material N" section), their reading and checks. */
  template <int dim>
  void
  add_j2_plasticity_material(Registry<Material<dim>> &registry);
} // namespace dealmpm
