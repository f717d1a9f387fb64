#pragma once

#include <dealmpm/materials/material.h>

namespace dealmpm
{
  /**
   * Isotropic linear elasticity in rate form (small strain):
   * sigma += dt (lambda tr(D) I + 2 mu D), D = sym(L). Parameters:
   * Young's modulus E > 0 and Poisson's ratio -1 < nu < 0.5.
   *
   * The rate form has no stored-energy function under large rotation, so
   * the model integrates the stress power J sigma : D per unit reference
   * volume (trapezoidal rule) in an internal variable: the strain energy in
   * the statistics is then the work actually done on the particle, and the
   * energy balance measures only the scheme's error.
   */
  template <int dim>
  class LinearElastic : public Material<dim>
  {
  public:
    explicit LinearElastic(const LameParameters &lame);

    std::vector<FieldDescription>
    internal_variables() const override
    {
      return {{"stress_work", 1}};
    }

    void
    update_stress(const Tensor<2, dim>    &L,
                  const Tensor<2, dim>    &F,
                  const double             dt,
                  SymmetricTensor<2, dim> &stress,
                  ArrayView<double>        internal) const override;

    double
    wave_speed(const Tensor<2, dim> &F) const override;

    /** The integrated stress power. */
    /** In plane strain d sigma_zz = dt lambda tr(D) = nu d(sigma_xx +
     * sigma_yy), so sigma_zz = nu (sigma_xx + sigma_yy) from a stress-free
     * start. */
    double
    out_of_plane_stress(const Tensor<2, dim>          &F,
                        const SymmetricTensor<2, dim> &stress,
                        ArrayView<const double>        internal) const override;

    double
    strain_energy_density(const Tensor<2, dim>          &F,
                          const SymmetricTensor<2, dim> &stress,
                          ArrayView<const double> internal) const override;

  private:
    LameParameters lame;
  };

  /** Register "linear elastic" in the material table: its parameters
   * (subsection "linear elastic" of a "Material N" section), their reading and
   * checks. */
  template <int dim>
  void
  add_linear_elastic_material(Registry<Material<dim>> &registry);
} // namespace dealmpm
