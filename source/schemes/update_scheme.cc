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

  std::vector<Stage>
  stages_of(const UpdateScheme scheme)
  {
    switch (scheme)
      {
        case UpdateScheme::USL:
          // G2P and the stress update share one sweep: both use v*.
          return {Stage::p2g_all,
                  Stage::apply_effects,
                  Stage::grid_update,
                  Stage::g2p_motion_and_stress};
        case UpdateScheme::USF:
          return {Stage::p2g_mass_momentum,
                  Stage::velocity_from_momentum,
                  Stage::g2p_stress,
                  Stage::p2g_force,
                  Stage::apply_effects,
                  Stage::grid_update,
                  Stage::g2p_motion};
        case UpdateScheme::MUSL:
          // Re-mapping the updated particle momentum smooths v* where nodes
          // have little mass (a stressed particle entering an empty cell).
          return {Stage::p2g_all,
                  Stage::apply_effects,
                  Stage::grid_update,
                  Stage::g2p_motion,
                  Stage::p2g_mass_momentum,
                  Stage::velocity_from_momentum,
                  Stage::g2p_stress};
      }
    return {};
  }
} // namespace dealmpm
