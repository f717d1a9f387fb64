#pragma once

#include <deal.II/base/array_view.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

namespace dealmpm
{
  using namespace dealii;

  /**
   * The part of a model whose state remembers more than its stress: a
   * preconsolidation pressure, the largest stress a clay has carried. A
   * geostatic start (start_geostatic_bodies()) finds each point's F and
   * stress by loading it from the unstrained state, which leaves such a
   * history at whatever that loading made; the model then sets it from
   * the stress at rest instead (Modified Cam-Clay: its overconsolidation
   * ratio times the yield surface through that stress).
   */
  template <int dim>
  class GeostaticHistory
  {
  public:
    virtual ~GeostaticHistory() = default;

    /** Set the history of a point at rest at @p F under the Cauchy
     * stress @p stress (in-plane in 2D, the rest in @p internal). */
    virtual void
    start_history(const Tensor<2, dim>          &F,
                  const SymmetricTensor<2, dim> &stress,
                  ArrayView<double>              internal) const = 0;
  };
} // namespace dealmpm
