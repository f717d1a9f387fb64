#include <dealmpm/schemes/update_scheme.h>

#include <stdexcept>

namespace dealmpm
{
  UpdateScheme
  parse_update_scheme(const std::string &name)
  {
    if (name == "USL")
      return UpdateScheme::USL;
    if (name == "USF")
      return UpdateScheme::USF;
    if (name == "MUSL")
      return UpdateScheme::MUSL;
    throw std::invalid_argument("unknown update scheme '" + name + "'");
  }

  std::string
  update_scheme_pattern()
  {
    return "USL|USF|MUSL";
  }

} // namespace dealmpm
