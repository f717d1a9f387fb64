#include <deal.II/base/symmetric_tensor.h>

#include <dealmpm/base/errors.h>
#include <dealmpm/transfer/deformation_update.h>

namespace dealmpm
{
  std::string
  DeformationUpdate::pattern()
  {
    return "first order|Taylor series|Cayley|subcycle";
  }

  DeformationUpdate::Variant
  DeformationUpdate::parse(const std::string &name)
  {
    if (name == "Taylor series")
      return Variant::taylor_series;
    if (name == "Cayley")
      return Variant::cayley;
    if (name == "subcycle")
      return Variant::subcycle;
    AssertThrow(name == "first order",
                ExcMessage("unknown deformation gradient update '" + name +
                           "'"));
    return Variant::first_order;
  }

  template <int dim>
  Tensor<2, dim>
  DeformationUpdate::increment(const Tensor<2, dim> &dt_L) const
  {
    const Tensor<2, dim> I = unit_symmetric_tensor<dim>();
    switch (variant)
      {
        case Variant::first_order:
          return I + dt_L;
          case Variant::taylor_series: {
            // Horner: I + A (I + A/2 (I + A/3 (... (I + A/K)))).
            Tensor<2, dim> dF = I;
            for (unsigned int k = taylor_terms; k >= 1; --k)
              dF = I + dt_L * dF / static_cast<double>(k);
            return dF;
          }
        case Variant::cayley:
          return invert(I - 0.5 * dt_L) * (I + 0.5 * dt_L);
          case Variant::subcycle: {
            const Tensor<2, dim> step =
              I + dt_L / static_cast<double>(subcycles);
            Tensor<2, dim> dF = step;
            for (unsigned int n = 1; n < subcycles; ++n)
              dF = step * dF;
            return dF;
          }
      }
    return I + dt_L;
  }

  template Tensor<2, 2>
  DeformationUpdate::increment(const Tensor<2, 2> &) const;
  template Tensor<2, 3>
  DeformationUpdate::increment(const Tensor<2, 3> &) const;
} // namespace dealmpm
