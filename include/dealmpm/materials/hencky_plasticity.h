#pragma once

#include <dealmpm/materials/material.h>

#include <array>

namespace dealmpm
{
  /**
   * Finite-strain elastoplasticity with Hencky elasticity, the frame the
   * principal-space returns share (Simo 1992): multiplicative split
   * F = F_e F_p, stored energy W = K/2 (tr eps_e)^2 + G |dev eps_e|^2 in the
   * logarithmic elastic strain eps_e = ln(b_e)/2, and a return mapping in
   * the principal directions of the trial b_e = F C_p^-1 F^T. Keeping
   * C_p^-1 makes the update need only the current F: exactly objective, no
   * incremental drift. A model supplies only its return
   * (return_to_surface), and its elasticity if it is not Hencky's
   * (kirchhoff, elastic_energy); the plastic work is tau : d eps_p of each
   * step.
   *
   * Internal variables: C_p^-1 (xx, yy, zz, xy, and xz, yz in 3D), the
   * equivalent plastic strain, the plastic work per unit reference volume,
   * sigma_zz in 2D, then the model's own (model_variables()).
   */
  template <int dim>
  class HenckyPlasticity : public Material<dim>
  {
  public:
    HenckyPlasticity(const LameParameters &lame);

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

    /** The elastic stored energy W(eps_e) (elastic_energy()). */
    double
    strain_energy_density(const Tensor<2, dim>          &F,
                          const SymmetricTensor<2, dim> &stress,
                          ArrayView<const double> internal) const override;

    double
    dissipated_energy_density(ArrayView<const double> internal) const override
    {
      return internal[plastic_work_index];
    }

    bool
    dissipates() const override
    {
      return true;
    }

    /** The stress depends on F only through b_e = F C_p^-1 F^T. */
    bool
    renormalises_deformation() const override
    {
      return true;
    }

    /** F' = (J / J_e)^(1/dim) b_e^(1/2) in the plane, C_p^-1' = (J_e /
     * J)^(2/dim) I there (2D keeps its zz): the same b_e, J and plastic
     * volume change; F's rotation and accumulated plastic distortion, which
     * an isotropic model never reads, are dropped. */
    void
    renormalise_deformation(Tensor<2, dim>   &F,
                            ArrayView<double> internal) const override;

    /** Plastic flow (isochoric for J2 and a dilation angle of 0, little
     * dilation otherwise) cannot follow a volume change of each point's
     * own. */
    bool
    locks_in_linear_cells() const override
    {
      return true;
    }

    /** The equivalent plastic strain of a state. */
    static double
    plastic_strain(ArrayView<const double> internal)
    {
      return internal[plastic_strain_index];
    }

    /** Stored components of C_p^-1: xx, yy, zz, xy (and xz, yz in 3D). */
    static constexpr unsigned int n_inverse_plastic    = dim == 2 ? 4 : 6;
    static constexpr unsigned int plastic_strain_index = n_inverse_plastic;
    static constexpr unsigned int plastic_work_index   = n_inverse_plastic + 1;
    /** Where a model's own variables start. */
    static constexpr unsigned int model_index =
      n_inverse_plastic + (dim == 2 ? 3 : 2);

  protected:
    /**
     * Return the principal logarithmic elastic strains of the trial state,
     * @p strain, to the model's yield surface (in place; the stress is
     * K tr(eps) + 2G dev(eps)). Returns the increment of the equivalent
     * plastic strain (0: elastic). @p internal is the whole state; a model
     * updates its own variables in it.
     */
    virtual double
    return_to_surface(std::array<double, 3> &strain,
                      const double           dt,
                      ArrayView<double>      internal) const = 0;

    /** The model's own internal variables, after the shared ones. */
    virtual std::vector<FieldDescription>
    model_variables() const
    {
      return {};
    }

    /** Principal Kirchhoff stresses of principal elastic strains:
     * K tr(eps) + 2G dev(eps), unless a model's elasticity is another
     * (Modified Cam-Clay's pressure grows with the volume strain). */
    virtual std::array<double, 3>
    kirchhoff(const std::array<double, 3> &strain) const;

    /** |dev eps|^2 of principal strains. */
    static double
    deviator_squared(const std::array<double, 3> &strain)
    {
      const double mean = (strain[0] + strain[1] + strain[2]) / 3.;
      return (strain[0] - mean) * (strain[0] - mean) +
             (strain[1] - mean) * (strain[1] - mean) +
             (strain[2] - mean) * (strain[2] - mean);
    }

    /** The stored energy of principal elastic strains, whose derivative
     * is kirchhoff(): K/2 tr(eps)^2 + G |dev eps|^2 unless a model says
     * otherwise. */
    virtual double
    elastic_energy(const std::array<double, 3> &strain) const;

    const double bulk_modulus;
    const double shear_modulus;
  };
} // namespace dealmpm
