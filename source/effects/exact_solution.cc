#include <dealmpm/effects/exact_solution.h>
#include <dealmpm/materials/material.h>

namespace dealmpm
{
  void
  declare_known_motion(ParameterHandler  &prm,
                       const double       youngs_modulus,
                       const std::string &density,
                       const std::string &amplitude,
                       const std::string &wave_speed,
                       const std::string &amplitude_doc,
                       const std::string &wave_speed_doc)
  {
    declare_elastic_constants(prm, youngs_modulus, 0.3);
    prm.declare_entry("Density",
                      density,
                      Patterns::Double(),
                      "The material's reference density.");
    prm.declare_entry("Amplitude",
                      amplitude,
                      Patterns::Double(),
                      amplitude_doc);
    prm.declare_entry("Wave speed",
                      wave_speed,
                      Patterns::Double(),
                      wave_speed_doc);
  }
} // namespace dealmpm
