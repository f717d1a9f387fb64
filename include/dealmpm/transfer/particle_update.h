#pragma once

#include <string>

namespace dealmpm
{
  /**
   * How the particles advance from the grid's acceleration ('MPM/Particle
   * update').
   *
   * explicit: the usual MPM update, v_p += dt sum N a_i and x_p += dt sum
   * N v_i; the particle velocity is a half step out of phase with its
   * position, so velocities (and kinetic energy) carry an O(dt) error.
   *
   * Newmark: Newmark's formulas (Newmark 1959)
   *   x_{n+1} = x_n + dt v_n + dt^2 [(1/2 - beta) a_n + beta a_{n+1}],
   *   v_{n+1} = v_n + dt [(1 - gamma) a_n + gamma a_{n+1}],
   * with a_p = sum N a_i, in the explicit predictor-corrector form of Hughes
   * and Liu (1978, J. Appl. Mech. 45:371): the grid's force is evaluated at
   * the predicted position x~_{n+1} = x_n + dt v_n + dt^2 (1/2 - beta) a_n,
   * which is the particle's location, so each step keeps one force
   * evaluation and the explicit stable step. The particle's displacement
   * velocity over the step, d_p = (x~_{n+1} - x~_n) / dt, is re-mapped to
   * the grid (as MUSL re-maps momentum), so that positions and F follow the
   * same nodal field. gamma = 1/2 adds no numerical damping; gamma > 1/2
   * damps the highest frequencies at first order. beta enters only the
   * first step and the difference between the stored position x~ and
   * Newmark's x, x = x~ + beta dt^2 a: second order either way, but only
   * with beta = 0 (central differences, the default) is the stored
   * position Newmark's own, so that positions, velocities and energies
   * agree from the first step. With beta > 0 the first step moves the
   * body by dt^2 (1/2 - beta) a while the velocity gains dt a: an energy
   * mismatch of the order of the energy put in during the first steps,
   * which the energy-growth check may take for growth when it runs then.
   */
  struct ParticleUpdate
  {
    bool   newmark = false;
    double beta    = 0;
    double gamma   = 0.5;

    /** "explicit|Newmark" */
    static std::string
    pattern()
    {
      return "explicit|Newmark";
    }
  };

  /**
   * The coefficients of one Newmark step of size h after one of size g (g
   * = 0 at the first step, where the particles carry the initial velocity
   * v_0). Between steps a particle stores its velocity v_n (corrected with
   * the acceleration of the step before, a second-order estimate) and that
   * acceleration a. In a step:
   * - P2G maps the predicted velocity v~ = v - predictor_offset a;
   * - the grid gives a_p = sum N (v*_i - v_i) / h, including the walls'
   *   reactions as in FLIP;
   * - the particle's displacement velocity is d = v~ + displacement a_p,
   *   re-mapped to the grid to move the particle and update F;
   * - its velocity becomes d + reported a_p.
   * With g = h this is v~_{n+1} = v~_n + h a_n (FLIP's increment) and d =
   * v~_n + (gamma + 1/2) h a_n.
   */
  struct NewmarkStep
  {
    NewmarkStep(const ParticleUpdate &u, const double h, const double g)
      : predictor_offset(u.gamma * g)
      , displacement(u.beta * g * g / h + u.gamma * g + (0.5 - u.beta) * h)
      , reported(h * (0.5 + u.beta * (1. - (g / h) * (g / h))))
    {}

    double predictor_offset;
    double displacement;
    double reported;
  };
} // namespace dealmpm
