#pragma once

#include <dealmpm/base/smallest_stretch.h>
#include <dealmpm/grid/background_grid.h>
#include <dealmpm/materials/material.h>
#include <dealmpm/particles/particle_set.h>
#include <dealmpm/transfer/gimp_windows.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <type_traits>
#include <typeinfo>
#include <vector>

namespace dealmpm
{
  /**
   * What the stress stage learns about the particles on the way: the
   * largest signal rate (c_p + |v_p|) / h for the CFL time step and the
   * particle that has it, the smallest J, and the first particle whose state
   * is unusable (non-finite, or J <= 0).
   */
  template <int dim>
  struct ParticleCheck
  {
    double                max_signal_rate = 0;
    double                min_J           = std::numeric_limits<double>::max();
    bool                  failed          = false;
    types::particle_index particle        = 0;
    Point<dim>            location;
    std::string           reason;
    /** The particle with the largest signal rate. */
    types::particle_index fastest = 0;
    Point<dim>            fastest_location;
    /** cpGIMP on windows: every stretched domain still fits them
     * (StressUpdate::watch_domains()). */
    bool domains_fit = true;

    /** Fold one particle into the check; false when its state is
     * unusable. @p material is a Material<dim>, or the final model class
     * the caller knows it to be (StressUpdate::Of); @p internal is the
     * particle's state in it. */
    template <typename Accessor, typename Model>
    DEAL_II_ALWAYS_INLINE inline bool
    inspect(const Accessor                &p,
            const Tensor<1, dim>          &v,
            const Tensor<2, dim>          &F,
            const SymmetricTensor<2, dim> &stress,
            const Model                   &material,
            ArrayView<const double>        internal,
            const double                   h)
    {
      const double J = determinant(F);
      min_J          = std::min(min_J, J);
      double sum     = J + v.norm_square();
      for (unsigned int i = 0;
           i < SymmetricTensor<2, dim>::n_independent_components;
           ++i)
        sum += stress.access_raw_entry(i);
      for (unsigned int d = 0; d < dim; ++d)
        sum += p.get_location()[d];
      if (!std::isfinite(sum))
        fail(p,
             "non-finite position, velocity, deformation gradient or stress");
      else if (!(J > 0.))
        fail(
          p,
          "deformation gradient with J <= 0 (the particle turned inside out: "
          "time step too large, or cell crossing and tiny nodal masses; try a "
          "smaller CFL number)");
      else
        {
          const double rate =
            (material.wave_speed_of_state(F, internal) + v.norm()) / h;
          if (rate > max_signal_rate)
            {
              max_signal_rate  = rate;
              fastest          = p.get_id();
              fastest_location = p.get_location();
            }
          return true;
        }
      return false;
    }

    /**
     * Add to the reason of the failed particle @p id its material and the
     * state its stress update left: the material's section, F and each
     * internal variable by name (a local solve that did not converge shows
     * here as a non-finite state). Out of line and cold: the sweep that
     * calls it pays only the branch.
     */
    [[gnu::cold, gnu::noinline]] void
    describe_state(const types::particle_index id,
                   const unsigned int          material_index,
                   const Material<dim>        &material,
                   const Tensor<2, dim>       &F,
                   ArrayView<const double>     internal)
    {
      if (!failed || particle != id || described)
        return;
      described = true;
      std::ostringstream text;
      text.precision(6);
      text << "; in 'Material " << material_index + 1 << "', F = [";
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          text << (j == 0 ? (i == 0 ? "[" : ", [") : ", ") << F[i][j]
               << (j + 1 == dim ? "]" : "");
      text << ']';
      unsigned int k = 0;
      for (const FieldDescription &field : material.internal_variables())
        {
          text << (k == 0 ? ", state after its update: " : ", ") << field.name
               << " =";
          for (unsigned int c = 0; c < field.n_components; ++c, ++k)
            text << ' ' << internal[k];
        }
      reason += text.str();
    }

  private:
    bool described = false;

    template <typename Accessor>
    void
    fail(const Accessor &p, const char *why)
    {
      if (failed)
        return;
      failed   = true;
      particle = p.get_id();
      location = p.get_location();
      reason   = why;
    }
  };

