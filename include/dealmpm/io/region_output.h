#pragma once

#include <dealmpm/fem/solid_region.h>

#include <string>

namespace dealmpm
{
  /** Write an FEM region on its deformed mesh: nodal displacement and
   * velocity, per cell the mean stress (its 6 components), von Mises
   * stress and internal variables, and the MPI rank; files
   * <base>.<rank>.vtu and <base>.pvtu in @p directory. Returns the .pvtu's
   * name. Collective (the ghost exchanges come before the files). */
  template <int dim>
  std::string
  write_region_output(const SolidRegion<dim> &region,
                      const std::string      &directory,
                      const std::string      &base);
} // namespace dealmpm
