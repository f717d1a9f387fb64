#pragma once

#include <dealmpm/effects/effect.h>

namespace dealmpm
{
  /** Register "local damping" in the effect table: its parameters (section
   * Local damping), their reading and checks. */
  template <int dim>
  void
  add_local_damping_effect(Registry<Effect<dim>> &registry);
} // namespace dealmpm
