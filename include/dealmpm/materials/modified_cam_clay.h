#pragma once

#include <dealmpm/materials/geostatic_history.h>
#include <dealmpm/materials/hencky_plasticity.h>

namespace dealmpm
{
  /** Parameters of Modified Cam-Clay (pressures in Pa, compression
   * positive). */
  struct CamClayParameters
  {
    /** M: the stress ratio q / p' of the critical state. */
    double critical_state_ratio = 0.9;
    /** lambda*: the slope of the normal compression line in ln v - ln p'
     * (about lambda / (1 + e) of the e - ln p' form). */
    double compression_index = 0.1;
    /** kappa*: the slope of the swelling lines in ln v - ln p'. */
    double swelling_index = 0.02;
    /** G: the shear modulus, constant (the elasticity is hyperelastic). */
    double shear_modulus = 3e6;
    /** p_r: the mean effective pressure of the unstrained soil (F = I). */
    double reference_pressure = 100e3;
    /** p_c / p_r of the unstrained soil, >= 1; for a body that starts
     * geostatic, p_c over the p_c of the yield surface through its stress
     * at rest (1: normally consolidated, on the surface). */
    double overconsolidation_ratio = 1;
  };

  /**
   * Modified Cam-Clay (Roscoe and Burland 1968) at finite strain on the
   * Hencky frame (HenckyPlasticity), in the form of Borja and Tamagnini
   * (1998) with constant shear modulus.
   *
   * With p = -tr(tau) / 3 and q = sqrt(3/2) |dev tau| from the Kirchhoff
   * stress tau and the logarithmic elastic strain eps_e:
   * - elasticity: p = p_r exp(eps_v / kappa*) with eps_v = -tr(eps_e)
   *   (the bulk modulus p / kappa* grows with the pressure) and
   *   dev tau = 2 G dev eps_e; stored energy kappa* p + G |dev eps_e|^2
   *   = kappa* p_r exp(eps_v / kappa*) + G |dev eps_e|^2, counted from
   *   the stress-free soil (p -> 0): kappa* p_r at F = I;
   * - yield surface f = q^2 / M^2 + p (p - p_c), an ellipse through the
   *   origin and p_c, with associated flow;
   * - hardening by the plastic volume strain (compression positive):
   *   p_c = p_c0 exp(eps_v^p / (lambda* - kappa*)).
   * Isotropic virgin compression then follows ln J = -lambda* ln(p / p_c0)
   * (the normal compression line in ln v - ln p', Butterfield 1979) and
   * unloading ln J = -kappa* ln(p / p_0). The soil carries no tension
   * (p > 0 always). The return is a closest-point projection on (eps_v,
   * Delta gamma) by Newton's method with a backtracking line search,
   * started from the trial state and, when that does not converge (a step
   * far past the surface, as from a low reference pressure to a geostatic
   * one), once more from the isotropic answer p = p_c; a return that
   * still does not converge leaves a non-finite state, which the step
   * reports.
   *
   * Internal variables: HenckyPlasticity's, then the preconsolidation
   * pressure p_c.
   */
  template <int dim>
  class ModifiedCamClay : public HenckyPlasticity<dim>,
                          public GeostaticHistory<dim>
  {
  public:
    explicit ModifiedCamClay(const CamClayParameters &parameters);

    /** p_c = overconsolidation ratio * (p + q^2 / (M^2 p)), the yield
     * surface through the Kirchhoff stress J sigma at rest (isotropic
     * overconsolidation: the ellipse grows about its shape). */
    void
    start_history(const Tensor<2, dim>          &F,
                  const SymmetricTensor<2, dim> &stress,
                  ArrayView<double>              internal) const override;

    void
    initialize_internal_variables(ArrayView<double> internal) const override;

    /** The elastic P-wave speed sqrt((p / kappa* + 4 G / 3) / rho0) at the
     * pressure of the state's elastic volume strain. */
    double
    wave_speed_of_state(const Tensor<2, dim>   &F,
                        ArrayView<const double> internal) const override;

    /** f of a Kirchhoff pressure @p p and equivalent stress @p q at the
     * preconsolidation pressure @p p_c. */
    double
    yield_function(const double p, const double q, const double p_c) const;

    /** Where p_c sits among the internal variables. */
    static constexpr unsigned int preconsolidation_index =
      HenckyPlasticity<dim>::model_index;

  protected:
    double
    return_to_surface(std::array<double, 3> &strain,
                      const double           dt,
                      ArrayView<double>      internal) const override;

    std::vector<FieldDescription>
    model_variables() const override;

    std::array<double, 3>
    kirchhoff(const std::array<double, 3> &strain) const override;

    double
    elastic_energy(const std::array<double, 3> &strain) const override;

  private:
    /** p of the elastic volume strain eps_v (compression positive). */
    double
    pressure(const double volume_strain) const;

    CamClayParameters parameters;
  };

  /** Register "Modified Cam-Clay" in the material table: its parameters
   * (subsection "Modified Cam-Clay" of a "Material N" section), their
   * reading and checks. */
  template <int dim>
  void
  add_modified_cam_clay_material(Registry<Material<dim>> &registry);
} // namespace dealmpm
