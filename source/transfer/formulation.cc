#include <dealmpm/transfer/formulation.h>

#include <stdexcept>

namespace dealmpm
{
  std::string
  formulation_pattern()
  {
    return "updated Lagrangian|total Lagrangian";
  }

  Formulation
  parse_formulation(const std::string &name)
  {
    if (name == "updated Lagrangian")
      return Formulation::updated_lagrangian;
    if (name == "total Lagrangian")
      return Formulation::total_lagrangian;
    throw std::invalid_argument("unknown formulation '" + name + "'");
  }

} // namespace dealmpm
