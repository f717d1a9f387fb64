// Plane strain (2D) has an out-of-plane stress sigma_zz: pressure and von
// Mises stress, as a user computes them from the written 3 x 3 tensor, must
// match the 3D twin. A column settled under gravity between slip walls
// (nu = 0.3, laterally confined in every direction): the vertical stress is
// -rho g (H - Y), both horizontal ones nu / (1 - nu) of it, in 2D and in
// 3D. With sigma_zz written as 0 the 2D pressure was 14 % of rho g H off.
#include <gtest/gtest.h>

#include <cmath>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  constexpr double rho = 1000, g = 9.81, H = 4, nu = 0.3;

  std::string
  column(const unsigned int dim, const std::string &model)
  {
    const std::string walls  = dim == 2 ? "0: slip, 1: slip, 2: slip" :
                                          "0: slip, 1: slip, 2: slip, 3: slip, "
                                          "4: slip";
    const std::string across = dim == 2 ? "0.25, " : "0.25, 0.25, ";
    const std::string zero   = dim == 2 ? "0, " : "0, 0, ";
    return "set Dimension = " + std::to_string(dim) +
           "\nset Effects = gravity, local damping\n"
           "subsection Grid\n set Lower corner = " +
           zero + "0\n set Upper corner = " + across +
           "5\n set Cells = " + (dim == 2 ? "1, 20" : "1, 1, 20") +
           "\n set Boundary conditions = " + walls +
           "\nend\n"
           "subsection Material 1\n set Model = " +
           model + "\n set Density = 1000\n subsection " + model +
           "\n  set Young's modulus = 1e7\n  set Poisson's ratio = 0.3\n "
           "end\nend\n"
           "subsection Body 1\n set Lower corner = " +
           zero + "0\n set Upper corner = " + across +
           "4\nend\n"
           "subsection Gravity\n set Acceleration = " +
           zero +
           "-9.81\nend\n"
           "subsection Local damping\n set Coefficient = 0.15\nend\n";
  }

  /** Mean and largest |pressure - exact| and |von Mises - exact| over the
   * particles, relative to rho g H, once the column has settled. */
  template <int dim>
  std::array<double, 4>
  stress_invariant_errors(const std::string &model)
  {
    auto simulation = test::make_simulation<dim>(column(dim, model));
    while (simulation->time() < 3.)
      simulation->advance(simulation->time_step());
    const auto           &particles = simulation->particle_set();
    const CoreFields     &f         = particles.fields;
    const Material<dim>  &material  = simulation->material(0);
    std::array<double, 4> errors{};
    double                n = 0;
    for (const auto &p : particles.handler)
      {
        const auto   props = p.get_properties();
        const double Y =
          p.get_location()[dim - 1] - props[f.displacement + dim - 1];
        const SymmetricTensor<2, 3> sigma = full_stress<dim>(
          material,
          read_tensor<dim>(&props[f.deformation_gradient]),
          read_symmetric<dim>(&props[f.stress]),
          ArrayView<const double>(&props[particles.internal_offset[0]],
                                  particles.n_internal[0]));
        const double vertical   = -rho * g * (H - Y);
        const double horizontal = nu / (1 - nu) * vertical;
        const double pressure   = -trace(sigma) / 3;
        const double von_mises  = std::sqrt(1.5) * deviator(sigma).norm();
        const double pressure_error =
          std::abs(pressure + (vertical + 2 * horizontal) / 3) / (rho * g * H);
        const double von_mises_error =
          std::abs(von_mises - std::abs(vertical - horizontal)) / (rho * g * H);
        errors[0] += pressure_error;
        errors[1] = std::max(errors[1], pressure_error);
        errors[2] += von_mises_error;
        errors[3] = std::max(errors[3], von_mises_error);
        n += 1;
      }
    errors[0] /= n;
    errors[2] /= n;
    return errors;
  }
} // namespace

TEST(PlaneStrainStress, PressureAndVonMisesMatchThe3DTwin)
{
  for (const std::string model : {"linear elastic", "neo-Hookean"})
    {
      const auto plane = stress_invariant_errors<2>(model);
      const auto solid = stress_invariant_errors<3>(model);
      std::cout << "plane strain, " << model
                << ": pressure error / (rho g H) mean " << plane[0] << " max "
                << plane[1] << " (3D " << solid[0] << ", " << solid[1]
                << "); von Mises mean " << plane[2] << " max " << plane[3]
                << " (3D " << solid[2] << ", " << solid[3] << ")" << std::endl;
      // The 3D twin's own discretisation error bounds what 2D may show.
      for (unsigned int i = 0; i < 4; ++i)
        {
          EXPECT_LT(solid[i], 0.05) << model << ' ' << i;
          EXPECT_LT(plane[i], std::max(0.02, 1.5 * solid[i]))
            << model << ' ' << i;
        }
    }
}
