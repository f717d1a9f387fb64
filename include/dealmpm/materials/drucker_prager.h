#pragma once

#include <dealmpm/materials/hencky_plasticity.h>

namespace dealmpm
{
  /** The cone of a Drucker-Prager model: f = sqrt(J2) + eta p - xi c,
   * plastic potential sqrt(J2) + eta_bar p (p the mean stress, tension
   * positive). */
  struct DruckerPragerCone
  {
    double eta;      ///< friction
    double eta_bar;  ///< dilation
    double xi;       ///< cohesion factor
    double cohesion; ///< c (Pa)

    /**
     * The cone matched to Mohr-Coulomb's friction angle phi, dilation angle
     * psi (radians) and cohesion c: 'plane strain' (the same collapse loads
     * in plane strain: eta = 3 tan(phi) / sqrt(9 + 12 tan^2(phi)), xi =
     * 3 / sqrt(9 + 12 tan^2(phi))), 'outer cone' (through the compressive
     * meridian: eta = 6 sin(phi) / (sqrt(3) (3 - sin(phi)))) or 'inner cone'
     * (through the tensile meridian: 3 + sin(phi)); eta_bar likewise from
     * psi.
     */
    static DruckerPragerCone
    matched(const std::string &matching,
            const double       friction_angle,
            const double       dilation_angle,
            const double       cohesion);
  };

  /**
   * Non-associative Drucker-Prager plasticity, perfectly plastic, on the
   * Hencky frame (HenckyPlasticity): the return to the smooth cone, or to
   * its apex where the cone return would cross it (de Souza Neto et al.
   * 2008, Box 8.9, in the logarithmic elastic strain). For soils and
   * granular flows; with c = 0 the material carries no tension.
   */
  template <int dim>
  class DruckerPrager : public HenckyPlasticity<dim>
  {
  public:
    DruckerPrager(const LameParameters &lame, const DruckerPragerCone &cone);

  protected:
    double
    return_to_surface(std::array<double, 3> &strain,
                      const double           dt,
                      ArrayView<double>      internal) const override;

  private:
    DruckerPragerCone cone;
  };

  /** Register "Drucker-Prager" in the material table: its parameters
   * (subsection "Drucker-Prager" of a "Material N" section), their reading and
   * checks. */
  template <int dim>
  void
  add_drucker_prager_material(Registry<Material<dim>> &registry);
} // namespace dealmpm
