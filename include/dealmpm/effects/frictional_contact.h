#pragma once

#include <dealmpm/effects/dissipates_at_nodes.h>
#include <dealmpm/effects/effect.h>

#include <map>
#include <utility>
#include <vector>

namespace dealmpm
{
  /**
   * Frictional contact between bodies (Bardenhagen et al. 2000, 2001), in
   * the multi-velocity-field form of Uintah's FrictionContactBard: each body
   * has its own nodal fields (NodalFieldSet::body; P2G maps each particle to
   * its body's, and G2P reads them), the core fields hold their sums, the
   * centre-of-mass field. Where two or more bodies have mass at a node, each
   * body b with outward normal n_b (from the mass gradients, see
   * Normals) that approaches the centre of mass, (v_b - v_cm) . n_b
   * > 0, loses that normal approach and, by Coulomb's law with its pair's
   * coefficient, up to mu times it of its tangential slip against the
   * centre of mass (sticking when that is enough). With two bodies at a
   * node the normals are opposite and the masses' weighted changes cancel:
   * momentum is kept to round-off. Away from contact each body's field
   * equals the centre-of-mass one, so bodies in contact only where they
   * touch.
   *
   * Each body's force: its internal force plus its mass share of the rest
   * (the external forces other effects put on the core fields). The
   * contact's work is its forces' (m_b times the change over dt) on the
   * velocities the particles then move with: zero for frictionless
   * contact between two bodies, the friction force times the slip left
   * otherwise (its friction part also alone, friction_work()).
   */
  template <int dim>
  class FrictionalContact : public Effect<dim>, public DissipatesAtNodes
  {
  public:
    /** Contact forces between bodies are equal and opposite. */
    bool
    conserves_momentum() const override
    {
      return true;
    }

    enum class Normals
    {
      /** n_b along g_b = sum_{p in b} m_p grad N_i(x_p), which points out
       * of body b (Bardenhagen's) */
      own_mass_gradient,
      /** n_b along g_b - g_others: two bodies at a node get opposite
       * normals */
      difference_of_bodies,
      /** of b and the other body c with the steepest gradient there, the
       * steeper one's: n_b = g_b / |g_b| or -g_c / |g_c| (Nairn's maximum
       * volume gradient, with masses); two bodies get opposite normals */
      steepest_mass_gradient,
    };

    /** @p pair_friction: (b, c) with b < c, 0-based, to mu. */
    FrictionalContact(
      const double                                            friction,
      std::map<std::pair<unsigned int, unsigned int>, double> pair_friction,
      const Normals                                           normals,
      const double separation_check = 0)
      : friction(friction)
      , pair_friction(std::move(pair_friction))
      , normals(normals)
      , separation_check(separation_check)
    {}

    /** With the separation check: each body's particle volume at the
     * nodes. */
    std::vector<FieldDescription>
    nodal_fields_per_body() const override
    {
      if (separation_check > 0)
        return {{"contact volume", 1}};
      return {};
    }

    /** With the separation check: each body's particle volume at the
     * nodes, sum_p V_p N_ip. */
    void
    add_nodal_forces(const EffectContext<dim> &state,
                     NodalFields<dim>         &fields) override;

    void
    grid_changed(const BackgroundGrid<dim> &grid) override;

    bool
    needs_body_fields() const override
    {
      return true;
    }

    /** With friction: under FLIP a block that friction should hold on a
     * base creeps (4 % of its frictionless slide in 0.5 s at h = 1/80;
     * under PIC it holds to its elastic strain). */
    bool
    wants_pic() const override
    {
      bool any = friction > 0;
      for (const auto &item : pair_friction)
        any = any || item.second > 0;
      return any;
    }

    /** Checks the pairs' bodies exist; keeps the boundary conditions, which
     * each body's field obeys as the core one does. */
    void
    setup(const EffectSetup<dim> &setup, SceneReader &reader) override;

    /** Each body's v* and increment (its force and its share of the
     * external ones, the boundary conditions), then contact. */
    void
    after_grid_update(const EffectContext<dim> &state,
                      NodalFields<dim>         &fields) override;

