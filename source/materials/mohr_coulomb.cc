#include <dealmpm/materials/friction_angles.h>
#include <dealmpm/materials/mohr_coulomb.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

namespace dealmpm
{
  namespace
  {
    using Principal = std::array<double, 3>;

    /** D n of the isotropic stiffness in principal space:
     * lambda (sum n) + 2 G n. */
    Principal
    stiffness_times(const double lambda, const double G, const Principal &n)
    {
      const double sum = n[0] + n[1] + n[2];
      return {{lambda * sum + 2 * G * n[0],
               lambda * sum + 2 * G * n[1],
               lambda * sum + 2 * G * n[2]}};
    }

    double
    dot(const Principal &a, const Principal &b)
    {
      return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    /** A plane a . tau <= r in principal space with flow direction n. */
    struct Plane
    {
      Principal a, n;
      double    r;
    };

    /**
     * The closest point (in the energy norm of the flow) of @p tau on one
     * or two planes, all active: tau -= sum d_gamma_j D n_j with
     * a_i . tau = r_i. Returns false, leaving @p tau as it was, when a
     * multiplier is negative.
     */
    bool
    return_to_planes(Principal                  &tau,
                     const std::array<Plane, 2> &planes,
                     const unsigned int          m,
                     const double                lambda,
                     const double                G)
    {
      Eigen::Matrix2d          A = Eigen::Matrix2d::Identity();
      Eigen::Vector2d          f = Eigen::Vector2d::Zero();
      std::array<Principal, 2> Dn;
      for (unsigned int j = 0; j < m; ++j)
        Dn[j] = stiffness_times(lambda, G, planes[j].n);
      for (unsigned int i = 0; i < m; ++i)
        {
          f[i] = dot(planes[i].a, tau) - planes[i].r;
          for (unsigned int j = 0; j < m; ++j)
            A(i, j) = dot(planes[i].a, Dn[j]);
        }
      const Eigen::Vector2d d_gamma = A.partialPivLu().solve(f);
      for (unsigned int j = 0; j < m; ++j)
        if (d_gamma[j] < 0)
          return false; // tau untouched
      for (unsigned int j = 0; j < m; ++j)
        for (unsigned int a = 0; a < 3; ++a)
          tau[a] -= d_gamma[j] * Dn[j][a];
      return true;
    }

    bool
    sorted(const Principal &tau, const double tolerance)
    {
      return tau[0] >= tau[1] - tolerance && tau[1] >= tau[2] - tolerance;
    }
  } // namespace

  template <int dim>
  MohrCoulomb<dim>::MohrCoulomb(const LameParameters        &lame,
                                const MohrCoulombParameters &mc)
    : HenckyPlasticity<dim>(lame)
    , parameters(mc)
    , softening_strain_here(mc.softening_strain)
    , peak(softened(0.))
    , residual(softened(std::numeric_limits<double>::infinity()))
  {}

  template <int dim>
  void
  MohrCoulomb<dim>::set_cell_size(const double h)
  {
    Assert(h > 0, ExcMessage("a cell size must be positive"));
    if (needs_cell_size())
      softening_strain_here =
        parameters.softening_strain * parameters.regularisation_length / h;
  }

  template <int dim>
  typename MohrCoulomb<dim>::Strength
  MohrCoulomb<dim>::softened(const double plastic_strain) const
  {
    const MohrCoulombParameters &p = parameters;
    const double                 s = p.softening_strain > 0 ?
                                       std::min(plastic_strain / softening_strain_here, 1.) :
                                       0.;
    const double                 phi =
      p.friction_angle + s * (p.residual_friction_angle - p.friction_angle);
    const double psi =
      p.dilation_angle + s * (p.residual_dilation_angle - p.dilation_angle);
    const double c = p.cohesion + s * (p.residual_cohesion - p.cohesion);
    return {std::sin(phi),
            std::sin(psi),
            2 * c * std::cos(phi),
            phi > 0 ? c / std::tan(phi) : 0.};
  }

  template <int dim>
  double
  MohrCoulomb<dim>::yield_function(std::array<double, 3> tau,
                                   const double          plastic_strain) const
  {
    std::sort(tau.begin(), tau.end(), std::greater<double>());
    return sorted_yield_function(tau, strength(plastic_strain));
  }

