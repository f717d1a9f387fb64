#pragma once

#include <dealmpm/materials/cell_size_dependent.h>
#include <dealmpm/materials/hencky_plasticity.h>

#include <limits>

namespace dealmpm
{
  /** Parameters of Mohr-Coulomb plasticity (angles in radians). */
  struct MohrCoulombParameters
  {
    double friction_angle = 0;
    double dilation_angle = 0;
    double cohesion       = 0;
    /** The largest principal stress allowed (Pa); +infinity: no cut-off. */
    double tension_cut_off = std::numeric_limits<double>::infinity();
    /** Strain softening: the cohesion and the friction and dilation angles
     * fall linearly with the equivalent plastic strain, from the values
     * above at 0 to these residual ones at softening_strain, and stay
     * there; softening_strain = 0: none (the residual values unused). */
    double softening_strain        = 0;
    double residual_friction_angle = 0;
    double residual_dilation_angle = 0;
    double residual_cohesion       = 0;
    /** The width of the band softening_strain belongs to (m); > 0: the
     * softening strain on a grid of cell edge h is softening_strain *
     * regularisation_length / h (the same displacement across a band one
     * cell wide on every grid); 0: softening_strain on every grid. */
    double regularisation_length = 0;
  };

  /**
   * Non-associative Mohr-Coulomb plasticity, perfectly plastic, on the
   * Hencky frame (HenckyPlasticity). The return works on the sorted
   * principal Kirchhoff stresses tau_1 >= tau_2 >= tau_3 (tension
   * positive) with f = (tau_1 - tau_3) + (tau_1 + tau_3) sin(phi)
   * - 2 c cos(phi) and the potential with psi for phi: to the main plane,
   * to one of its two edges (tau_1 = tau_2, triaxial compression, or
   * tau_2 = tau_3, triaxial extension) or to the apex (de Souza Neto et
   * al. 2008, Boxes 8.4 and 8.5; Clausen et al. 2006). The optional tension
   * cut-off (Rankine, tau_a <= T) returns after the Mohr-Coulomb return,
   * which it keeps admissible: it only lowers f.
   *
   * With softening, a step returns to the strength of the plastic strain
   * the step starts from (explicit in the softening: the step's own
   * plastic strain softens the next step). Softening localises in a band
   * about a cell wide, so that the load after the peak depends on the
   * cell size: the softening strain is a property of the band's width,
   * and a finer grid softens faster (doc/guide/materials.md). With a
   * regularisation length the softening strain is scaled by it over the
   * cell size (set_cell_size()), which keeps the displacement across the
   * band at which the residual strength is reached, and so the load
   * against displacement after the peak, the same on every grid.
   */
  template <int dim>
  class MohrCoulomb : public HenckyPlasticity<dim>, public CellSizeDependent
  {
  public:
    MohrCoulomb(const LameParameters &lame, const MohrCoulombParameters &mc);

    bool
    needs_cell_size() const override
    {
      return parameters.regularisation_length > 0;
    }

    /** The softening strain becomes softening_strain * regularisation
     * length / h. */
    void
    set_cell_size(const double h) override;

    /** The equivalent plastic strain at which the residual strength is
     * reached on this grid. */
    double
    softening_strain() const
    {
      return softening_strain_here;
    }

    /** f of sorted or unsorted principal stresses (the largest pair), with
     * the strength at equivalent plastic strain @p plastic_strain (the
     * peak at 0). */
    double
    yield_function(std::array<double, 3> tau,
                   const double          plastic_strain = 0) const;

  protected:
    double
    return_to_surface(std::array<double, 3> &strain,
                      const double           dt,
                      ArrayView<double>      internal) const override;

  private:
    /** The surface's constants at an equivalent plastic strain. */
    struct Strength
    {
      double sin_phi, sin_psi, two_c_cos_phi;
      double apex; ///< c cot(phi); Tresca (phi = 0) has none
    };
    /** The peak's before any plastic strain and without softening, the
     * residual's past the softening strain (both computed once: most
     * points of a scene are at one or the other, and the sines and
     * cosines cost more than the rest of an elastic step). */
    Strength
    strength(const double plastic_strain) const
    {
      if (!(parameters.softening_strain > 0 && plastic_strain > 0))
        return peak;
      return plastic_strain < softening_strain_here ? softened(plastic_strain) :
                                                      residual;
    }
    Strength
    softened(const double plastic_strain) const;

    /** f of principal stresses sorted largest first. */
    static double
    sorted_yield_function(const std::array<double, 3> &tau,
                          const Strength              &strength)
    {
      return tau[0] - tau[2] + (tau[0] + tau[2]) * strength.sin_phi -
             strength.two_c_cos_phi;
    }

    /** Return sorted principal stresses to the Mohr-Coulomb surface. */
    void
    return_mohr_coulomb(std::array<double, 3> &tau,
                        const Strength        &strength) const;

    /** Return sorted principal stresses to tau_a <= T. */
    void
    return_tension_cut_off(std::array<double, 3> &tau) const;

    MohrCoulombParameters parameters;
    /** parameters.softening_strain, scaled to the cell size with a
     * regularisation length. */
    double   softening_strain_here;
    Strength peak, residual;
  };

  /** Register "Mohr-Coulomb" in the material table: its parameters (subsection
   * "Mohr-Coulomb" of a "Material N" section), their reading and checks. */
  template <int dim>
  void
  add_mohr_coulomb_material(Registry<Material<dim>> &registry);
} // namespace dealmpm