  /**
   * The stress update of one particle with its material, from the velocity
   * gradient and the updated F of G2P; folds the particle into a
   * ParticleCheck. Passed to grid_to_particle() so it runs in the same sweep.
   */
  template <int dim>
  class StressUpdate
  {
  public:
    /** @p keeps_reference (total Lagrangian): F is the map from the
     * reference configuration, never renormalised. */
    StressUpdate(const std::vector<std::unique_ptr<Material<dim>>> &materials,
                 const ParticleSet<dim>                            &particles,
                 const double                                       dt,
                 const bool keeps_reference = false)
      : materials(materials)
      , particles(particles)
      , dt(dt)
    {
      // A particle set laid out for another list of materials (a unit
      // test pairing its own materials with a scene's particles) has no
      // offsets for these: the slots then hold none, and such a stress
      // update must not update particles. The step state is always made
      // for the scene's own materials and particles.
      laid_out = particles.internal_offset.size() == materials.size();
      for (unsigned int m = 0; m < materials.size(); ++m)
        {
          slots.push_back(
            {materials[m].get(),
             laid_out ? particles.internal_offset[m] : 0,
             laid_out ? particles.n_internal[m] : 0,
             materials[m]->resets_deformation(),
             !keeps_reference && materials[m]->renormalises_deformation()});
          any_resets        = any_resets || slots.back().resets;
          resets_or_watches = any_resets;
          any_renormalise   = any_renormalise || slots.back().renormalises;
        }
      const auto &of_body = particles.material_of_body;
      if (!of_body.empty() &&
          std::all_of(of_body.begin(), of_body.end(), [&](unsigned int m) {
            return m == of_body.front();
          }))
        only_material = of_body.front();
    }

    template <typename Accessor>
    DEAL_II_ALWAYS_INLINE void
    operator()(const Accessor          &p,
               const ArrayView<double> &props,
               const Tensor<2, dim>    &L,
               const Tensor<2, dim>    &F,
               const double             h)
    {
      update<Material<dim>>(p, props, L, F, h);
    }

    /** The update for a sweep in which every material is a @p Model, a
     * final class whose methods are defined in its header: its calls are
     * direct and inlined, and the check shares their arithmetic (J). */
    template <typename Model>
    struct Of
    {
      StressUpdate &stress_update;

      template <typename Accessor>
      DEAL_II_ALWAYS_INLINE void
      operator()(const Accessor          &p,
                 const ArrayView<double> &props,
                 const Tensor<2, dim>    &L,
                 const Tensor<2, dim>    &F,
                 const double             h)
      {
        stress_update.template update<Model>(p, props, L, F, h);
      }
    };

    /** Whether every material of the scene is exactly a @p Model (not a
     * class derived from it). */
    template <typename Model>
    bool
    all_materials_are() const
    {
      for (const auto &m : materials)
        if (typeid(*m) != typeid(Model))
          return false;
      return true;
    }

    /** Check each updated particle's cpGIMP domain, its half-lengths at
     * @p half_length stretched by its F's diagonal as the next step's
     * weights stretch them (GimpWindows), against @p limit
     * (Stencil::gimp_stretch_limit): ParticleCheck::domains_fit. */
    void
    watch_domains(const unsigned int half_length, const Tensor<1, dim> &limit)
    {
      watched_half_length = half_length;
      domain_limit        = limit;
      resets_or_watches   = true;
    }

    ParticleCheck<dim> check;

  private:
    template <typename Model, typename Accessor>
    DEAL_II_ALWAYS_INLINE void
    update(const Accessor          &p,
           const ArrayView<double> &props,
           const Tensor<2, dim>    &L,
           const Tensor<2, dim>    &F,
           const double             h)
    {
      Assert(laid_out,
             ExcMessage("a stress update for particles laid out for other "
                        "materials"));
      const unsigned int m    = only_material != numbers::invalid_unsigned_int ?
                                  only_material :
                                  particles.material_of(props);
      const Slot        &slot = slots[m];
      const Model       &material = static_cast<const Model &>(*slot.material);
      // &props[0], not props.data(), which tests for an empty view.
      const ArrayView<double> internal(&props[0] + slot.internal_offset,
                                       slot.n_internal);
      SymmetricTensor<2, dim> stress =
        read_symmetric<dim>(&props[FixedCore<dim>::stress]);
      material.update_stress(L, F, dt, stress, internal);
      write_symmetric<dim>(&props[FixedCore<dim>::stress], stress);
      if (!check.inspect(p,
                         read_vector<dim>(&props[FixedCore<dim>::velocity]),
                         F,
                         stress,
                         material,
                         internal,
                         h))
        check.describe_state(p.get_id(), m, material, F, internal);
      // The rare tails behind one test, which the lean path (a final
      // Model that never renormalises: LinearElastic) pays alone: a reset
      // (fluids) and cpGIMP's domain check.
      if (resets_or_watches)
        {
          if (any_resets && slot.resets)
            reset_deformation(props, F);
          else
            renormalise_if_ill_conditioned(
              material, slot.renormalises, internal, props, F);
          if (watched_half_length != numbers::invalid_unsigned_int)
            check.domains_fit = check.domains_fit && domain_fits(props);
        }
      else
        renormalise_if_ill_conditioned(
          material, slot.renormalises, internal, props, F);
    }

