#include <dealmpm/materials/linear_elastic.h>

namespace dealmpm
{
  template <int dim>
  LinearElastic<dim>::LinearElastic(const LameParameters &lame)
    : lame(lame)
  {}

  template <int dim>
  double
  LinearElastic<dim>::out_of_plane_stress(const Tensor<2, dim> &,
                                          const SymmetricTensor<2, dim> &stress,
                                          ArrayView<const double>) const
  {
    return 0.5 * lame.lambda / (lame.lambda + lame.mu) * trace(stress);
  }

  template <int dim>
  double
  LinearElastic<dim>::strain_energy_density(
    const Tensor<2, dim> &,
    const SymmetricTensor<2, dim> &,
    ArrayView<const double> internal) const
  {
    return internal[0];
  }

  template class LinearElastic<2>;
  template class LinearElastic<3>;

  template <int dim>
  void
  add_linear_elastic_material(Registry<Material<dim>> &registry)
  {
    registry.add(
      "linear elastic",
      "isotropic small-strain elasticity in rate form (Young's modulus, "
      "Poisson's ratio).",
      [](ParameterHandler &prm) { declare_elastic_constants(prm, 1e3, 0.3); },
      [](SceneReader &reader) -> std::unique_ptr<Material<dim>> {
        return std::make_unique<LinearElastic<dim>>(
          read_elastic_constants(reader));
      });
  }

  template void
  add_linear_elastic_material(Registry<Material<2>> &);
  template void
  add_linear_elastic_material(Registry<Material<3>> &);
} // namespace dealmpm
