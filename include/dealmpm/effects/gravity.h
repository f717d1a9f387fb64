#pragma once

#include <dealmpm/effects/effect.h>

namespace dealmpm
{
  /** Register "gravity" in the effect table: its parameters (section
   * Gravity), their reading and checks. */
  template <int dim>
  void
  add_gravity_effect(Registry<Effect<dim>> &registry);
} // namespace dealmpm
