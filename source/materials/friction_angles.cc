#include <dealmpm/materials/friction_angles.h>

#include <cmath>

namespace dealmpm
{
  void
  declare_friction_parameters(ParameterHandler  &prm,
                              const std::string &friction_default,
                              const std::string &friction_documentation,
                              const std::string &cohesion_documentation)
  {
    prm.declare_entry("Friction angle",
                      friction_default,
                      Patterns::Double(),
                      friction_documentation);
    prm.declare_entry("Dilation angle",
                      "0",
                      Patterns::Double(),
                      "Dilation angle psi (degrees), in [0, phi]; psi = "
                      "phi: associative flow.");
    prm.declare_entry("Cohesion",
                      "0",
                      Patterns::Double(),
                      cohesion_documentation);
  }

  std::array<double, 2>
  read_friction_angles(SceneReader &reader)
  {
    const double friction = reader.get_double("Friction angle");
    if (!(friction >= 0 && friction < 90))
      reader.fail("Friction angle", "an angle in [0, 90) degrees");
    const double dilation = reader.get_double("Dilation angle");
    if (!(dilation >= 0 && dilation <= friction))
      reader.fail("Dilation angle", "an angle in [0, Friction angle] degrees");
    return {{friction * M_PI / 180., dilation * M_PI / 180.}};
  }
} // namespace dealmpm