    /** renormalise_deformation() where F has lost its digits
     * (ill_conditioned()) and the material and formulation allow it. */
    template <typename Model>
    DEAL_II_ALWAYS_INLINE void
    renormalise_if_ill_conditioned(const Model             &material,
                                   const bool               renormalises,
                                   const ArrayView<double> &internal,
                                   const ArrayView<double> &props,
                                   const Tensor<2, dim>    &F) const
    {
      if (may_renormalise(material, renormalises) && ill_conditioned(F))
        {
          Tensor<2, dim> F_new = F;
          material.renormalise_deformation(F_new, internal);
          write_tensor<dim>(&props[particles.fields.deformation_gradient],
                            F_new);
        }
    }

    /** Whether the particle's stretched domain fits the windows
     * (watch_domains()); reads F after a reset or renormalisation. */
    bool
    domain_fits(const ArrayView<double> &props) const
    {
      bool fits = true;
      for (unsigned int d = 0; d < dim; ++d)
        fits =
          fits && stretched_half_length<dim>(props, watched_half_length, d) <=
                    domain_limit[d];
      return fits;
    }

    /** Whether a particle whose slot says @p renormalises may need
     * renormalising. On the lean path (Model a final class, as
     * LinearElastic) the model's own answer folds the test away: the
     * elastic step pays nothing for it. */
    template <typename Model>
    DEAL_II_ALWAYS_INLINE bool
    may_renormalise(const Model &material, const bool renormalises) const
    {
      if constexpr (std::is_same_v<Model, Material<dim>>)
        return any_renormalise && renormalises;
      else
        return material.renormalises_deformation() && renormalises;
    }

    /** Whether F's condition number |F| |F^-1| (Frobenius norms; |F^-1|
     * = |cof F| / |J|) is above 1e4, where b_e = F C_p^-1 F^T has lost
     * about eight of its digits to cancellation: past 1e8 it has lost
     * them all, and the fine granular collapse's floor grains got there. */
    static bool
    ill_conditioned(const Tensor<2, dim> &F)
    {
      return F.norm() * cofactor(F).norm() > 1e4 * std::abs(determinant(F));
    }

    /** F <- J^(1/dim) I. */
    void
    reset_deformation(const ArrayView<double> &props,
                      const Tensor<2, dim>    &F) const
    {
      const double   J = determinant(F);
      Tensor<2, dim> isotropic;
      for (unsigned int d = 0; d < dim; ++d)
        isotropic[d][d] = std::pow(J, 1. / dim);
      write_tensor<dim>(&props[particles.fields.deformation_gradient],
                        isotropic);
    }

    /** What the update needs of each material, resolved once a step
     * rather than through three vectors a particle. */
    struct Slot
    {
      const Material<dim> *material;
      unsigned int         internal_offset;
      unsigned int         n_internal;
      bool                 resets; ///< resets_deformation()
      /** renormalises_deformation(), and the formulation allows it. */
      bool renormalises;
    };
    std::vector<Slot> slots;
    /** Whether the particles' offsets are for these materials. */
    bool laid_out        = false;
    bool any_resets      = false;
    bool any_renormalise = false;
    /** The material of every body, when they share one (the usual scene):
     * then no particle looks up its body. */
    unsigned int only_material = numbers::invalid_unsigned_int;
    /** any_resets, or watch_domains() was called. */
    bool resets_or_watches = false;
    /** watch_domains(): the domain_half_length checked, or none. */
    unsigned int   watched_half_length = numbers::invalid_unsigned_int;
    Tensor<1, dim> domain_limit;
    const std::vector<std::unique_ptr<Material<dim>>> &materials;
    const ParticleSet<dim>                            &particles;
    double                                             dt;
  };

  /** The checks without a stress update (for the first time step). With
   * @p reference_cells (total Lagrangian), a particle's cell is its
   * reference one, and its size is scaled by F's smallest stretch. */
  template <int dim>
  ParticleCheck<dim>
  check_particles(const BackgroundGrid<dim>                         &grid,
                  const std::vector<std::unique_ptr<Material<dim>>> &materials,
                  const ParticleSet<dim>                            &particles,
                  const bool reference_cells = false);
} // namespace dealmpm
