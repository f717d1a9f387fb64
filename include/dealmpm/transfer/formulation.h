#pragma once

#include <string>

namespace dealmpm
{
  /**
   * Where the momentum balance is written ('MPM/Formulation').
   *
   * Updated Lagrangian (the usual MPM): rho dv/dt = div sigma + rho b on
   * the current configuration; the shape functions are evaluated at the
   * particles' current positions every step, and particles change cells.
   *
   * Total Lagrangian (de Vaucorbeil, Nguyen and Hutchinson 2020, "A
   * Total-Lagrangian Material Point Method for solid mechanics problems
   * involving large deformations", CMAME 360:112783; Karamelo's TLMPM):
   * rho0 dv/dt =
   * Div P + rho0 b on the reference configuration, P = J sigma F^-T. The
   * stencil (N_I(X_p), Grad N_I(X_p)) is made once at the particles'
   * reference positions X_p and kept: a particle never changes cell or
   * rank, so there is no cell-crossing error and no relocation.
   * f_int,I = -sum_p V_p0 P_p Grad N_I, F_{n+1} = F_n + dt sum_I v_I (x)
   * Grad N_I. Particles interact only with those that share grid nodes
   * with them in the reference configuration: no contact between bodies
   * that start apart, no flow past neighbours (fluids), and walls act only
   * where the body touches them at the start.
   */
  enum class Formulation
  {
    updated_lagrangian,
    total_lagrangian
  };

  /** "updated Lagrangian|total Lagrangian" */
  std::string
  formulation_pattern();

  Formulation
  parse_formulation(const std::string &name);

} // namespace dealmpm
