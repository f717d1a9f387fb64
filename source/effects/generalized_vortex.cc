#include <dealmpm/effects/generalized_vortex.h>

#include <cmath>

namespace dealmpm
{
  namespace
  {
    /** h(R) and its first two derivatives. */
    struct Profile
    {
      double h, dh, ddh;
    };

    Profile
    profile(const double R)
    {
      const double s = R - 1.;
      return {1. - 32. * s * s + 256. * s * s * s * s,
              -64. * s + 1024. * s * s * s,
              -64. + 3072. * s * s};
    }
  } // namespace

  template <int dim>
  GeneralizedVortex<dim>::GeneralizedVortex(const double mu,
                                            const double density,
                                            const double amplitude,
                                            const double wave_speed)
    : mu(mu)
    , density(density)
    , amplitude(amplitude)
    , wave_speed(wave_speed)
  {
    AssertThrow(dim == 2, ExcNotImplemented());
  }

  template <int dim>
  Tensor<1, dim>
  GeneralizedVortex<dim>::exact_displacement(const Point<dim> &X,
                                             const double      t) const
  {
    const double R     = std::hypot(X[0], X[1]);
    const double Theta = std::atan2(X[1], X[0]);
    const double alpha =
      amplitude * std::sin(wave_speed * M_PI * t) * profile(R).h;
    Tensor<1, dim> u;
    u[0] = R * std::cos(Theta + alpha) - X[0];
    u[1] = R * std::sin(Theta + alpha) - X[1];
    return u;
  }

  template <int dim>
  Tensor<1, dim>
  GeneralizedVortex<dim>::body_force(const Point<dim> &X, const double t) const
  {
    const double  R        = std::hypot(X[0], X[1]);
    const double  Theta    = std::atan2(X[1], X[0]);
    const Profile p        = profile(R);
    const double  w        = wave_speed * M_PI;
    const double  alpha    = amplitude * std::sin(w * t) * p.h;
    const double  alpha_t  = amplitude * w * std::cos(w * t) * p.h;
    const double  alpha_tt = -amplitude * w * w * std::sin(w * t) * p.h;
    const double  alpha_R  = amplitude * std::sin(w * t) * p.dh;
    const double  alpha_RR = amplitude * std::sin(w * t) * p.ddh;
    const double  b_R =
      -R * alpha_t * alpha_t + (mu / density) * R * alpha_R * alpha_R;
    const double b_theta =
      R * alpha_tt - (mu / density) * (R * alpha_RR + 3. * alpha_R);
    // Polar components at the current angle.
    const double   theta = Theta + alpha;
    Tensor<1, dim> b;
    b[0] = b_R * std::cos(theta) - b_theta * std::sin(theta);
    b[1] = b_R * std::sin(theta) + b_theta * std::cos(theta);
    return b;
  }

  template <int dim>
  void
  GeneralizedVortex<dim>::initialize_particles(
    ParticleSet<dim> &particles) const
  {
    // v_theta = R d(alpha)/dt at t = 0, tangential.
    for (auto &p : particles.handler)
      {
        const Point<dim> X   = p.get_location();
        const double     R   = std::hypot(X[0], X[1]);
        const double v_theta = R * amplitude * wave_speed * M_PI * profile(R).h;
        p.get_properties()[particles.fields.velocity]     = -v_theta * X[1] / R;
        p.get_properties()[particles.fields.velocity + 1] = v_theta * X[0] / R;
      }
  }

  template class GeneralizedVortex<2>;
  template class GeneralizedVortex<3>;

  template <int dim>
  void
  add_generalized_vortex_effect(Registry<Effect<dim>> &registry)
  {
    registry.add(
      "generalized vortex",
      "the generalized vortex on the annulus 0.75 < R < 1.25 (2D): "
      "initial velocity, body force and exact displacement for error "
      "norms (section Generalized vortex: Amplitude, Wave speed, and the "
      "neo-Hookean material's Young's modulus, Poisson's ratio and "
      "Density).",
      [](ParameterHandler &prm) {
        declare_known_motion(prm,
                             1e3,
                             "1000",
                             "1",
                             "1",
                             "A in alpha = A sin(c pi t) h(R).",
                             "c in sin(c pi t): the period is 2 / c.");
      },
      [](SceneReader &reader) -> std::unique_ptr<Effect<dim>> {
        if (dim != 2)
          reader.fail("Amplitude",
                      "Dimension = 2: the generalized vortex is a 2D problem");
        return std::make_unique<GeneralizedVortex<dim>>(
          read_elastic_constants(reader).mu,
          reader.get_positive("Density"),
          reader.get_positive("Amplitude"),
          reader.get_positive("Wave speed"));
      });
  }

  template void
  add_generalized_vortex_effect(Registry<Effect<2>> &);
  template void
  add_generalized_vortex_effect(Registry<Effect<3>> &);
} // namespace dealmpm