  template <int dim>
  void
  MohrCoulomb<dim>::return_mohr_coulomb(std::array<double, 3> &tau,
                                        const Strength        &strength) const
  {
    const double sin_phi = strength.sin_phi, sin_psi = strength.sin_psi;
    const double two_c_cos_phi = strength.two_c_cos_phi;
    if (!(sorted_yield_function(tau, strength) > 0))
      return;
    const double G      = this->shear_modulus;
    const double lambda = this->bulk_modulus - 2. * G / 3.;
    const double up = 1 + sin_phi, down = 1 - sin_phi;
    const double up_psi = 1 + sin_psi, down_psi = 1 - sin_psi;
    const Plane main{{{up, 0, -down}}, {{up_psi, 0, -down_psi}}, two_c_cos_phi};
    // The neighbouring planes across the edges tau_1 = tau_2 (triaxial
    // compression) and tau_2 = tau_3 (triaxial extension).
    const Plane  compression{{{0, up, -down}},
                            {{0, up_psi, -down_psi}},
                            two_c_cos_phi};
    const Plane  extension{{{up, -down, 0}},
                          {{up_psi, -down_psi, 0}},
                          two_c_cos_phi};
    const double tolerance =
      1e-12 * (std::abs(tau[0]) + std::abs(tau[2]) + two_c_cos_phi);

    Principal on_plane = tau;
    if (return_to_planes(on_plane, {{main, main}}, 1, lambda, G) &&
        sorted(on_plane, tolerance))
      {
        tau = on_plane;
        return;
      }
    const Plane &second  = on_plane[1] > on_plane[0] ? compression : extension;
    Principal    on_edge = tau;
    if (return_to_planes(on_edge, {{main, second}}, 2, lambda, G) &&
        sorted(on_edge, tolerance))
      {
        tau = on_edge;
        return;
      }
    // The apex (Tresca, phi = 0, has none: its edges always hold).
    const double apex =
      sin_phi > 0 ? strength.apex : (tau[0] + tau[1] + tau[2]) / 3.;
    tau = {{apex, apex, apex}};
  }

  template <int dim>
  void
  MohrCoulomb<dim>::return_tension_cut_off(std::array<double, 3> &tau) const
  {
    const double T = parameters.tension_cut_off;
    if (!(tau[0] > T))
      return;
    const double G      = this->shear_modulus;
    const double lambda = this->bulk_modulus - 2. * G / 3.;
    const Plane  first{{{1, 0, 0}}, {{1, 0, 0}}, T};
    const Plane  second{{{0, 1, 0}}, {{0, 1, 0}}, T};
    Principal    returned = tau;
    return_to_planes(returned, {{first, first}}, 1, lambda, G);
    if (returned[1] > T)
      {
        returned = tau;
        if (!return_to_planes(returned, {{first, second}}, 2, lambda, G))
          returned = {{T, T, T}};
      }
    if (returned[2] > T)
      returned = {{T, T, T}};
    tau = returned;
  }

  template <int dim>
  double
  MohrCoulomb<dim>::return_to_surface(std::array<double, 3> &strain,
                                      const double,
                                      ArrayView<double> internal) const
  {
    const double          plastic_strain = this->plastic_strain(internal);
    std::array<double, 3> tau            = this->kirchhoff(strain);
    const bool            plastic =
      yield_function(tau, plastic_strain) > 0 ||
      *std::max_element(tau.begin(), tau.end()) > parameters.tension_cut_off;
    if (!plastic)
      return 0;

    // Sort descending, return, and put the stresses back in their
    // principal directions.
    std::array<unsigned int, 3> order = {{0, 1, 2}};
    std::sort(order.begin(), order.end(), [&](unsigned int i, unsigned int j) {
      return tau[i] > tau[j];
    });
    Principal sorted_tau = {{tau[order[0]], tau[order[1]], tau[order[2]]}};
    return_mohr_coulomb(sorted_tau, strength(plastic_strain));
    return_tension_cut_off(sorted_tau);

    const double K = this->bulk_modulus, G = this->shear_modulus;
    const double mean  = (sorted_tau[0] + sorted_tau[1] + sorted_tau[2]) / 3.;
    double       d_sum = 0, d_plastic[3];
    for (unsigned int k = 0; k < 3; ++k)
      {
        const double elastic =
          mean / (3. * K) + (sorted_tau[k] - mean) / (2. * G);
        d_plastic[k]     = strain[order[k]] - elastic;
        strain[order[k]] = elastic;
        d_sum += d_plastic[k] * d_plastic[k];
      }
    return std::sqrt(2. / 3. * d_sum);
  }

  template class MohrCoulomb<2>;
  template class MohrCoulomb<3>;

