// Using dealmpm as a library: register an effect of our own from outside
// the library, air drag f = -c m (v - v_air) on the grid nodes, with its
// work in the energy balance and a column of its own in statistics.csv,
// then run a scene that lists it with "set Effects = air drag".
//
//   ./custom_effect ../examples/custom_effect.prm
#include <dealmpm/app/program.h>
#include <dealmpm/core/simulation.h>
#include <dealmpm/effects/effect_with_work.h>

using namespace dealmpm;

namespace
{
  /** Linear drag towards the air's velocity, at rate c (1/s). Its work
   * accumulator, column and saved state come with EffectWithWork. */
  template <int dim>
  class AirDrag : public EffectWithWork<dim>
  {
  public:
    AirDrag(const double rate, const Tensor<1, dim> &air)
      : EffectWithWork<dim>("drag_work")
      , rate(rate)
      , air(air)
    {}

    /** After P2G: the nodes' own velocity p / m sets the drag; its power
     * f . v, taken at the start of the step, is the work done. */
    void
    add_nodal_forces(const EffectContext<dim> &state,
                     NodalFields<dim>         &fields) override
    {
      const unsigned int n = fields.mass.locally_owned_size();
      for (unsigned int i = 0; i < n; ++i)
        {
          const double m = fields.mass.local_element(i);
          if (!(m > state.mass_threshold))
            continue;
          for (unsigned int d = 0; d < dim; ++d)
            {
              const double v = fields.momentum[d].local_element(i) / m;
              const double f = -rate * m * (v - air[d]);
              fields.force[d].local_element(i) += f;
              this->work += state.dt * f * v;
            }
        }
    }

  private:
    double         rate;
    Tensor<1, dim> air;
  };

  template <int dim>
  void
  register_effect()
  {
    effect_registry<dim>().add(
      "air drag",
      "linear air drag -c m (v - v_air) (section Air drag: Rate, Air "
      "velocity); registered by examples/custom_effect.cc.",
      [](ParameterHandler &prm) {
        prm.declare_entry("Rate",
                          "1",
                          Patterns::Double(0),
                          "c (1/s): a free body's speed relative to the "
                          "air falls as exp(-c t).");
        prm.declare_entry("Air velocity",
                          dim == 2 ? "0, 0" : "0, 0, 0",
                          Patterns::List(Patterns::Double(), dim, dim),
                          "v_air (m/s).");
      },
      [](SceneReader &reader) -> std::unique_ptr<Effect<dim>> {
        return std::make_unique<AirDrag<dim>>(reader.get_nonnegative("Rate"),
                                              reader.template get_vector<dim>(
                                                "Air velocity"));
      });
  }
} // namespace

int
main(int argc, char **argv)
{
  register_effect<2>();
  register_effect<3>();
  return run_program(argc, argv);
}
