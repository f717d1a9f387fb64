#include <dealmpm/effects/manufactured_solution.h>
#include <dealmpm/materials/material.h>

#include <cmath>

namespace dealmpm
{
  template <int dim>
  ManufacturedSolution<dim>::ManufacturedSolution(const LameParameters &lame,
                                                  const double          density,
                                                  const double amplitude,
                                                  const double wave_speed)
    : lame(lame)
    , density(density)
    , amplitude(amplitude)
    , wave_speed(wave_speed)
  {}

  template <int dim>
  double
  ManufacturedSolution<dim>::phase(const unsigned int i)
  {
    return 2. * M_PI * i / 3.;
  }

  template <int dim>
  Tensor<1, dim>
  ManufacturedSolution<dim>::exact_displacement(const Point<dim> &X,
                                                const double      t) const
  {
    Tensor<1, dim> u;
    for (unsigned int i = 0; i < dim; ++i)
      u[i] = amplitude * std::sin(M_PI * X[i]) *
             std::sin(wave_speed * M_PI * t + phase(i));
    return u;
  }

  template <int dim>
  Tensor<1, dim>
  ManufacturedSolution<dim>::body_force(const Point<dim> &X,
                                        const double      t) const
  {
    // F = diag(1 + A pi cos(pi X_i) sin(c pi t + phi_i)).
    const Tensor<1, dim> u = exact_displacement(X, t);
    Tensor<1, dim>       F_ii;
    double               J = 1;
    for (unsigned int i = 0; i < dim; ++i)
      {
        F_ii[i] = 1. + amplitude * M_PI * std::cos(M_PI * X[i]) *
                         std::sin(wave_speed * M_PI * t + phase(i));
        J *= F_ii[i];
      }
    Tensor<1, dim> b;
    for (unsigned int i = 0; i < dim; ++i)
      b[i] = M_PI * M_PI * u[i] *
             (lame.mu / density - wave_speed * wave_speed -
              (lame.lambda * (std::log(J) - 1.) - lame.mu) /
                (density * F_ii[i] * F_ii[i]));
    return b;
  }

  template <int dim>
  void
  ManufacturedSolution<dim>::initialize_particles(
    ParticleSet<dim> &particles) const
  {
    // The particles were made at their reference positions X; at t = 0 the
    // body is already deformed: x = X + u(X, 0), F = diag(F_ii), the
    // neo-Hookean stress of that F, and v(X, 0).
    const CoreFields &f = particles.fields;
    for (auto &p : particles.handler)
      {
        const Point<dim>     X = p.get_location();
        const Tensor<1, dim> u = exact_displacement(X, 0.);
        Tensor<2, dim>       F;
        Tensor<1, dim>       v;
        for (unsigned int i = 0; i < dim; ++i)
          {
            F[i][i] = 1. + amplitude * M_PI * std::cos(M_PI * X[i]) *
                             std::sin(phase(i));
            v[i] = amplitude * wave_speed * M_PI * std::sin(M_PI * X[i]) *
                   std::cos(phase(i));
          }
        const double                  J = determinant(F);
        const SymmetricTensor<2, dim> B = symmetrize(F * transpose(F));
        const SymmetricTensor<2, dim> stress =
          (lame.mu / J) * (B - unit_symmetric_tensor<dim>()) +
          (lame.lambda * std::log(J) / J) * unit_symmetric_tensor<dim>();
        const auto props = p.get_properties();
        write_vector<dim>(&props[f.velocity], v);
        write_vector<dim>(&props[f.displacement], u);
        write_tensor<dim>(&props[f.deformation_gradient], F);
        write_symmetric<dim>(&props[f.stress], stress);
        p.set_location(X + u);
      }
  }

  template class ManufacturedSolution<2>;
  template class ManufacturedSolution<3>;

  template <int dim>
  void
  add_manufactured_solution_effect(Registry<Effect<dim>> &registry)
  {
    registry.add(
      "manufactured solution",
      "the axis-aligned manufactured solution of Wallstedt and Guilkey "
      "(2008) on the unit square/cube: initial velocity, body force and "
      "exact displacement for error norms (section Manufactured solution: "
      "Amplitude, Wave speed, and the neo-Hookean material's Young's "
      "modulus, Poisson's ratio and Density).",
      [](ParameterHandler &prm) {
        declare_known_motion(prm,
                             1e4,
                             "1",
                             "0.05",
                             "100",
                             "Displacement amplitude A.",
                             "c in sin(c pi t + phi): the period is 2 / c.");
      },
      [](SceneReader &reader) -> std::unique_ptr<Effect<dim>> {
        return std::make_unique<ManufacturedSolution<dim>>(
          read_elastic_constants(reader),
          reader.get_positive("Density"),
          reader.get_positive("Amplitude"),
          reader.get_positive("Wave speed"));
      });
  }

  template void
  add_manufactured_solution_effect(Registry<Effect<2>> &);
  template void
  add_manufactured_solution_effect(Registry<Effect<3>> &);
} // namespace dealmpm
