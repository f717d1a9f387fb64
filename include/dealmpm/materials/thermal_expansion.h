#pragma once

#include <dealmpm/materials/material.h>

#include <memory>
#include <optional>
#include <string>

namespace dealmpm
{
  /**
   * A material that expands with its temperature: any model (@p inner)
   * driven by the mechanical part of the motion, F = F_m theta, theta the
   * isotropic thermal stretch. The model sees F_m = F / theta and the
   * velocity gradient L - (d ln theta / dt) I, so that a hyperelastic, a
   * rate-form and a plastic model alike feel only the mechanical strain.
   * Heat conduction sets theta: the stretch grows by stretch_per_kelvin()
   * times each temperature increment, so a body is stress-free at its
   * initial temperature.
   *
   * In 3D theta = 1 + alpha (T - T_0), exact for every model. In 2D
   * (plane strain, F_zz = 1) the out-of-plane thermal strain is held by
   * the plane: for isotropic elasticity that is an in-plane stretch of
   * (1 + nu) alpha per kelvin and sigma_zz lowered by E alpha (T - T_0)
   * = 2 mu (theta - 1), exact at small strain (and the in-plane
   * equivalent for a plastic model's flow), with nu and mu of the
   * model's initial response (initial_elastic_constants()).
   *
   * Energy: the stress does work on the thermal stretch, J tr(sigma) d
   * ln theta per unit reference volume, which the model's stored energy
   * (per unit volume of the stress-free state, theta^dim its reference
   * volume) does not count: it is kept as (negative) dissipated work, so
   * the energy balance of a heated, constrained body closes. Internal
   * variables: the model's, then thermal_stretch, stretch_at_update (the
   * theta of the last stress update) and thermal_work, each name with
   * @p suffix.
   */
  /**
   * The isotropic elastic constants of @p model's response to a small
   * uniaxial strain eps = -1e-7 from its initial state: lambda = d
   * sigma_yy / eps, mu = (d sigma_xx - d sigma_yy) / (2 eps), d the change
   * from the unstrained state's stress (Modified Cam-Clay's reference
   * pressure: its moduli there). None when they
   * are not finite, lambda + 2 mu <= 0, mu < 0 or nu outside [-1, 0.5]
   * (within 1e-6): a model with no elastic response there.
   */
  template <int dim>
  std::optional<LameParameters>
  initial_elastic_constants(const Material<dim> &model);

  template <int dim>
  class ThermallyExpanding : public Material<dim>
  {
  public:
    /** @p alpha: the linear expansion coefficient (1/K). In 2D @p inner
     * must have initial_elastic_constants(). */
    ThermallyExpanding(std::unique_ptr<Material<dim>> inner,
                       const double                   alpha,
                       const std::string             &suffix);

    /** The growth of theta per kelvin: alpha in 3D, (1 + nu) alpha in
     * 2D. */
    double
    stretch_per_kelvin() const
    {
      return per_kelvin;
    }

    /** Where theta sits among the internal variables. */
    unsigned int
    stretch_index() const
    {
      return n_inner;
    }

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
    wave_speed(const Tensor<2, dim> &F) const override
    {
      return inner->wave_speed(F);
    }

    double
    wave_speed_of_state(const Tensor<2, dim>   &F,
                        ArrayView<const double> internal) const override
    {
      return inner->wave_speed_of_state(F / internal[n_inner], own(internal));
    }

    double
    out_of_plane_stress(const Tensor<2, dim>          &F,
                        const SymmetricTensor<2, dim> &stress,
                        ArrayView<const double>        internal) const override;

    /** The model's, at F_m, times theta^dim. */
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

    /** Not renormalised: a replaced F would carry theta into the model's
     * own state. */
    bool
    renormalises_deformation() const override
    {
      return false;
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

  private:
    ArrayView<const double>
    own(const ArrayView<const double> &internal) const
    {
      return make_array_view(internal.begin(), internal.begin() + n_inner);
    }

    std::unique_ptr<Material<dim>> inner;
    std::string                    suffix;
    unsigned int                   n_inner = 0;
    bool                           inner_dissipates;
    double                         per_kelvin;
    /** 2 mu (2D: sigma_zz's thermal part is -2 mu (theta - 1)). */
    double two_mu = 0;
  };
} // namespace dealmpm
