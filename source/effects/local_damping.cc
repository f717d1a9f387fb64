#include <dealmpm/effects/local_damping.h>

#include <cmath>

namespace dealmpm
{
  namespace
  {
    /**
     * Cundall's local non-viscous damping on the grid: each nodal force
     * component is reduced by alpha |f| against the direction of motion. It
     * drives a scene to its static state without changing that state.
     */
    template <int dim>
    class LocalDamping : public Effect<dim>
    {
    public:
      bool
      reads_stencil() const override
      {
        return false;
      }

      explicit LocalDamping(const double alpha)
        : alpha(alpha)
      {}

      void
      adjust_nodal_forces(NodalFields<dim> &fields) override
      {
        const unsigned int n = fields.mass.locally_owned_size();
        for (unsigned int d = 0; d < dim; ++d)
          {
            double       *force    = fields.force[d].begin();
            const double *momentum = fields.momentum[d].begin();
            for (unsigned int i = 0; i < n; ++i)
              if (momentum[i] != 0.)
                force[i] -=
                  alpha * std::abs(force[i]) * (momentum[i] > 0. ? 1. : -1.);
          }
      }

    private:
      double alpha;
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
