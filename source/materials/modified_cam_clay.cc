#include <dealmpm/base/scene_reader.h>
#include <dealmpm/materials/modified_cam_clay.h>

#include <cmath>
#include <limits>

namespace dealmpm
{
  namespace
  {
    /**
     * The closest-point return of Modified Cam-Clay in the invariants: the
     * elastic volume strain v (compression positive) and the multiplier g
     * solve
     *   r1 = v - v_trial + g (2 p(v) - p_c(v)) = 0      (volume flow)
     *   r2 = (q(g)^2 / M^2 + p(v) (p(v) - p_c(v))) / p_c(v)^2 = 0  (f = 0)
     * with p(v) = p_r exp(v / kappa*), q(g) = q_trial / (1 + 6 G g / M^2)
     * (the deviatoric flow has the trial's direction) and p_c(v) = p_cn
     * exp((v_trial - v) / (lambda* - kappa*)) (hardening by the plastic
     * volume strain v_trial - v).
     */
    struct CamClayReturn
    {
      double p_r, kappa, hardening, M2, c, v_trial, q_trial, p_cn;

      double
      p(const double v) const
      {
        return p_r * std::exp(v / kappa);
      }
      double
      p_c(const double v) const
      {
        return p_cn * std::exp(hardening * (v_trial - v));
      }
      double
      q(const double g) const
      {
        return q_trial / (1 + c * g);
      }

      std::array<double, 2>
      residual(const double v, const double g) const
      {
        const double pv = p(v), pc = p_c(v), qg = q(g);
        return {{v - v_trial + g * (2 * pv - pc),
                 (qg * qg / M2 + pv * (pv - pc)) / (pc * pc)}};
      }

      /** The isotropic answer, p = p_c, and the g of its volume flow: the
       * start for a step too large for the trial state's (one step from
       * a low reference pressure to a geostatic one). */
      void
      isotropic_start(double &v, double &g) const
      {
        // kappa ln(p_c / p_r) = v with ln p_c linear in v.
        v = (std::log(p_cn / p_r) + hardening * v_trial) /
            (1. / kappa + hardening);
        g = std::max(0., (v_trial - v) / p(v));
      }

      /** Newton's method from (v, g) with a backtracking line search;
       * false if it does not converge in 100 iterations. */
      bool
      solve(double &v, double &g) const
      {
        std::array<double, 2> r = residual(v, g);
        for (unsigned int iteration = 0; iteration < 100; ++iteration)
          {
            if (std::abs(r[0]) <= 1e-13 && std::abs(r[1]) <= 1e-13)
              return g >= 0;
            const double pv = p(v), pc = p_c(v), qg = q(g);
            const double a11 = 1 + g * (2 * pv / kappa + hardening * pc);
            const double a12 = 2 * pv - pc;
            // r2 = f / p_c^2 with dp_c/dv = -hardening p_c.
            const double a21 =
              (pv / kappa * (2 * pv - pc) + hardening * pv * pc) / (pc * pc) +
              2 * hardening * r[1];
            const double a22  = -2 * c * qg * qg / (M2 * (1 + c * g) * pc * pc);
            const double det  = a11 * a22 - a12 * a21;
            const double dv   = -(a22 * r[0] - a12 * r[1]) / det;
            const double dg   = -(a11 * r[1] - a21 * r[0]) / det;
            const double old  = r[0] * r[0] + r[1] * r[1];
            double       step = 1;
            for (unsigned int halving = 0; halving < 30; ++halving, step /= 2)
              {
                const std::array<double, 2> tried =
                  residual(v + step * dv, g + step * dg);
                if (tried[0] * tried[0] + tried[1] * tried[1] < old)
                  break;
              }
            v += step * dv;
            g += step * dg;
            r = residual(v, g);
            if (!std::isfinite(r[0] + r[1]))
              return false;
          }
        return false;
      }
    };
  } // namespace

  template <int dim>
  ModifiedCamClay<dim>::ModifiedCamClay(const CamClayParameters &parameters)
    // The base's constant moduli are those at the reference pressure (its
    // wave_speed(F) of the unstrained soil).
    : HenckyPlasticity<dim>(LameParameters{parameters.reference_pressure /
                                               parameters.swelling_index -
                                             2. / 3. * parameters.shear_modulus,
                                           parameters.shear_modulus})
    , parameters(parameters)
  {}

  template <int dim>
  void
  ModifiedCamClay<dim>::initialize_internal_variables(
    ArrayView<double> internal) const
  {
    HenckyPlasticity<dim>::initialize_internal_variables(internal);
    internal[preconsolidation_index] =
      parameters.overconsolidation_ratio * parameters.reference_pressure;
  }

