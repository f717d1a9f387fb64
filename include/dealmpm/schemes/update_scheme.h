#pragma once

#include <string>
#include <vector>

namespace dealmpm
{
  /** When the stress is updated relative to the momentum update. */
  enum class UpdateScheme
  {
    USL,  ///< update stress last: with v* of this step
    USF,  ///< update stress first: with v = p / m at the start of the step
    MUSL, ///< modified USL: with v* re-mapped from the updated particles
  };

  /**
   * The stages of one explicit step. Every scheme is an order of these, run
   * by Simulation::advance(); none has a loop of its own.
   */
  enum class Stage
  {
    p2g_all,                ///< mass, momentum and internal force
    p2g_mass_momentum,      ///< mass and momentum
    p2g_force,              ///< internal force with the current stress
    apply_effects,          ///< external and adjusted nodal forces
    grid_update,            ///< v* = v + dt f / m, boundary conditions
    velocity_from_momentum, ///< v = p / m, boundary conditions
    g2p_motion_and_stress,  ///< one sweep: velocity, position, F, stress
    g2p_motion,             ///< particle velocity and position from v*
    g2p_stress,             ///< F and stress from the nodal velocity
  };

  UpdateScheme
  parse_update_scheme(const std::string &name);

  /** "USL|USF|MUSL" */
  std::string
  update_scheme_pattern();

  std::vector<Stage>
  stages_of(const UpdateScheme scheme);
} // namespace dealmpm
