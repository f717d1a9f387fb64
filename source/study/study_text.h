#pragma once

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

namespace dealmpm
{
  /** A number for the study's tables and messages: empty when not known
   * (the NaN of a run that failed early). */
  inline std::string
  number(const double x, const int precision = 4)
  {
    if (!std::isfinite(x))
      return "";
    std::ostringstream s;
    s << std::setprecision(precision) << x;
    return s.str();
  }
} // namespace dealmpm
