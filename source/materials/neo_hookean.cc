#include <dealmpm/materials/neo_hookean.h>

#include <algorithm>
#include <cmath>

namespace dealmpm
{
  template <int dim>
  NeoHookean<dim>::NeoHookean(const LameParameters &lame)
    : lame(lame)
  {}

  namespace
  {
    /** sigma = mu / J (B - I) + lambda ln(J) / J I, entry by entry in
     * scalars (the tensor expression's numbers; GCC's partial
     * vectorization of that expression stalled on its own stores). */
    template <int dim>
    inline SymmetricTensor<2, dim>
    neo_hookean_stress(const LameParameters &lame, const Tensor<2, dim> &F)
    {
      const double J = determinant(F);
      // A non-positive J makes log() NaN; the step's finiteness check
      // then stops the run and names the particle (an FEM region checks J
      // before).
      const double            shear = lame.mu / J;
      const double            bulk  = lame.lambda * std::log(J) / J;
      SymmetricTensor<2, dim> stress;
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = a; b < dim; ++b)
          {
            double B_ab = F[a][0] * F[b][0]; // (F F^T)_ab
            for (unsigned int k = 1; k < dim; ++k)
              B_ab += F[a][k] * F[b][k];
            stress[a][b] = a == b ? shear * (B_ab - 1.) + bulk : shear * B_ab;
          }
      return stress;
    }
  } // namespace

  template <int dim>
  void
  NeoHookean<dim>::update_stress(const Tensor<2, dim> &,
                                 const Tensor<2, dim> &F,
                                 const double,
                                 SymmetricTensor<2, dim> &stress,
                                 ArrayView<double>) const
  {
    stress = neo_hookean_stress(lame, F);
  }

  template <int dim>
  void
  NeoHookean<dim>::update_stresses(
    const ArrayView<const Tensor<2, dim>> &,
    const ArrayView<const Tensor<2, dim>> &F,
    const double,
    const ArrayView<SymmetricTensor<2, dim>> &stress,
    const ArrayView<double> &) const
  {
    for (std::size_t q = 0; q < F.size(); ++q)
      stress[q] = neo_hookean_stress(lame, F[q]);
  }

  namespace
  {
    /** Tangent P-wave modulus over current density: (lambda + 2 (mu -
     * lambda ln J)) / J divided by rho0 / J; at least the small-strain
     * one. */
    template <int dim>
    inline double
    neo_hookean_modulus(const LameParameters &lame, const Tensor<2, dim> &F)
    {
      const double modulus =
        lame.lambda + 2. * (lame.mu - lame.lambda * std::log(determinant(F)));
      return std::max(modulus, lame.lambda + 2. * lame.mu);
    }
  } // namespace

  template <int dim>
  double
  NeoHookean<dim>::wave_speed(const Tensor<2, dim> &F) const
  {
    return std::sqrt(neo_hookean_modulus(lame, F) / this->density);
  }

  template <int dim>
  double
  NeoHookean<dim>::max_wave_speed(const ArrayView<const Tensor<2, dim>> &F,
                                  const ArrayView<const double> &) const
  {
    // The modulus falls with J where lambda >= 0 (rises where lambda < 0):
    // the largest over the points is the one at the extreme J, one log
    // per call instead of one per point (the same number). Where that J is
    // not positive (a log of NaN or -inf) the loop over all decides, as
    // before.
    if (F.size() == 0)
      return 0.;
    std::size_t extreme   = 0;
    double      extreme_J = determinant(F[0]);
    for (std::size_t q = 1; q < F.size(); ++q)
      {
        const double J = determinant(F[q]);
        if (lame.lambda >= 0 ? J < extreme_J : J > extreme_J)
          extreme = q, extreme_J = J;
      }
    double largest = 0;
    if (extreme_J > 0)
      largest = neo_hookean_modulus(lame, F[extreme]);
    else
      for (const Tensor<2, dim> &f : F)
        largest = std::max(largest, neo_hookean_modulus(lame, f));
    return std::sqrt(largest / this->density);
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
