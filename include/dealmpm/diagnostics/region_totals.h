#pragma once

#include <dealmpm/diagnostics/statistics.h>
#include <dealmpm/fem/fem_regions.h>

#include <vector>

namespace dealmpm
{
  /** Add the FEM regions' totals to @p s (computed for the particles):
   * the coupled system's mass, momentum and energies, and each region's
   * columns. */
  template <int dim>
  void
  add_region_totals(const std::vector<RegionTotals<dim>> &regions,
                    Statistics                           &s)
  {
    for (const RegionTotals<dim> &t : regions)
      {
        s.mass += t.mass;
        for (unsigned int d = 0; d < dim; ++d)
          s.momentum[d] += t.momentum[d];
        s.kinetic_energy += t.kinetic_energy;
        s.strain_energy += t.strain_energy;
        s.gravitational_energy += t.gravitational_energy;
        if (t.dissipates)
          {
            s.has_dissipated_work = true;
            s.dissipated_work += t.dissipated_work;
          }
        s.effect_columns.insert(s.effect_columns.end(),
                                t.columns.begin(),
                                t.columns.end());
        s.effect_values.insert(s.effect_values.end(),
                               t.values.begin(),
                               t.values.end());
      }
  }
} // namespace dealmpm
