#pragma once

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <array>

namespace dealmpm
{
  using namespace dealii;

  /**
   * Logarithmic (Hencky) strain in principal form: a symmetric positive
   * definite 3 x 3 tensor b = sum_a lambda_a^2 n_a (x) n_a (an elastic left
   * Cauchy-Green tensor) as its principal directions and the principal
   * logarithmic strains eps_a = ln(lambda_a) = ln(b_a) / 2. The models that
   * return in principal space (J2, Drucker-Prager, Mohr-Coulomb) share it.
   * The decomposition is Eigen's self-adjoint solver (iterative, accurate for
   * close and repeated eigenvalues).
   */
  struct PrincipalStrain
  {
    std::array<double, 3>       strain;
    std::array<Tensor<1, 3>, 3> direction;
  };

  /** @p b's principal logarithmic strains and directions. */
  PrincipalStrain
  principal_log_strain(const SymmetricTensor<2, 3> &b);

  /** sum_a values_a n_a (x) n_a: a tensor from principal values. */
  SymmetricTensor<2, 3>
  from_principal(const std::array<double, 3>       &values,
                 const std::array<Tensor<1, 3>, 3> &direction);

  /** A plane-strain (2D) tensor as 3 x 3 with F_zz = 1; a 3D one as is. */
  template <int dim>
  Tensor<2, 3>
  embed_deformation(const Tensor<2, dim> &F)
  {
    Tensor<2, 3> F3;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        F3[i][j] = F[i][j];
    for (unsigned int i = dim; i < 3; ++i)
      F3[i][i] = 1;
    return F3;
  }
} // namespace dealmpm
