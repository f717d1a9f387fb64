#pragma once

#include <dealmpm/materials/material.h>

namespace dealmpm
{
  /** Constants of a weakly compressible Newtonian fluid. */
  struct TaitParameters
  {
    double sound_speed     = 50;   ///< c0 (m/s): about 10x the fastest flow
    double exponent        = 7;    ///< gamma of Tait's equation
    double viscosity       = 1e-3; ///< dynamic viscosity mu (Pa s)
    bool   tension_cut_off = true;
  };

  /**
   * Weakly compressible Newtonian fluid: Tait's equation of state from J
   * (not from an integrated rate, so the density does not drift),
   * p = B (J^-gamma - 1), B = rho0 c0^2 / gamma, and the viscous stress
   * 2 mu dev(D): sigma = -p I + 2 mu dev(D). With the tension cut-off, p >= 0
   * (free surfaces do not pull). F is reset to J^(1/dim) I after each
   * update (resets_deformation): a fluid forgets its shape, and an F stirred
   * for long would lose its accuracy. The stored energy is
   * -int_1^J p dJ; the viscous work is dissipated (an internal variable).
   */
  template <int dim>
  class TaitFluid : public Material<dim>
  {
  public:
    explicit TaitFluid(const TaitParameters &parameters);

    std::vector<FieldDescription>
    internal_variables() const override;

    void
    update_stress(const Tensor<2, dim>    &L,
                  const Tensor<2, dim>    &F,
                  const double             dt,
                  SymmetricTensor<2, dim> &stress,
                  ArrayView<double>        internal) const override;

    /** c0 (rho / rho0)^((gamma - 1) / 2): sqrt(dp / d rho). */
    double
    wave_speed(const Tensor<2, dim> &F) const override;

    double
    out_of_plane_stress(const Tensor<2, dim>          &F,
                        const SymmetricTensor<2, dim> &stress,
                        ArrayView<const double>        internal) const override;

    double
    strain_energy_density(const Tensor<2, dim>          &F,
                          const SymmetricTensor<2, dim> &stress,
                          ArrayView<const double> internal) const override;

    double
    dissipated_energy_density(ArrayView<const double> internal) const override
    {
      return internal[0];
    }

    bool
    dissipates() const override
    {
      return parameters.viscosity > 0;
    }

    bool
    resets_deformation() const override
    {
      return true;
    }

    /** The pressure at J. */
    double
    pressure(const double J) const;

  private:
    TaitParameters parameters;
  };

  /** Register "Tait fluid" in the material table: its parameters (subsection
   * "Tait fluid" of a "Material N" section), their reading and checks. */
  template <int dim>
  void
  add_tait_fluid_material(Registry<Material<dim>> &registry);
} // namespace dealmpm