    /** Each body's re-mapped v = p / m, for the stress update. Not
     * corrected for contact again: the particles' velocities carry this
     * step's correction already, and correcting the re-map too made
     * the colliding disks (MUSL, CFL 0.5) gain 15 % of their energy
     * while they pushed apart, against 2.3 % without (0 % at CFL 0.25;
     * USF alike). */
    void
    after_remap(const EffectContext<dim> &state,
                NodalFields<dim>         &fields) override;

    double
    work_done() const override
    {
      return work;
    }

    /** The friction's part of work_done() (this rank's). */
    double
    friction_work() const
    {
      return friction_part;
    }

    /** contact_work (all the corrections took) and friction_work. */
    std::vector<std::pair<std::string, double>>
    statistics_columns() const override
    {
      return {{"contact_work", work}, {"friction_work", friction_part}};
    }

    std::vector<double>
    saved_state() const override
    {
      return {work, friction_part};
    }

    void
    restore_state(const std::vector<double> &state) override
    {
      work          = state.at(0);
      friction_part = state.at(1);
    }

  private:
    /** The coefficient between bodies @p b and @p c. */
    double
    coefficient(const unsigned int b, const unsigned int c) const;

    /**
     * Contact at every locally owned node where bodies meet, on each body's
     * velocity and its FLIP increment. Returns the
     * work of the corrections (see the class), and its friction part.
     */
    std::pair<double, double>
    correct(NodalFieldSet<dim> &set, const double mass_threshold) const;

    /** With the separation check: whether the particles of the bodies
     * @p present at owned node @p i (their volumes at the nodes,
     * @p volumes) fill enough of it to touch; true without it. */
    bool
    filled(const std::vector<const NodalVector *> &volumes,
           const std::vector<unsigned int>        &present,
           const unsigned int                      i) const;

    /** The contact normal of body @p b (not yet of unit length, possibly
     * zero) from its mass gradient @p g_b, that of the body @p other it
     * presses on, @p g_other, and the sum over the bodies at the node,
     * @p gradient_sum, as Normals asks. */
    Tensor<1, dim>
    normal_direction(const unsigned int    b,
                     const Tensor<1, dim> &g_b,
                     const unsigned int    other,
                     const Tensor<1, dim> &g_other,
                     const Tensor<1, dim> &gradient_sum) const;

    /** Coulomb's correction of body @p b's velocity and its increment at
     * owned node @p i against the centre of mass's @p v_cm, along the unit
     * normal @p n, if it approaches; its pair's coefficient with @p other.
     * Adds the correction's work to @p taken, its friction part to
     * @p by_friction. */
    void
    correct_body(NodalFields<dim>     &body,
                 const unsigned int    i,
                 const Tensor<1, dim> &v_cm,
                 const Tensor<1, dim> &n,
                 const unsigned int    b,
                 const unsigned int    other,
                 double               &taken,
                 double               &by_friction) const;

    /** Contact at owned node @p i between the bodies @p present there (two
     * or more): each body's normal against the one it presses on, then its
     * correction. Adds the work as correct_body() does. */
    void
    correct_node(NodalFieldSet<dim>              &set,
                 const unsigned int               i,
                 const std::vector<unsigned int> &present,
                 double                          &taken,
                 double                          &by_friction) const;

    double                                                  friction;
    std::map<std::pair<unsigned int, unsigned int>, double> pair_friction;
    Normals                                                 normals;
    /** Contact at a node only where the bodies' particles fill this
     * fraction of its volume, integral N_i dx (0: everywhere two bodies
     * have mass): Uintah's volume constraint. */
    double separation_check;
    /** integral N_i dx over the grid, per locally owned node. */
    NodalVector                    full_volume;
    const BoundaryConditions<dim> *conditions    = nullptr;
    double                         work          = 0;
    double                         friction_part = 0;
  };

  /** Register "frictional contact" in the effect table: its parameters (section
   * Frictional contact), their reading and checks. */
  template <int dim>
  void
  add_frictional_contact_effect(Registry<Effect<dim>> &registry);
} // namespace dealmpm