  namespace
  {
    void
    declare_mohr_coulomb_parameters(ParameterHandler &prm)
    {
      // A dense sand.
      declare_elastic_constants(prm, 50e6, 0.3);
      declare_friction_parameters(
        prm,
        "30",
        "Friction angle phi (degrees), in [0, 90); 0: Tresca.",
        "Cohesion c (Pa), >= 0; 0: no tension (the apex at zero stress). "
        "Tresca (phi = 0) needs c > 0.");
      prm.declare_entry("Tension cut-off",
                        "false",
                        Patterns::Bool(),
                        "Cap every principal stress at the Tensile strength "
                        "(Rankine), below Mohr-Coulomb's own apex c cot(phi).");
      prm.declare_entry("Tensile strength",
                        "0",
                        Patterns::Double(),
                        "T (Pa), >= 0: the largest principal stress with the "
                        "Tension cut-off.");
      prm.declare_entry(
        "Softening strain",
        "0",
        Patterns::Double(0),
        "Equivalent plastic strain at which the strength has fallen "
        "linearly from the peak (Cohesion, Friction angle, Dilation angle) "
        "to the residual values below; 0: no softening. Softening localises "
        "in a band about a cell wide, so that this strain belongs to the "
        "cell size it was chosen for: a finer grid softens faster, unless "
        "a Regularisation length is given.");
      prm.declare_entry(
        "Regularisation length",
        "0",
        Patterns::Double(0),
        "The width of the shear band (m) the Softening strain was "
        "measured on (a laboratory test's band, or the cell size a "
        "calibration used); > 0: on a grid of cell edge h the softening "
        "strain is Softening strain * length / h, so that the band's "
        "displacement at the residual strength, and the load after the "
        "peak, do not depend on the grid (the smallest cell's edge; not "
        "with adaptivity or in an FEM region). 0: none.");
      prm.declare_entry("Residual cohesion",
                        "0",
                        Patterns::Double(0),
                        "c_r (Pa), <= Cohesion, with a Softening strain.");
      prm.declare_entry("Residual friction angle",
                        "0",
                        Patterns::Double(0),
                        "phi_r (degrees), <= Friction angle, with a "
                        "Softening strain.");
      prm.declare_entry("Residual dilation angle",
                        "0",
                        Patterns::Double(0),
                        "psi_r (degrees), <= Residual friction angle and "
                        "<= Dilation angle, with a Softening strain.");
    }

    /** The residual strength of a softening material (its checks). */
    void
    read_softening(SceneReader &reader, MohrCoulombParameters &mc)
    {
      mc.softening_strain = reader.get_nonnegative("Softening strain");
      mc.regularisation_length =
        reader.get_nonnegative("Regularisation length");
      if (!(mc.softening_strain > 0))
        {
          if (mc.regularisation_length > 0)
            reader.fail("Regularisation length",
                        "0 without a Softening strain (it scales the "
                        "softening strain)");
          return;
        }
      const double degree  = M_PI / 180.;
      mc.residual_cohesion = reader.get_nonnegative("Residual cohesion");
      mc.residual_friction_angle =
        reader.get_nonnegative("Residual friction angle") * degree;
      mc.residual_dilation_angle =
        reader.get_nonnegative("Residual dilation angle") * degree;
      if (mc.residual_cohesion > mc.cohesion)
        reader.fail("Residual cohesion", "at most the Cohesion");
      if (mc.residual_friction_angle > mc.friction_angle)
        reader.fail("Residual friction angle", "at most the Friction angle");
      if (mc.residual_dilation_angle > mc.residual_friction_angle ||
          mc.residual_dilation_angle > mc.dilation_angle)
        reader.fail("Residual dilation angle",
                    "at most the Residual friction angle and the Dilation "
                    "angle");
      if (mc.residual_friction_angle == 0 && !(mc.residual_cohesion > 0))
        reader.fail("Residual cohesion",
                    "a positive number when Residual friction angle is 0");
    }

    MohrCoulombParameters
    read_mohr_coulomb(SceneReader &reader)
    {
      MohrCoulombParameters mc;
      const auto            angles = read_friction_angles(reader);
      mc.friction_angle            = angles[0];
      mc.dilation_angle            = angles[1];
      mc.cohesion                  = reader.get_nonnegative("Cohesion");
      if (mc.friction_angle == 0 && !(mc.cohesion > 0))
        reader.fail("Cohesion", "a positive number when Friction angle is 0");
      const double strength = reader.get_nonnegative("Tensile strength");
      if (reader.get_bool("Tension cut-off"))
        mc.tension_cut_off = strength;
      read_softening(reader, mc);
      return mc;
    }
  } // namespace

  template <int dim>
  void
  add_mohr_coulomb_material(Registry<Material<dim>> &registry)
  {
    registry.add(
      "Mohr-Coulomb",
      "non-associative Mohr-Coulomb plasticity on Hencky elasticity, "
      "perfectly plastic or softening with the plastic strain, "
      "principal-stress return to a plane, an edge or the apex, optional "
      "tension cut-off (Young's modulus, Poisson's ratio, Friction angle, "
      "Dilation angle, Cohesion, Tension cut-off, Tensile strength, "
      "Softening strain, Residual cohesion, Residual friction angle, "
      "Residual dilation angle, Regularisation length); for soils and "
      "rock.",
      declare_mohr_coulomb_parameters,
      [](SceneReader &reader) -> std::unique_ptr<Material<dim>> {
        const LameParameters lame = read_elastic_constants(reader);
        return std::make_unique<MohrCoulomb<dim>>(lame,
                                                  read_mohr_coulomb(reader));
      });
  }

  template void
  add_mohr_coulomb_material(Registry<Material<2>> &);
  template void
  add_mohr_coulomb_material(Registry<Material<3>> &);
} // namespace dealmpm
