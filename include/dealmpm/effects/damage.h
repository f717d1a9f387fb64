#pragma once

#include <dealmpm/effects/effect.h>
#include <dealmpm/materials/damaged_material.h>

#include <set>
#include <vector>

namespace dealmpm
{
  /**
   * Damage and erosion: the listed materials fail (DamagedMaterial: their
   * stress softens by 1 - D as a strain or stress measure passes a
   * threshold), and their fully failed particles (D = 1) are removed at the
   * end of the step or kept, stress-free. Kept, they conserve mass and
   * momentum; removed, what they carried (mass, momentum, kinetic energy
   * and dissipated work) goes to the statistics' eroded_* columns, and
   * their energy leaves the balance as work (eroded_energy), so that it
   * still closes.
   */
  template <int dim>
  class Damage : public Effect<dim>
  {
  public:
    bool
    reads_stencil() const override
    {
      return false;
    }

    struct Settings
    {
      std::set<unsigned int> materials; ///< 0-based; empty: all
      DamageLaw              law;
      bool                   erode = true;
    };

    explicit Damage(const Settings &settings);

    void
    wrap_materials(MaterialSections<dim> &materials,
                   SceneReader           &reader) override;

    void
    after_g2p(const EffectContext<dim> &state,
              ParticleSet<dim>         &particles) override;

    double
    work_done() const override
    {
      return -eroded[eroded_energy];
    }

    double
    removed_mass() const override
    {
      return eroded[eroded_mass];
    }

    Tensor<1, dim>
    removed_momentum() const override
    {
      Tensor<1, dim> P;
      for (unsigned int d = 0; d < dim; ++d)
        P[d] = eroded[eroded_momentum + d];
      return P;
    }

    /** Erosion's momentum counts as removed. */
    bool
    conserves_momentum() const override
    {
      return true;
    }

    std::vector<std::pair<std::string, double>>
    statistics_columns() const override;

    std::vector<double>
    saved_state() const override
    {
      std::vector<double> state = eroded;
      state.push_back(failed_kept);
      return state;
    }

    void
    restore_state(const std::vector<double> &state) override
    {
      eroded.assign(state.begin(), state.end() - 1);
      failed_kept = state.back();
    }

  private:
    enum Eroded : unsigned int
    {
      eroded_particles,
      eroded_mass,
      eroded_energy,
      eroded_momentum, ///< then dim components
    };

    Settings settings;
    /** Per material: its damaged model, or nullptr. */
    std::vector<const DamagedMaterial<dim> *> damaged;
    /** Running sums over the removed particles of this rank. */
    std::vector<double> eroded;
    /** Particles that reached D = 1 and were kept, counted on the rank
     * where they failed (the statistics sum the ranks). */
    double failed_kept = 0;
  };

  /** Register "damage" in the effect table. */
  template <int dim>
  void
  add_damage_effect(Registry<Effect<dim>> &registry);
} // namespace dealmpm
