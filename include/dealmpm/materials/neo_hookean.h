#pragma once

#include <dealmpm/materials/material.h>

namespace dealmpm
{
  /**
   * Compressible neo-Hookean solid (the model of the manufactured solutions):
   * sigma = mu / J (B - I) + lambda ln(J) / J I, stored energy
   * W = mu / 2 (tr C - 3) - mu ln J + lambda / 2 (ln J)^2. Parameters:
   * Young's modulus and Poisson's ratio (small-strain values).
   */
  template <int dim>
  class NeoHookean : public Material<dim>
  {
  public:
    explicit NeoHookean(const LameParameters &lame);

    void
    update_stress(const Tensor<2, dim>    &L,
                  const Tensor<2, dim>    &F,
                  const double             dt,
                  SymmetricTensor<2, dim> &stress,
                  ArrayView<double>        internal) const override;

    /** The points in one loop (the stress of each from its F alone). */
    void
    update_stresses(const ArrayView<const Tensor<2, dim>>    &L,
                    const ArrayView<const Tensor<2, dim>>    &F,
                    const double                              dt,
                    const ArrayView<SymmetricTensor<2, dim>> &stress,
                    const ArrayView<double> &internal) const override;
    /** From the tangent moduli at the current J: stiffer in compression. */
    double
    wave_speed(const Tensor<2, dim> &F) const override;
    /** The root taken once, of the largest modulus (see Material). */
    double
    max_wave_speed(const ArrayView<const Tensor<2, dim>> &F,
                   const ArrayView<const double> &) const override;

    /** lambda ln(J) / J (F_zz = 1). */
    double
    out_of_plane_stress(const Tensor<2, dim>          &F,
                        const SymmetricTensor<2, dim> &stress,
                        ArrayView<const double>        internal) const override;

    double
    strain_energy_density(const Tensor<2, dim>          &F,
                          const SymmetricTensor<2, dim> &stress,
                          ArrayView<const double> internal) const override;

    bool
    locks_in_linear_cells() const override
    {
      return lame.nearly_incompressible();
    }

  private:
    LameParameters lame;
  };

  /** Register "neo-Hookean" in the material table: its parameters (subsection
   * "neo-Hookean" of a "Material N" section), their reading and checks. */
  template <int dim>
  void
  add_neo_hookean_material(Registry<Material<dim>> &registry);
} // namespace dealmpm
