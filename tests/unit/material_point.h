#pragma once

#include <dealmpm/materials/material.h>

#include <vector>

namespace dealmpm::test
{
  /** One material point of a model without a grid: the model, its state and
   * its stress, deformed by a given F. */
  template <int dim, class Model>
  struct MaterialPoint
  {
    Model                   model;
    std::vector<double>     internal;
    SymmetricTensor<2, dim> stress;

    template <class... Arguments>
    explicit MaterialPoint(const Arguments &...arguments)
      : model(arguments...)
    {
      unsigned int n = 0;
      for (const auto &f : model.internal_variables())
        n += f.n_components;
      internal.resize(n);
      model.initialize_internal_variables(make_array_view(internal));
      model.density = 1;
    }

    /** Deform to @p F over a step of @p dt. */
    void
    deform(const Tensor<2, dim> &F, const double dt = 1.)
    {
      model.update_stress(
        Tensor<2, dim>(), F, dt, stress, make_array_view(internal));
    }

    ArrayView<const double>
    state() const
    {
      return make_array_view(internal);
    }

    /** The 3 x 3 Kirchhoff stress J sigma (sigma_zz from the model in 2D). */
    SymmetricTensor<2, 3>
    kirchhoff(const Tensor<2, dim> &F) const
    {
      return determinant(F) * full_stress<dim>(model, F, stress, state());
    }
  };

  /** sqrt(3/2) |dev tau|. */
  inline double
  von_mises(const SymmetricTensor<2, 3> &tau)
  {
    return std::sqrt(1.5) * deviator(tau).norm();
  }

  /** A uniaxial stretch along x with logarithmic strain @p log_strain. */
  template <int dim>
  Tensor<2, dim>
  stretch_x(const double log_strain)
  {
    Tensor<2, dim> F = unit_symmetric_tensor<dim>();
    F[0][0]          = std::exp(log_strain);
    return F;
  }
} // namespace dealmpm::test
