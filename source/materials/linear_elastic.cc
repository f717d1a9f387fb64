#include <dealmpm/materials/linear_elastic.h>

#include <cmath>

namespace dealmpm
{
  template <int dim>
  LinearElastic<dim>::LinearElastic(const LameParameters &lame)
    : lame(lame)
  {}

  template <int dim>
  void
  LinearElastic<dim>::update_stress(const Tensor<2, dim> &L,
                                    const Tensor<2, dim> &,
                                    const double             dt,
                                    SymmetricTensor<2, dim> &stress,
                                    ArrayView<double>) const
  {
    const SymmetricTensor<2, dim> D = symmetrize(L);
    stress += dt * (2. * lame.mu * D +
                    lame.lambda * trace(D) * unit_symmetric_tensor<dim>());
  }

  template <int dim>
  double
  LinearElastic<dim>::wave_speed(const Tensor<2, dim> &F) const
  {
    // Current density rho0 / J.
    return std::sqrt((lame.lambda + 2. * lame.mu) * determinant(F) /
                     this->density);
  }

  template <int dim>
  double
  LinearElastic<dim>::strain_energy_density(
    const Tensor<2, dim> &,
    const SymmetricTensor<2, dim> &stress,
    ArrayView<const double>) const
  {
    // Invert sigma = 2 mu eps + lambda tr(eps) I; in 2D (plane strain) the
    // trace runs over the in-plane components, which is what dim gives.
    const double trace_strain =
      trace(stress) / (2. * lame.mu + dim * lame.lambda);
    const SymmetricTensor<2, dim> strain =
      (stress - lame.lambda * trace_strain * unit_symmetric_tensor<dim>()) /
      (2. * lame.mu);
    return lame.mu * (strain * strain) +
           0.5 * lame.lambda * trace_strain * trace_strain;
  }

  template class LinearElastic<2>;
  template class LinearElastic<3>;
} // namespace dealmpm
