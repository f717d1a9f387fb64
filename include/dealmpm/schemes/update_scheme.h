#pragma once

#include <string>

namespace dealmpm
{
  /** When the stress is updated relative to the momentum update. */
  enum class UpdateScheme
  {
    USL,  ///< update stress last: with v* of this step
    USF,  ///< update stress first: with v = p / m at the start of the step
    MUSL, ///< modified USL: with v* re-mapped from the updated particles
  };

  UpdateScheme
  parse_update_scheme(const std::string &name);

  /** "USL|USF|MUSL" */
  std::string
  update_scheme_pattern();

} // namespace dealmpm
