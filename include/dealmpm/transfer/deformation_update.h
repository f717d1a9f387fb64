#pragma once

#include <deal.II/base/tensor.h>

#include <string>

namespace dealmpm
{
  using namespace dealii;

  /**
   * How F advances over a step with a constant velocity gradient L:
   * F_{n+1} = dF F_n, dF approximating exp(dt L) (as Uintah's
   * defGradAlgorithm offers):
   * - first order: dF = I + dt L (the default: cheapest, exact for simple
   *   shear, J > 0 only while dt |L| is small);
   * - Taylor series: dF = sum_{k <= K} (dt L)^k / k!, error O(dt^(K+1))
   *   per step;
   * - Cayley: dF = (I - dt L / 2)^-1 (I + dt L / 2), second order; a
   *   rotation for skew L (a rigid spin keeps J = 1 exactly), and
   *   J > 0 whenever the eigenvalues of dt L / 2 lie in (-1, 1);
   * - subcycle: dF = (I + dt L / N)^N, first order with an error N times
   *   smaller.
   */
  struct DeformationUpdate
  {
    enum class Variant
    {
      first_order,
      taylor_series,
      cayley,
      subcycle
    };
    Variant      variant      = Variant::first_order;
    unsigned int taylor_terms = 4; ///< K, the highest power kept
    unsigned int subcycles    = 4; ///< N

    /** "first order|Taylor series|Cayley|subcycle". */
    static std::string
    pattern();
    static Variant
    parse(const std::string &name);

    /** dF for the increment dt L (of any variant). */
    template <int dim>
    Tensor<2, dim>
    increment(const Tensor<2, dim> &dt_L) const;
  };

  /** The first-order increment I + dt L, inline for the sweeps. */
  struct FirstOrderIncrement
  {
    template <int dim>
    DEAL_II_ALWAYS_INLINE Tensor<2, dim>
                          operator()(const Tensor<2, dim> &dt_L) const
    {
      Tensor<2, dim> dF = dt_L;
      for (unsigned int d = 0; d < dim; ++d)
        dF[d][d] += 1.;
      return dF;
    }
  };

  /** The increment of the scene's chosen variant (not first order). */
  struct ChosenIncrement
  {
    DeformationUpdate update;

    template <int dim>
    Tensor<2, dim>
    operator()(const Tensor<2, dim> &dt_L) const
    {
      return update.increment(dt_L);
    }
  };
} // namespace dealmpm
