#pragma once

#include <dealmpm/materials/material.h>

#include <memory>
#include <string>

namespace dealmpm
{
  /** When a point starts to fail and when it has failed. */
  struct DamageLaw
  {
    enum class Measure
    {
      principal_strain, ///< largest principal stretch - 1
      principal_stress  ///< largest principal effective stress (3 x 3)
    };
    Measure measure = Measure::principal_strain;
    double  onset   = 0; ///< the measure where damage starts
    double  failure = 0; ///< where it reaches 1 (>= onset; = onset: brittle)

    /** D for a measure @p q: 0 below the onset, linear up to 1. */
    double
    damage(double q) const;
  };

  /**
   * A material that fails: any model (the undamaged one, @p inner) whose
   * stress is scaled by (1 - D), D the largest damage the point has seen
   * (irreversible). The model itself advances its effective stress, kept
   * among the internal variables: an incremental model would otherwise
   * start each step from the softened stress and soften it again. The
   * strain energy is (1 - D) times the model's, the energy released as D
   * grows (the model's energy times dD) is dissipated work, and so is the
   * model's own dissipation (times 1 - D, the share the softened stress
   * did). Internal variables: the model's, then damage, effective_stress
   * and damage_work (each name with @p suffix, so that two damaged models
   * keep separate storage).
   */
  template <int dim>
  class DamagedMaterial : public Material<dim>
  {
  public:
    DamagedMaterial(std::unique_ptr<Material<dim>> inner,
                    const DamageLaw               &law,
                    const std::string             &suffix);

    std::vector<FieldDescription>
    internal_variables() const override;

    void
    initialize_internal_variables(ArrayView<double> internal) const override;

    void
    update_stress(const Tensor<2, dim>    &L,
                  const Tensor<2, dim>    &F,
                  double                   dt,
                  SymmetricTensor<2, dim> &stress,
                  ArrayView<double>        internal) const override;

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
    dissipated_energy_density(ArrayView<const double> internal) const override;

    bool
    dissipates() const override
    {
      return true;
    }

    bool
    resets_deformation() const override
    {
      return inner->resets_deformation();
    }

    bool
    renormalises_deformation() const override
    {
      return inner->renormalises_deformation();
    }

    /** The inner model's, on its variables (the damage and the effective
     * stress are spatial: F' leaves them). */
    void
    renormalise_deformation(Tensor<2, dim>   &F,
                            ArrayView<double> internal) const override
    {
      inner->renormalise_deformation(
        F, make_array_view(internal.begin(), internal.begin() + n_inner));
    }

    bool
    locks_in_linear_cells() const override
    {
      return inner->locks_in_linear_cells();
    }

    bool
    particles_take_f_bar() const override
    {
      return inner->particles_take_f_bar();
    }

    /** The wrapped model. */
    Material<dim> &
    inner_model()
    {
      return *inner;
    }
    const Material<dim> &
    inner_model() const
    {
      return *inner;
    }

    /** Where D sits among the internal variables. */
    unsigned int
    damage_index() const
    {
      return n_inner;
    }

    /** Points of this rank that reached D = 1 since the last call (the
     * erosion sweeps only in steps that have some). */
    unsigned int
    take_newly_failed() const
    {
      const unsigned int n = newly_failed;
      newly_failed         = 0;
      return n;
    }

  private:
    /** The wrapped model's own internal variables. */
    ArrayView<const double>
    inner_variables(const ArrayView<const double> &internal) const
    {
      return make_array_view(internal.begin(), internal.begin() + n_inner);
    }

    /** The effective stress: the stored one while undamaged. */
    SymmetricTensor<2, dim>
    effective_stress(const SymmetricTensor<2, dim> &stress,
                     ArrayView<const double>        internal) const;

    std::unique_ptr<Material<dim>> inner;
    DamageLaw                      law;
    std::string                    suffix;
    unsigned int                   n_inner;
    bool                           inner_dissipates;
    /** The stress update runs on one thread per rank. */
    mutable unsigned int newly_failed = 0;
  };
} // namespace dealmpm
