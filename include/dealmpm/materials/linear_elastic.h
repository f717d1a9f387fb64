#pragma once

#include <dealmpm/materials/material.h>

namespace dealmpm
{
  /**
   * Isotropic linear elasticity in rate form (small strain):
   * sigma += dt (lambda tr(D) I + 2 mu D), D = sym(L). Parameters:
   * Young's modulus E > 0 and Poisson's ratio -1 < nu < 0.5.
   */
  template <int dim>
  class LinearElastic : public Material<dim>
  {
  public:
    explicit LinearElastic(const LameParameters &lame);

    void
    update_stress(const Tensor<2, dim> &   L,
                  const Tensor<2, dim> &   F,
                  const double             dt,
                  SymmetricTensor<2, dim> &stress,
                  ArrayView<double>        internal) const override;

    double
    wave_speed(const Tensor<2, dim> &F) const override;

    /** The complementary energy sigma : C^-1 : sigma / 2 (per unit volume). */
    double
    strain_energy_density(const Tensor<2, dim> &         F,
                          const SymmetricTensor<2, dim> &stress,
                          ArrayView<const double>        internal) const override;

  private:
    LameParameters lame;
  };
} // namespace dealmpm
