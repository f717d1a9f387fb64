// Using dealmpm as a library: register a material model of our own (a
// Saint Venant-Kirchhoff solid) from outside the library, then run a scene
// that selects it with "set Model = Saint Venant-Kirchhoff".
//
//   ./custom_material ../examples/custom_material.prm
#include <dealmpm/app/program.h>
#include <dealmpm/core/simulation.h>
#include <dealmpm/materials/material.h>

using namespace dealmpm;

namespace
{
  /** S = lambda tr(E) I + 2 mu E with E = (F^T F - I) / 2; sigma = F S F^T / J.
   */
  template <int dim>
  class SaintVenantKirchhoff : public Material<dim>
  {
  public:
    explicit SaintVenantKirchhoff(const LameParameters &lame)
      : lame(lame)
    {}

    void
    update_stress(const Tensor<2, dim> &,
                  const Tensor<2, dim> &F,
                  const double,
                  SymmetricTensor<2, dim> &stress,
                  ArrayView<double>) const override
    {
      const SymmetricTensor<2, dim> S = second_piola_kirchhoff(F);
      stress =
        symmetrize(F * Tensor<2, dim>(S) * transpose(F)) / determinant(F);
    }

    /** sigma_zz = S_zz / J with E_zz = 0 in plane strain. */
    double
    out_of_plane_stress(const Tensor<2, dim> &F,
                        const SymmetricTensor<2, dim> &,
                        ArrayView<const double>) const override
    {
      return lame.lambda * trace(green_lagrange(F)) / determinant(F);
    }

    double
    wave_speed(const Tensor<2, dim> &) const override
    {
      return std::sqrt((lame.lambda + 2 * lame.mu) / this->density);
    }

    double
    strain_energy_density(const Tensor<2, dim> &F,
                          const SymmetricTensor<2, dim> &,
                          ArrayView<const double>) const override
    {
      const SymmetricTensor<2, dim> E = green_lagrange(F);
      return 0.5 * lame.lambda * trace(E) * trace(E) + lame.mu * (E * E);
    }

  private:
    static SymmetricTensor<2, dim>
    green_lagrange(const Tensor<2, dim> &F)
    {
      return 0.5 *
             (symmetrize(transpose(F) * F) - unit_symmetric_tensor<dim>());
    }

    SymmetricTensor<2, dim>
    second_piola_kirchhoff(const Tensor<2, dim> &F) const
    {
      const SymmetricTensor<2, dim> E = green_lagrange(F);
      return lame.lambda * trace(E) * unit_symmetric_tensor<dim>() +
             2 * lame.mu * E;
    }

    LameParameters lame;
  };

  template <int dim>
  void
  register_model()
  {
    material_registry<dim>().add(
      "Saint Venant-Kirchhoff",
      "hyperelastic S = lambda tr(E) I + 2 mu E (Young's modulus, Poisson's ratio); "
      "registered by examples/custom_material.cc.",
      [](ParameterHandler &prm) { declare_elastic_constants(prm, 1e3, 0.3); },
      [](SceneReader &reader) -> std::unique_ptr<Material<dim>> {
        return std::make_unique<SaintVenantKirchhoff<dim>>(
          read_elastic_constants(reader));
      });
  }
} // namespace

int
main(int argc, char **argv)
{
  register_model<2>();
  register_model<3>();
  return run_program(argc, argv);
}
