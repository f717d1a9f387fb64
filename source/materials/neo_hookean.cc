#include <dealmpm/materials/neo_hookean.h>

#include <algorithm>
#include <cmath>

namespace dealmpm
{
  template <int dim>
  NeoHookean<dim>::NeoHookean(const LameParameters &lame)
    : lame(lame)
  {}

  template <int dim>
  void
  NeoHookean<dim>::update_stress(const Tensor<2, dim> &,
                                 const Tensor<2, dim> &F,
                                 const double,
                                 SymmetricTensor<2, dim> &stress,
                                 ArrayView<double>) const
  {
    const double J = determinant(F);
    // A non-positive J makes log() NaN; the step's finiteness check then
    // stops the run and names the particle.
    const SymmetricTensor<2, dim> B = symmetrize(F * transpose(F));
    stress = (lame.mu / J) * (B - unit_symmetric_tensor<dim>()) +
             (lame.lambda * std::log(J) / J) * unit_symmetric_tensor<dim>();
  }

  template <int dim>
  double
  NeoHookean<dim>::wave_speed(const Tensor<2, dim> &F) const
  {
    // Tangent P-wave modulus over current density: (lambda + 2 (mu - lambda
    // ln J)) / J divided by rho0 / J.
    const double J = determinant(F);
    const double modulus =
      lame.lambda + 2. * (lame.mu - lame.lambda * std::log(J));
    return std::sqrt(std::max(modulus, lame.lambda + 2. * lame.mu) /
                     this->density);
  }

  template <int dim>
  double
  NeoHookean<dim>::out_of_plane_stress(const Tensor<2, dim> &F,
                                       const SymmetricTensor<2, dim> &,
                                       ArrayView<const double>) const
  {
    const double J = determinant(F);
    return lame.lambda * std::log(J) / J;
  }

  template <int dim>
  double
  NeoHookean<dim>::strain_energy_density(const Tensor<2, dim> &F,
                                         const SymmetricTensor<2, dim> &,
                                         ArrayView<const double>) const
  {
    // In plane strain F_zz = 1, so tr C - 3 = tr_2D C - 2 = tr C - dim.
    const double log_J = std::log(determinant(F));
    return 0.5 * lame.mu * (trace(transpose(F) * F) - dim) - lame.mu * log_J +
           0.5 * lame.lambda * log_J * log_J;
  }

  template class NeoHookean<2>;
  template class NeoHookean<3>;

  template <int dim>
  void
  add_neo_hookean_material(Registry<Material<dim>> &registry)
  {
    registry.add(
      "neo-Hookean",
      "compressible neo-Hookean hyperelasticity, stress from F "
      "(Young's modulus, Poisson's ratio).",
      [](ParameterHandler &prm) { declare_elastic_constants(prm, 1e3, 0.3); },
      [](SceneReader &reader) -> std::unique_ptr<Material<dim>> {
        return std::make_unique<NeoHookean<dim>>(
          read_elastic_constants(reader));
      });
  }

  template void
  add_neo_hookean_material(Registry<Material<2>> &);
  template void
  add_neo_hookean_material(Registry<Material<3>> &);
} // namespace dealmpm
