#include <dealmpm/effects/absorbing_boundary.h>
#include <dealmpm/effects/base_shaking.h>
#include <dealmpm/effects/boundary_friction.h>
#include <dealmpm/effects/damage.h>
#include <dealmpm/effects/effect.h>
#include <dealmpm/effects/frictional_contact.h>
#include <dealmpm/effects/generalized_vortex.h>
#include <dealmpm/effects/gravity.h>
#include <dealmpm/effects/heat_conduction.h>
#include <dealmpm/effects/local_damping.h>
#include <dealmpm/effects/manufactured_solution.h>
#include <dealmpm/effects/rigid_body.h>
#include <dealmpm/effects/rotating_frame.h>
#include <dealmpm/effects/traction.h>

#include <cctype>

namespace dealmpm
{
  std::string
  section_title(const std::string &name)
  {
    std::string title = name;
    if (!title.empty())
      title[0] = std::toupper(title[0]);
    return title;
  }

  /* The built-in effects: each file registers its own (its parameters,
   * their reading and checks) in the table built on first use. */
  template <int dim>
  Registry<Effect<dim>> &
  effect_registry()
  {
    static Registry<Effect<dim>> registry = [] {
      Registry<Effect<dim>> r;
      add_gravity_effect(r);
      add_boundary_friction_effect(r);
      add_local_damping_effect(r);
      add_absorbing_boundary_effect(r);
      add_base_shaking_effect(r);
      add_rigid_body_effect(r);
      add_traction_effect(r);
      add_rotating_frame_effect(r);
      add_frictional_contact_effect(r);
      add_manufactured_solution_effect(r);
      add_generalized_vortex_effect(r);
      add_damage_effect(r);
      add_heat_conduction_effect(r);
      return r;
    }();
    return registry;
  }

#define DEALMPM_INSTANTIATE(dim) \
  template Registry<Effect<dim>> &effect_registry<dim>();
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
