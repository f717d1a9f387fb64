#pragma once

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <dealmpm/materials/material.h>

namespace dealmpm
{
  /**
   * The geostatic Cauchy stress: sigma_v (n (x) n + K0 (I - n (x) n)) with
   * n the unit vertical (along gravity) and sigma_v = -rho g d the weight
   * of the material above, d deep (compression negative). In 2D the
   * out-of-plane stress is the material's (plane strain).
   */
  template <int dim>
  SymmetricTensor<2, dim>
  geostatic_stress(const double          sigma_v,
                   const Tensor<1, dim> &n,
                   const double          K0);

  /**
   * The material's own K0: the lateral over the vertical change of normal
   * stress in a small confined compression along the unit vector @p n from
   * its initial state (nu / (1 - nu) for isotropic elasticity, 1 for a
   * fluid).
   */
  template <int dim>
  double
  confined_stress_ratio(const Material<dim>  &material,
                        const unsigned int    n_internal,
                        const Tensor<1, dim> &n);

  /**
   * Put a material point at rest under the Cauchy stress @p target (its
   * in-plane part in 2D): the stretch F, symmetric and coaxial with the
   * target (1 out of plane in 2D), whose one step from the model's initial
   * state (zero stress, initial internal variables, L = log F over a step
   * of 1) gives the target; found by Newton's method on the principal
   * log-stretches, with a least-squares solve so that a fluid's isotropic
   * stretch is found too. Works for any model through its stress update:
   * rate forms and hyperelastic ones alike. Writes @p F, @p stress and
   * @p internal; returns false (and writes nothing) when no stretch gives
   * the target to 1e-9 of its size: a stress beyond the yield surface, a
   * fluid under a stress that is not a pressure.
   */
  template <int dim>
  bool
  start_at_stress(const Material<dim>           &material,
                  const SymmetricTensor<2, dim> &target,
                  Tensor<2, dim>                &F,
                  SymmetricTensor<2, dim>       &stress,
                  ArrayView<double>              internal);
} // namespace dealmpm
