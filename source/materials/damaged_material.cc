#include <deal.II/base/symmetric_tensor.h>

#include <dealmpm/materials/damaged_material.h>

#include <algorithm>
#include <cmath>

namespace dealmpm
{
  namespace
  {
    constexpr unsigned int
    n_stress(const int dim)
    {
      return dim * (dim + 1) / 2;
    }
  } // namespace

  double
  DamageLaw::damage(const double q) const
  {
    if (q < onset)
      return 0;
    if (failure <= onset || q >= failure)
      return 1;
    return (q - onset) / (failure - onset);
  }

  template <int dim>
  DamagedMaterial<dim>::DamagedMaterial(std::unique_ptr<Material<dim>> inner,
                                        const DamageLaw               &law,
                                        const std::string             &suffix)
    : inner(std::move(inner))
    , law(law)
    , suffix(suffix)
  {
    this->density    = this->inner->density;
    inner_dissipates = this->inner->dissipates();
    n_inner          = 0;
    for (const FieldDescription &f : this->inner->internal_variables())
      n_inner += f.n_components;
  }

  template <int dim>
  std::vector<FieldDescription>
  DamagedMaterial<dim>::internal_variables() const
  {
    std::vector<FieldDescription> list = inner->internal_variables();
    list.push_back({"damage" + suffix, 1});
    list.push_back({"effective_stress" + suffix, n_stress(dim)});
    list.push_back({"damage_work" + suffix, 1});
    return list;
  }

  template <int dim>
  void
  DamagedMaterial<dim>::initialize_internal_variables(
    ArrayView<double> internal) const
  {
    inner->initialize_internal_variables(
      make_array_view(internal.begin(), internal.begin() + n_inner));
    std::fill(internal.begin() + n_inner, internal.end(), 0.);
  }

  template <int dim>
  SymmetricTensor<2, dim>
  DamagedMaterial<dim>::effective_stress(const SymmetricTensor<2, dim> &stress,
                                         ArrayView<const double> internal) const
  {
    if (internal[n_inner] == 0.)
      return stress;
    SymmetricTensor<2, dim> s;
    for (unsigned int i = 0; i < n_stress(dim); ++i)
      s.access_raw_entry(i) = internal[n_inner + 1 + i];
    return s;
  }

  template <int dim>
  void
  DamagedMaterial<dim>::update_stress(const Tensor<2, dim>    &L,
                                      const Tensor<2, dim>    &F,
                                      const double             dt,
                                      SymmetricTensor<2, dim> &stress,
                                      ArrayView<double>        internal) const
  {
    const ArrayView<double> own =
      make_array_view(internal.begin(), internal.begin() + n_inner);
    const double D_old = internal[n_inner];
    const double inner_work_old =
      inner->dissipates() ? inner->dissipated_energy_density(own) : 0.;
    SymmetricTensor<2, dim> s = effective_stress(stress, internal);
    inner->update_stress(L, F, dt, s, own);

    double q = 0;
    if (law.measure == DamageLaw::Measure::principal_strain)
      {
        // The largest eigenvalue of b = F F^T is at most tr/d +
        // sqrt((d - 1) / d |dev b|^2) (Wolkowicz and Styan): most points
        // are far from failing, and skip the eigenvalues.
        const SymmetricTensor<2, dim> b =
          symmetrize(Tensor<2, dim>(F * transpose(F)));
        const double mean = trace(b) / dim;
        const double bound =
          mean +
          std::sqrt(
            std::max(0., (dim - 1.) / dim * (b * b - dim * mean * mean)));
        q = bound < (1. + law.onset) * (1. + law.onset) ?
              -1. :
              std::sqrt(eigenvalues(b)[0]) - 1.;
      }
    else
      q = eigenvalues(full_stress(*inner, F, s, own))[0];
    const double D = std::max(D_old, law.damage(q));

    // Released energy and the model's own dissipation, in the share the
    // softened stress did.
    double &work = internal[n_inner + 1 + n_stress(dim)];
    if (D > D_old)
      work += (D - D_old) * inner->strain_energy_density(F, s, own);
    if (inner_dissipates)
      work +=
        (1. - D) * (inner->dissipated_energy_density(own) - inner_work_old);
    if (D >= 1. && D_old < 1.)
      ++newly_failed;
    internal[n_inner] = D;
    for (unsigned int i = 0; i < n_stress(dim); ++i)
      internal[n_inner + 1 + i] = s.access_raw_entry(i);
    stress = (1. - D) * s;
  }

  template <int dim>
  double
  DamagedMaterial<dim>::wave_speed(const Tensor<2, dim> &F) const
  {
    return inner->wave_speed(F);
  }

  template <int dim>
  double
  DamagedMaterial<dim>::out_of_plane_stress(
    const Tensor<2, dim>          &F,
    const SymmetricTensor<2, dim> &stress,
    ArrayView<const double>        internal) const
  {
    return (1. - internal[n_inner]) *
           inner->out_of_plane_stress(F,
                                      effective_stress(stress, internal),
                                      inner_variables(internal));
  }

  template <int dim>
  double
  DamagedMaterial<dim>::strain_energy_density(
    const Tensor<2, dim>          &F,
    const SymmetricTensor<2, dim> &stress,
    ArrayView<const double>        internal) const
  {
    return (1. - internal[n_inner]) *
           inner->strain_energy_density(F,
                                        effective_stress(stress, internal),
                                        inner_variables(internal));
  }

  template <int dim>
  double
  DamagedMaterial<dim>::dissipated_energy_density(
    ArrayView<const double> internal) const
  {
    return internal[n_inner + 1 + n_stress(dim)];
  }

  template class DamagedMaterial<2>;
  template class DamagedMaterial<3>;
} // namespace dealmpm