  template <int dim>
  void
  ModifiedCamClay<dim>::start_history(const Tensor<2, dim>          &F,
                                      const SymmetricTensor<2, dim> &stress,
                                      ArrayView<double> internal) const
  {
    const SymmetricTensor<2, 3> tau =
      determinant(F) * full_stress<dim>(*this, F, stress, internal);
    const double p = -trace(tau) / 3.;
    const double q = std::sqrt(1.5) * deviator(tau).norm();
    const double M = parameters.critical_state_ratio;
    internal[preconsolidation_index] =
      parameters.overconsolidation_ratio * (p + q * q / (M * M * p));
  }

  template <int dim>
  std::vector<FieldDescription>
  ModifiedCamClay<dim>::model_variables() const
  {
    return {{"preconsolidation_pressure", 1}};
  }

  template <int dim>
  double
  ModifiedCamClay<dim>::pressure(const double volume_strain) const
  {
    return parameters.reference_pressure *
           std::exp(volume_strain / parameters.swelling_index);
  }

  template <int dim>
  std::array<double, 3>
  ModifiedCamClay<dim>::kirchhoff(const std::array<double, 3> &strain) const
  {
    const double          trace = strain[0] + strain[1] + strain[2];
    const double          p     = pressure(-trace);
    std::array<double, 3> tau;
    for (unsigned int a = 0; a < 3; ++a)
      tau[a] = -p + 2. * parameters.shear_modulus * (strain[a] - trace / 3.);
    return tau;
  }

  template <int dim>
  double
  ModifiedCamClay<dim>::elastic_energy(
    const std::array<double, 3> &strain) const
  {
    // Measured from the stress-free soil (p -> 0), not from F = I: the
    // unstrained soil holds kappa* p_r, which it gives back when it
    // swells, so the energy put in (and the energy check's scale) counts
    // the reference pressure of a body that starts at it.
    const double trace = strain[0] + strain[1] + strain[2];
    return parameters.swelling_index * pressure(-trace) +
           parameters.shear_modulus * this->deviator_squared(strain);
  }

  template <int dim>
  double
  ModifiedCamClay<dim>::yield_function(const double p,
                                       const double q,
                                       const double p_c) const
  {
    const double M = parameters.critical_state_ratio;
    return q * q / (M * M) + p * (p - p_c);
  }

  template <int dim>
  double
  ModifiedCamClay<dim>::wave_speed_of_state(
    const Tensor<2, dim>   &F,
    ArrayView<const double> internal) const
  {
    // det b_e = J^2 det C_p^-1 gives the elastic volume strain
    // -ln(det b_e) / 2 (stored C_p^-1: xx, yy, zz, xy, xz, yz).
    const double *c                   = internal.data();
    const double  det_inverse_plastic = dim == 2 ?
                                          c[2] * (c[0] * c[1] - c[3] * c[3]) :
                                          c[0] * (c[1] * c[2] - c[5] * c[5]) -
                                           c[3] * (c[3] * c[2] - c[5] * c[4]) +
                                           c[4] * (c[3] * c[5] - c[1] * c[4]);
    const double  volume_strain =
      -(std::log(determinant(F)) + 0.5 * std::log(det_inverse_plastic));
    const double bulk = pressure(volume_strain) / parameters.swelling_index;
    return std::sqrt((bulk + 4. / 3. * parameters.shear_modulus) /
                     this->density);
  }

  template <int dim>
  double
  ModifiedCamClay<dim>::return_to_surface(std::array<double, 3> &strain,
                                          const double,
                                          ArrayView<double> internal) const
  {
    const double          M       = parameters.critical_state_ratio;
    const double          G       = parameters.shear_modulus;
    const double          v_trial = -(strain[0] + strain[1] + strain[2]);
    std::array<double, 3> deviator;
    double                squared = 0;
    for (unsigned int a = 0; a < 3; ++a)
      {
        deviator[a] = strain[a] + v_trial / 3.;
        squared += deviator[a] * deviator[a];
      }
    const double q_trial = 3. * G * std::sqrt(2. / 3. * squared);
    const double p_cn    = internal[preconsolidation_index];
    if (!(yield_function(pressure(v_trial), q_trial, p_cn) > 0))
      return 0;

    const CamClayReturn problem{parameters.reference_pressure,
                                parameters.swelling_index,
                                1. / (parameters.compression_index -
                                      parameters.swelling_index),
                                M * M,
                                6. * G / (M * M),
                                v_trial,
                                q_trial,
                                p_cn};
    double              v = v_trial, g = 0;
    if (!problem.solve(v, g))
      {
        problem.isotropic_start(v, g);
        if (!problem.solve(v, g))
          {
            // Left for the step's check to report with the particle.
            strain.fill(std::numeric_limits<double>::quiet_NaN());
            internal[preconsolidation_index] =
              std::numeric_limits<double>::quiet_NaN();
            return 0;
          }
      }
    internal[preconsolidation_index] = problem.p_c(v);
    const double shrink              = 1. / (1. + problem.c * g);
    double       d_sum               = 0;
    for (unsigned int a = 0; a < 3; ++a)
      {
        const double elastic = -v / 3. + deviator[a] * shrink;
        d_sum += std::pow(strain[a] - elastic, 2);
        strain[a] = elastic;
      }
    return std::sqrt(2. / 3. * d_sum);
  }

