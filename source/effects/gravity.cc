#include <dealmpm/effects/gravity.h>
#include <dealmpm/transfer/stencil_order.h>

#include <algorithm>

namespace dealmpm
{
  namespace
  {
    /**
     * Uniform body force g per unit mass: f_i += m_i g, which equals
     * sum_p N_ip m_p g. With a ramp time T, g grows linearly from 0 to its
     * full value over [0, T] (the step uses its value at mid-step); the
     * potential -m g(t) . x then changes with t too, and that change,
     * -(g(t + dt) - g(t)) . sum_p m_p x_p (at mid-step), is counted as
     * work so that the energy balance closes (a particle sweep in the
     * ramp's steps only).
     */
    template <int dim>
    class Gravity : public Effect<dim>
    {
    public:
      bool
      reads_stencil() const override
      {
        return false;
      }

      Gravity(const Tensor<1, dim> &g, const double ramp_time)
        : g(g)
        , ramp_time(ramp_time)
        , factor_now(factor(0.))
      {}

      void
      add_nodal_forces(const EffectContext<dim> &state,
                       NodalFields<dim>         &fields) override
      {
        const double t = state.time, dt = state.dt;
        const double scale = factor(t + 0.5 * dt);
        if (factor(t + dt) != factor(t))
          {
            // sum_p m_p x_p at mid-step, x_p + dt / 2 v_p.
            const CoreFields &f = state.particles.fields;
            Tensor<1, dim>    moment;
            for_each_particle_in_stencil_order(
              state.grid,
              state.particles,
              [&](const std::size_t, const auto &p, const GridCell<dim> &) {
                const auto props = p.get_properties();
                moment += props[f.mass] *
                          (Tensor<1, dim>(p.get_location()) +
                           0.5 * dt * read_vector<dim>(&props[f.velocity]));
              });
            work -= (factor(t + dt) - factor(t)) * (g * moment);
          }
        factor_now = factor(t + dt);

        const unsigned int n    = fields.mass.locally_owned_size();
        const double      *mass = fields.mass.begin();
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double gd    = scale * g[d];
            double      *force = fields.force[d].begin();
            for (unsigned int i = 0; i < n; ++i)
              force[i] += mass[i] * gd;
          }
      }

      double
      potential_energy(const double mass, const Point<dim> &x) const override
      {
        return -mass * factor_now * (g * x);
      }

      bool
      potential_steady_from(const double t) const override
      {
        return ramp_time <= 0. || t >= ramp_time; // factor() is 1 from t on
      }

      bool
      body_acceleration_is_uniform() const override
      {
        return true;
      }

      Tensor<1, dim>
      body_acceleration(const Point<dim> &,
                        const Point<dim> &,
                        const Tensor<1, dim> &,
                        const double t) const override
      {
        return factor(t) * g;
      }

      double
      work_done() const override
      {
        return work;
      }

      std::vector<double>
      saved_state() const override
      {
        return {factor_now, work};
      }

      std::vector<bool>
      state_shared_by_ranks() const override
      {
        return {true, false};
      }

      void
      restore_state(const std::vector<double> &state) override
      {
        factor_now = state.at(0);
        work       = state.at(1);
      }

    private:
      /** g(t) / g. */
      double
      factor(const double t) const
      {
        return ramp_time > 0. ? std::min(1., t / ramp_time) : 1.;
      }

      Tensor<1, dim> g;
      double         ramp_time;
      double         factor_now; ///< g(t) / g at the end of the last step
      double         work = 0;   ///< of the ramp's change in time
    };
  } // namespace

  template <int dim>
  void
  add_gravity_effect(Registry<Effect<dim>> &registry)
  {
    registry.add(
      "gravity",
      "uniform body force (section Gravity: Acceleration).",
      [](ParameterHandler &prm) {
        prm.declare_entry("Acceleration",
                          dim == 2 ? "0, -9.81" : "0, 0, -9.81",
                          Patterns::List(Patterns::Double(), dim, dim),
                          "Gravitational acceleration vector (m/s^2). "
                          "Tilt it to put a scene on an incline.");
        prm.declare_entry("Ramp time",
                          "0",
                          Patterns::Double(0),
                          "0: full gravity from t = 0. T > 0: gravity "
                          "grows linearly from 0 to full over [0, T] (s), "
                          "so that a body settles without a shock.");
      },
      [](SceneReader &reader) -> std::unique_ptr<Effect<dim>> {
        return std::make_unique<Gravity<dim>>(
          reader.get_vector<dim>("Acceleration"),
          reader.get_nonnegative("Ramp time"));
      });
  }

  template void
  add_gravity_effect(Registry<Effect<2>> &);
  template void
  add_gravity_effect(Registry<Effect<3>> &);
} // namespace dealmpm
