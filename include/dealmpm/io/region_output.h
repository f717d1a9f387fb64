#pragma once

#include <dealmpm/fem/solid_region.h>
#include <dealmpm/io/output_settings.h>

#include <string>

namespace dealmpm
{
  /** Write an FEM region on its deformed mesh: nodal displacement and
   * velocity, per cell the mean stress (its 6 components), von Mises
   * stress and internal variables, and the MPI rank, in @p format (see
   * write_pieces()) at @p time. Returns the series entry. Collective (the
   * ghost exchanges come before the files). */
  template <int dim>
  std::string
  write_region_output(const SolidRegion<dim> &region,
                      const std::string      &directory,
                      const std::string      &base,
                      const OutputFormat      format,
                      const double            time);
} // namespace dealmpm
