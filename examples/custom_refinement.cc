// Using dealmpm as a library: register a refinement criterion of our own
// from outside the library, a band along a plane (the ground a body lands
// on) refined to a level, then run a scene that lists it with
// "set Criteria = ground band" in its Adaptivity section.
//
//   ./custom_refinement ../examples/custom_refinement.prm
#include <dealmpm/adaptivity/adaptivity.h>
#include <dealmpm/app/program.h>
#include <dealmpm/core/simulation.h>

using namespace dealmpm;

namespace
{
  /** Cells whose centre lies within a distance of the plane n . x = c go
   * to a level; the others may be coarsened. */
  template <int dim>
  class GroundBand : public RefinementCriterion<dim>
  {
  public:
    GroundBand(const Tensor<1, dim> &normal,
               const double          offset,
               const double          width,
               const int             level)
      : normal(normal / normal.norm())
      , offset(offset)
      , width(width)
      , level(level)
    {}

    void
    target_levels(const AdaptivityContext<dim> &context,
                  std::vector<int>             &levels) const override
    {
      for (std::size_t i = 0; i < context.grid.cells.size(); ++i)
        {
          const double distance =
            std::abs(normal * context.grid.cells[i].cell->center() - offset);
          levels[i] = distance < width ? level : context.min_level;
        }
    }

  private:
    Tensor<1, dim> normal;
    double         offset;
    double         width;
    int            level;
  };

  template <int dim>
  void
  register_criterion()
  {
    refinement_criterion_registry<dim>().add(
      "ground band",
      "cells near a plane refined (section Adaptivity/Ground band: Normal, "
      "Offset, Width, Level); registered by examples/custom_refinement.cc.",
      [](ParameterHandler &prm) {
        prm.declare_entry("Normal",
                          dim == 2 ? "0, 1" : "0, 0, 1",
                          Patterns::List(Patterns::Double(), dim, dim),
                          "n: the plane is n . x = Offset.");
        prm.declare_entry("Offset", "0", Patterns::Double(), "c (m).");
        prm.declare_entry("Width",
                          "0.1",
                          Patterns::Double(0),
                          "Cells whose centre is closer than this to the "
                          "plane are refined (m).");
        prm.declare_entry("Level",
                          "1",
                          Patterns::Integer(0, 20),
                          "Their level.");
      },
      [](SceneReader &reader) -> std::unique_ptr<RefinementCriterion<dim>> {
        const Tensor<1, dim> n = reader.template get_vector<dim>("Normal");
        if (!(n.norm() > 0))
          reader.fail("Normal", "a vector that is not zero");
        return std::make_unique<GroundBand<dim>>(n,
                                                 reader.get_double("Offset"),
                                                 reader.get_positive("Width"),
                                                 reader.get_integer("Level"));
      });
  }
} // namespace

int
main(int argc, char **argv)
{
  register_criterion<2>();
  register_criterion<3>();
  return run_program(argc, argv);
}