  template class ModifiedCamClay<2>;
  template class ModifiedCamClay<3>;

  namespace
  {
    void
    declare_cam_clay_parameters(ParameterHandler &prm)
    {
      // A soft, normally consolidated clay.
      const CamClayParameters clay;
      prm.declare_entry("Critical state ratio",
                        std::to_string(clay.critical_state_ratio),
                        Patterns::Double(),
                        "M = q / p' at the critical state, in (0, 3) "
                        "(6 sin(phi_cs) / (3 - sin(phi_cs)) in triaxial "
                        "compression).");
      prm.declare_entry("Compression index",
                        std::to_string(clay.compression_index),
                        Patterns::Double(),
                        "lambda*: slope of the normal compression line in "
                        "ln(v) - ln(p') (about lambda / (1 + e)), > the "
                        "Swelling index.");
      prm.declare_entry("Swelling index",
                        std::to_string(clay.swelling_index),
                        Patterns::Double(),
                        "kappa*: slope of the swelling lines in ln(v) - "
                        "ln(p'), > 0; the bulk modulus is p' / kappa*.");
      prm.declare_entry("Shear modulus",
                        std::to_string(clay.shear_modulus),
                        Patterns::Double(),
                        "G (Pa), > 0, constant.");
      prm.declare_entry("Reference pressure",
                        std::to_string(clay.reference_pressure),
                        Patterns::Double(),
                        "p_r (Pa), > 0: the mean effective pressure the "
                        "unstrained soil (F = I) carries. A body starts "
                        "there unless it starts geostatic.");
      prm.declare_entry("Overconsolidation ratio",
                        std::to_string(clay.overconsolidation_ratio),
                        Patterns::Double(),
                        "p_c / p_r of the unstrained soil, >= 1 (1: "
                        "normally consolidated). For a body that starts "
                        "geostatic: p_c over that of the yield surface "
                        "through each point's stress at rest (1: normally "
                        "consolidated, on the surface; 1.2-2: lightly "
                        "overconsolidated, inside it).");
    }

    CamClayParameters
    read_cam_clay(SceneReader &reader)
    {
      CamClayParameters clay;
      clay.critical_state_ratio =
        reader.get_in_open_range("Critical state ratio", 0., 3.);
      clay.swelling_index    = reader.get_positive("Swelling index");
      clay.compression_index = reader.get_positive("Compression index");
      if (!(clay.compression_index > clay.swelling_index))
        reader.fail("Compression index", "a number > the Swelling index");
      clay.shear_modulus      = reader.get_positive("Shear modulus");
      clay.reference_pressure = reader.get_positive("Reference pressure");
      clay.overconsolidation_ratio =
        reader.get_double("Overconsolidation ratio");
      if (!(clay.overconsolidation_ratio >= 1))
        reader.fail("Overconsolidation ratio", "a number >= 1");
      return clay;
    }
  } // namespace

  template <int dim>
  void
  add_modified_cam_clay_material(Registry<Material<dim>> &registry)
  {
    registry.add(
      "Modified Cam-Clay",
      "critical-state plasticity for clays on Hencky elasticity: an "
      "elliptic yield surface hardening with the plastic volume strain, "
      "bulk modulus growing with the pressure (Critical state ratio, "
      "Compression index, Swelling index, Shear modulus, Reference "
      "pressure, Overconsolidation ratio).",
      declare_cam_clay_parameters,
      [](SceneReader &reader) -> std::unique_ptr<Material<dim>> {
        return std::make_unique<ModifiedCamClay<dim>>(read_cam_clay(reader));
      });
  }

  template void
  add_modified_cam_clay_material(Registry<Material<2>> &);
  template void
  add_modified_cam_clay_material(Registry<Material<3>> &);
} // namespace dealmpm
