#include <dealmpm/effects/effect_with_work.h>
#include <dealmpm/effects/local_damping.h>

#include <array>
#include <cmath>
#include <vector>

namespace dealmpm
{
  namespace
  {
    /**
     * Cundall's local non-viscous damping on the grid: each nodal force
     * component is reduced by alpha |f| against the direction of motion. It
     * drives a scene to its static state without changing that state. Its
     * work (negative: the energy it takes out) is the statistics column
     * damping_work and counts in the energy balance, which closes as it
     * would without damping (before 2026-11-30 the damped column's balance
     * read -33.5 %).
     */
    template <int dim>
    class LocalDamping : public EffectWithWork<dim>
    {
    public:
      bool
      reads_stencil() const override
      {
        return false;
      }

      explicit LocalDamping(const double alpha)
        : EffectWithWork<dim>("damping_work")
        , alpha(alpha)
      {}

      void
      adjust_nodal_forces(NodalFields<dim> &fields) override
      {
        const unsigned int n = fields.mass.locally_owned_size();
        for (unsigned int d = 0; d < dim; ++d)
          {
            damping[d].assign(n, 0.);
            double       *force    = fields.force[d].begin();
            const double *momentum = fields.momentum[d].begin();
            for (unsigned int i = 0; i < n; ++i)
              if (momentum[i] != 0.)
                {
                  damping[d][i] =
                    -alpha * std::abs(force[i]) * (momentum[i] > 0. ? 1. : -1.);
                  force[i] += damping[d][i];
                }
          }
      }

      /** f . (v + v*) / 2 dt of the damping force, as every load counts. */
      void
      count_work(const EffectContext<dim> &state,
                 const NodalFields<dim>   &fields) override
      {
        const unsigned int n = fields.mass.locally_owned_size();
        for (unsigned int d = 0; d < dim; ++d)
          if (damping[d].size() == n)
            for (unsigned int i = 0; i < n; ++i)
              {
                const double m = fields.mass.local_element(i);
                if (damping[d][i] != 0. && m > state.mass_threshold)
                  this->work += 0.5 * state.dt * damping[d][i] *
                                (fields.momentum[d].local_element(i) / m +
                                 fields.velocity[d].local_element(i));
              }
      }

      /** Checkpoints written before the damping counted its work hold
       * none: it starts from 0 there. */
      void
      restore_state(const std::vector<double> &state) override
      {
        this->work = state.empty() ? 0. : state[0];
      }

    private:
      double alpha;
      /** The damping force of the step at each owned node. */
      std::array<std::vector<double>, dim> damping;
    };
  } // namespace

  template <int dim>
  void
  add_local_damping_effect(Registry<Effect<dim>> &registry)
  {
    registry.add(
      "local damping",
      "Cundall's local damping of nodal forces, for quasi-static "
      "settling (section Local damping: Coefficient).",
      [](ParameterHandler &prm) {
        prm.declare_entry("Coefficient",
                          "0.05",
                          Patterns::Double(),
                          "Damping coefficient alpha, 0 <= alpha < 1.");
      },
      [](SceneReader &reader) -> std::unique_ptr<Effect<dim>> {
        const double alpha = reader.get_double("Coefficient");
        if (!(alpha >= 0. && alpha < 1.))
          reader.fail("Coefficient", "a number in [0, 1)");
        return std::make_unique<LocalDamping<dim>>(alpha);
      });
  }

  template void
  add_local_damping_effect(Registry<Effect<2>> &);
  template void
  add_local_damping_effect(Registry<Effect<3>> &);
} // namespace dealmpm
