#include <dealmpm/materials/hencky.h>
#include <dealmpm/materials/hencky_plasticity.h>

#include <cmath>

namespace dealmpm
{
  namespace
  {
    /** Where each stored component of C_p^-1 sits in the 3 x 3 tensor. */
    constexpr unsigned int stored_row[6] = {0, 1, 2, 0, 0, 1};
    constexpr unsigned int stored_col[6] = {0, 1, 2, 1, 2, 2};

    /** The trial b_e = F C_p^-1 F^T of a state, in principal form. */
    template <int dim>
    PrincipalStrain
    trial_strain(const Tensor<2, 3> &F3, ArrayView<const double> internal)
    {
      SymmetricTensor<2, 3> inverse_plastic;
      for (unsigned int c = 0; c < HenckyPlasticity<dim>::n_inverse_plastic;
           ++c)
        inverse_plastic[stored_row[c]][stored_col[c]] = internal[c];
      return principal_log_strain(
        symmetrize(F3 * Tensor<2, 3>(inverse_plastic) * transpose(F3)));
    }
  } // namespace

  template <int dim>
  HenckyPlasticity<dim>::HenckyPlasticity(const LameParameters &lame)
    : bulk_modulus(lame.lambda + 2. / 3. * lame.mu)
    , shear_modulus(lame.mu)
  {}

  template <int dim>
  std::vector<FieldDescription>
  HenckyPlasticity<dim>::internal_variables() const
  {
    std::vector<FieldDescription> fields = {{"inverse_plastic_cauchy_green",
                                             n_inverse_plastic},
                                            {"plastic_strain", 1},
                                            {"plastic_work", 1}};
    if (dim == 2)
      fields.push_back({"stress_zz", 1});
    for (const auto &f : model_variables())
      fields.push_back(f);
    return fields;
  }

  template <int dim>
  void
  HenckyPlasticity<dim>::initialize_internal_variables(
    ArrayView<double> internal) const
  {
    for (unsigned int c = 0; c < internal.size(); ++c)
      internal[c] = c < 3 ? 1. : 0.;
  }

  template <int dim>
  std::array<double, 3>
  HenckyPlasticity<dim>::kirchhoff(const std::array<double, 3> &strain) const
  {
    const double          volumetric = strain[0] + strain[1] + strain[2];
    std::array<double, 3> tau;
    for (unsigned int a = 0; a < 3; ++a)
      tau[a] = bulk_modulus * volumetric +
               2. * shear_modulus * (strain[a] - volumetric / 3.);
    return tau;
  }

  template <int dim>
  void
  HenckyPlasticity<dim>::update_stress(const Tensor<2, dim> &,
                                       const Tensor<2, dim>    &F,
                                       const double             dt,
                                       SymmetricTensor<2, dim> &stress,
                                       ArrayView<double>        internal) const
  {
    const Tensor<2, 3>    F3        = embed_deformation<dim>(F);
    const PrincipalStrain trial     = trial_strain<dim>(F3, internal);
    std::array<double, 3> strain    = trial.strain;
    const double          d_plastic = return_to_surface(strain, dt, internal);
    const std::array<double, 3> tau = kirchhoff(strain);
    if (d_plastic > 0)
      {
        internal[plastic_strain_index] += d_plastic;
        for (unsigned int a = 0; a < 3; ++a)
          internal[plastic_work_index] +=
            tau[a] * (trial.strain[a] - strain[a]);
      }

    // The new elastic b_e on the trial directions gives the new C_p^-1.
    std::array<double, 3> b_elastic;
    for (unsigned int a = 0; a < 3; ++a)
      b_elastic[a] = std::exp(2. * strain[a]);
    const Tensor<2, 3>          F_inverse       = invert(F3);
    const SymmetricTensor<2, 3> inverse_plastic = symmetrize(
      F_inverse * Tensor<2, 3>(from_principal(b_elastic, trial.direction)) *
      transpose(F_inverse));
    for (unsigned int c = 0; c < n_inverse_plastic; ++c)
      internal[c] = inverse_plastic[stored_row[c]][stored_col[c]];

    const SymmetricTensor<2, 3> sigma =
      from_principal(tau, trial.direction) / determinant(F3);
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        stress[i][j] = sigma[i][j];
    if constexpr (dim == 2)
      internal[n_inverse_plastic + 2] = sigma[2][2];
  }

  template <int dim>
  void
  HenckyPlasticity<dim>::renormalise_deformation(
    Tensor<2, dim>   &F,
    ArrayView<double> internal) const
  {
    const PrincipalStrain b =
      trial_strain<dim>(embed_deformation<dim>(F), internal);
    std::array<double, 3> stretch;
    for (unsigned int a = 0; a < 3; ++a)
      stretch[a] = std::exp(b.strain[a]);
    // b_e^(1/2); in 2D its plane block (b_e's zz is C_p^-1's and stays).
    const SymmetricTensor<2, 3> root = from_principal(stretch, b.direction);
    Tensor<2, dim>              root_in_plane;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        root_in_plane[i][j] = root[i][j];
    const double scale =
      std::pow(determinant(F) / determinant(root_in_plane), 1. / dim);
    F = scale * root_in_plane;
    for (unsigned int c = 0; c < n_inverse_plastic; ++c)
      if (stored_row[c] != stored_col[c])
        internal[c] = 0.;
      else if (stored_row[c] < dim)
        internal[c] = 1. / (scale * scale);
  }

  template <int dim>
  double
  HenckyPlasticity<dim>::wave_speed(const Tensor<2, dim> &) const
  {
    return std::sqrt((bulk_modulus + 4. / 3. * shear_modulus) / this->density);
  }

  template <int dim>
  double
  HenckyPlasticity<dim>::out_of_plane_stress(
    const Tensor<2, dim> &,
    const SymmetricTensor<2, dim> &,
    ArrayView<const double> internal) const
  {
    return dim == 2 ? internal[n_inverse_plastic + 2] : 0.;
  }

  template <int dim>
  double
  HenckyPlasticity<dim>::strain_energy_density(
    const Tensor<2, dim> &F,
    const SymmetricTensor<2, dim> &,
    ArrayView<const double> internal) const
  {
    return elastic_energy(
      trial_strain<dim>(embed_deformation<dim>(F), internal).strain);
  }

  template <int dim>
  double
  HenckyPlasticity<dim>::elastic_energy(
    const std::array<double, 3> &strain) const
  {
    const double volumetric = strain[0] + strain[1] + strain[2];
    return 0.5 * bulk_modulus * volumetric * volumetric +
           shear_modulus * deviator_squared(strain);
  }

  template class HenckyPlasticity<2>;
  template class HenckyPlasticity<3>;
} // namespace dealmpm
