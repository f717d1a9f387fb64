#pragma once

#include <dealmpm/materials/material.h>

#include <cmath>

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
   *
   * Final, with the step's methods defined here: a sweep in which every
   * material is linear elastic calls them directly (StressUpdate::Of).
   */
  template <int dim>
  class LinearElastic final : public Material<dim>
  {
  public:
    explicit LinearElastic(const LameParameters &lame);

    std::vector<FieldDescription>
    internal_variables() const override
    {
      return {{"stress_work", 1}};
    }

    DEAL_II_ALWAYS_INLINE void
    update_stress(const Tensor<2, dim>    &L,
                  const Tensor<2, dim>    &F,
                  const double             dt,
                  SymmetricTensor<2, dim> &stress,
                  ArrayView<double>        internal) const override
    {
      const SymmetricTensor<2, dim> D = symmetrize(L);
      // dt (2 mu D + lambda tr(D) I) entry by entry (deal.II stores the
      // diagonal first), without the products with I's zeros: the same
      // numbers as the tensor expression.
      const double            two_mu       = 2. * lame.mu;
      const double            lambda_trace = lame.lambda * trace(D);
      SymmetricTensor<2, dim> increment;
      for (unsigned int i = 0; i < dim; ++i)
        increment.access_raw_entry(i) =
          dt * (two_mu * D.access_raw_entry(i) + lambda_trace);
      for (unsigned int i = dim; i < D.n_independent_components; ++i)
        increment.access_raw_entry(i) = dt * (two_mu * D.access_raw_entry(i));
      internal[0] += dt * determinant(F) * ((stress + 0.5 * increment) * D);
      stress += increment;
    }

    /** The points in one loop, update_stress() inlined. */
    void
    update_stresses(const ArrayView<const Tensor<2, dim>>    &L,
                    const ArrayView<const Tensor<2, dim>>    &F,
                    const double                              dt,
                    const ArrayView<SymmetricTensor<2, dim>> &stress,
                    const ArrayView<double> &internal) const override
    {
      for (std::size_t q = 0; q < F.size(); ++q)
        update_stress(L[q],
                      F[q],
                      dt,
                      stress[q],
                      ArrayView<double>(internal.begin() + q, 1));
    }

    DEAL_II_ALWAYS_INLINE double
    wave_speed(const Tensor<2, dim> &F) const override
    {
      // Current density rho0 / J.
      return std::sqrt((lame.lambda + 2. * lame.mu) * determinant(F) /
                       this->density);
    }

    /** Its moduli have no history. */
    DEAL_II_ALWAYS_INLINE double
    wave_speed_of_state(const Tensor<2, dim> &F,
                        ArrayView<const double>) const override
    {
      return wave_speed(F);
    }

    /** The root taken once, of the largest J (see Material). */
    double
    max_wave_speed(const ArrayView<const Tensor<2, dim>> &F,
                   const ArrayView<const double> &) const override
    {
      double largest_J = 0;
      for (const Tensor<2, dim> &f : F)
        largest_J = std::max(largest_J, determinant(f));
      return F.size() == 0 ? 0. :
                             std::sqrt((lame.lambda + 2. * lame.mu) *
                                       largest_J / this->density);
    }

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

    bool
    locks_in_linear_cells() const override
    {
      return lame.nearly_incompressible();
    }

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
