#pragma once

#include <dealmpm/materials/material.h>

#include <cmath>
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

  /** The rotation by @p angle about the coordinate axis @p axis. */
  inline Tensor<2, 3>
  rotation(const double angle, const unsigned int axis)
  {
    const unsigned int i = (axis + 1) % 3, j = (axis + 2) % 3;
    Tensor<2, 3>       Q;
    Q[i][i] = Q[j][j] = std::cos(angle);
    Q[i][j]           = -std::sin(angle);
    Q[j][i]           = std::sin(angle);
    Q[axis][axis]     = 1;
    return Q;
  }

  /** Shear a point confined by the isotropic logarithmic strain @p e0 to
   * F = (I + gamma e_x (x) e_y) exp(e0) I in @p n equal steps; returns F. */
  template <class Point>
  Tensor<2, 3>
  confined_simple_shear(Point             &point,
                        const double       e0,
                        const double       gamma,
                        const unsigned int n)
  {
    const Tensor<2, 3> confined =
      std::exp(e0) * Tensor<2, 3>(unit_symmetric_tensor<3>());
    Tensor<2, 3> F = confined;
    for (unsigned int s = 1; s <= n; ++s)
      {
        Tensor<2, 3> shear = unit_symmetric_tensor<3>();
        shear[0][1]        = gamma * s / n;
        F                  = shear * confined;
        point.deform(F);
      }
    return F;
  }

  /** Deform @p reference by @p F0 and @p rotated by F0, then Q F0: the
   * difference of rotated's stress from Q sigma Q^T, relative to it. */
  template <class Point>
  double
  rotation_error(Point              &reference,
                 Point              &rotated,
                 const Tensor<2, 3> &F0,
                 const Tensor<2, 3> &Q)
  {
    reference.deform(F0);
    rotated.deform(F0);
    rotated.deform(Q * F0);
    const Tensor<2, 3> expected =
      Q * Tensor<2, 3>(reference.stress) * transpose(Q);
    return (Tensor<2, 3>(rotated.stress) - expected).norm() / expected.norm();
  }

  /** Whether every component is finite. */
  inline bool
  all_finite(const SymmetricTensor<2, 3> &tau)
  {
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        if (!std::isfinite(tau[i][j]))
          return false;
    return true;
  }

  /** A path of compression, shear and some extension at time t, with an
   * added steady compaction of @p compaction along x per unit t. */
  template <int dim>
  Tensor<2, dim>
  wandering_deformation(const double t, const double compaction = 0)
  {
    Tensor<2, dim> F;
    F[0][0] = std::exp(-0.05 * std::sin(t) - compaction * t);
    F[1][1] = std::exp(0.02 * std::sin(2 * t) - 0.01 * t);
    F[0][1] = 0.3 * std::sin(1.3 * t);
    if (dim == 3)
      {
        F[dim - 1][dim - 1] = std::exp(0.01 * std::cos(t) - 0.01);
        F[1][dim - 1]       = 0.1 * std::cos(t) - 0.1;
      }
    return F;
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
