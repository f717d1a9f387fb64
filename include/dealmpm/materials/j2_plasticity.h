#pragma once

#include <dealmpm/materials/material.h>

#include <array>

namespace dealmpm
{
  /**
   * Isotropic hardening of the yield stress with the equivalent plastic
   * strain alpha: sigma_y = sigma_y0 + H alpha (linear) or
   * sigma_y = sigma_y0 + B alpha^n (power law).
   */
  struct IsotropicHardening
  {
    double yield_stress = 1;
    double modulus      = 0; ///< H (linear)
    double coefficient  = 0; ///< B (power law)
    double exponent     = 1; ///< n (power law); 1 with B = H is linear

    double
    flow_stress(const double alpha) const;

    /** d sigma_y / d alpha (infinite at alpha = 0 for n < 1). */
    double
    slope(const double alpha) const;
  };

  /**
   * Finite-strain J2 (von Mises) plasticity (Simo 1992): multiplicative
   * split F = F_e F_p, Hencky stored energy
   * W = K/2 (tr eps_e)^2 + G |dev eps_e|^2 in the logarithmic elastic strain
   * eps_e = ln(b_e)/2, radial return on the Kirchhoff deviator in principal
   * space, isotropic hardening. The state is C_p^-1 (the trial
   * b_e = F C_p^-1 F^T needs only the current F: exactly objective, no
   * incremental drift), the equivalent plastic strain and the plastic work
   * (for the energy balance); in 2D also sigma_zz.
   */
  template <int dim>
  class J2Plasticity : public Material<dim>
  {
  public:
    J2Plasticity(const LameParameters     &lame,
                 const IsotropicHardening &hardening);

    std::vector<FieldDescription>
    internal_variables() const override;

    void
    initialize_internal_variables(ArrayView<double> internal) const override;

    void
    update_stress(const Tensor<2, dim>    &L,
                  const Tensor<2, dim>    &F,
                  const double             dt,
                  SymmetricTensor<2, dim> &stress,
                  ArrayView<double>        internal) const override;

    /** The elastic P-wave speed sqrt((K + 4G/3) / rho0). */
    double
    wave_speed(const Tensor<2, dim> &F) const override;

    double
    out_of_plane_stress(const Tensor<2, dim>          &F,
                        const SymmetricTensor<2, dim> &stress,
                        ArrayView<const double>        internal) const override;

    /** The elastic stored energy W(eps_e). */
    double
    strain_energy_density(const Tensor<2, dim>          &F,
                          const SymmetricTensor<2, dim> &stress,
                          ArrayView<const double> internal) const override;

    /** The plastic work sum of sigma_y(alpha_n+1) d_gamma. */
    double
    dissipated_energy_density(ArrayView<const double> internal) const override;

    bool
    dissipates() const override
    {
      return true;
    }

    /** Stored components of C_p^-1: xx, yy, zz, xy (and xz, yz in 3D). */
    static constexpr unsigned int n_inverse_plastic = dim == 2 ? 4 : 6;

  protected:
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

    /** After a return with @p d_gamma at flow stress @p flow (Johnson-Cook:
     * adiabatic heating). */
    virtual void
    after_plastic_step(const double /*d_gamma*/,
                       const double /*flow*/,
                       ArrayView<double> /*internal*/) const
    {}

    /** How many internal variables J2 itself keeps (C_p^-1, plastic strain,
     * plastic work, and sigma_zz in 2D); a derived model's come after. */
    static constexpr unsigned int n_j2_internal =
      n_inverse_plastic + (dim == 2 ? 3 : 2);

    const IsotropicHardening hardening;

  private:
    double bulk_modulus;
    double shear_modulus;
  };
} // namespace dealmpm
