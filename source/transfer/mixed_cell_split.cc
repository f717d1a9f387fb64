#include <dealmpm/transfer/mixed_cell_split.h>
#include <dealmpm/transfer/stencil_order.h>

#include <algorithm>
#include <cmath>

namespace dealmpm
{
  namespace
  {
    /** The cell's interface normal: the unit vector from the softest
     * material's centroid to the stiffest one's; false where those are
     * closer than 1e-3 @p h (interleaved materials: no layer to split
     * along). Also sums each material's @p volume in the cell. */
    template <int dim, typename Members>
    bool
    interface_normal(const Members             &members,
                     const std::vector<double> &modulus,
                     const double               h,
                     std::vector<double>       &volume,
                     Tensor<1, dim>            &n)
    {
      const unsigned int          n_materials = modulus.size();
      std::vector<Tensor<1, dim>> centroid(n_materials);
      for (const auto &p : members)
        {
          volume[p.material] += p.volume;
          centroid[p.material] += p.volume * p.x;
        }
      unsigned int stiffest = members.front().material, softest = stiffest;
      for (unsigned int m = 0; m < n_materials; ++m)
        if (volume[m] > 0)
          {
            centroid[m] /= volume[m];
            if (modulus[m] > modulus[stiffest])
              stiffest = m;
            if (modulus[m] < modulus[softest])
              softest = m;
          }
      n = centroid[stiffest] - centroid[softest];
      if (!(n.norm() > 1e-3 * h))
        return false;
      n /= n.norm();
      return true;
    }

    /** The cell's volume and the volume mean of its particles' n.L.n. */
    struct CellRate
    {
      double total_volume = 0, mean_rate = 0;
    };

    /** Per material the volume sums of n.L.n (@p rate) and n.sigma.n
     * (@p stress) of the cell's particles. */
    template <int dim, typename Members>
    CellRate
    normal_sums(const Members          &members,
                const Stencil<dim>     &stencil,
                const NodalFields<dim> &fields,
                const unsigned int      stress_field,
                const Tensor<1, dim>   &n,
                std::vector<double>    &rate,
                std::vector<double>    &stress)
    {
      CellRate cell;
      for (const auto &p : members)
        {
          double rate_p = 0;
          for (unsigned int e = stencil.begin[p.k]; e < stencil.begin[p.k + 1];
               ++e)
            {
              double v_n = 0;
              for (unsigned int d = 0; d < dim; ++d)
                v_n += n[d] * fields.velocity[d].local_element(stencil.node[e]);
              rate_p += v_n * (n * stencil.grad_N[e]);
            }
          rate[p.material] += p.volume * rate_p;
          stress[p.material] +=
            p.volume * (n * (read_symmetric<dim>(p.props + stress_field) * n));
          cell.mean_rate += p.volume * rate_p;
          cell.total_volume += p.volume;
        }
      cell.mean_rate /= cell.total_volume;
      return cell;
    }

    /** The factor on the part that equalises the materials' stresses: 1,
     * or less if it would strain some material by more than
     * max_relaxation_strain in this step. A stiff neighbour's stress needs
     * little strain of either (its difference over the stiff modulus), but
     * two similar materials with very different histories would tear. */
    double
    relaxation_scale(const std::vector<double> &volume,
                     const std::vector<double> &stress,
                     const std::vector<double> &modulus,
                     const double               relaxed)
    {
      const double max_relaxation_strain = 1e-3;
      double       scale                 = 1;
      for (unsigned int m = 0; m < modulus.size(); ++m)
        if (volume[m] > 0)
          {
            const double strain = std::abs(relaxed - stress[m]) / modulus[m];
            if (strain > max_relaxation_strain * scale)
              scale = max_relaxation_strain / strain;
          }
      return scale;
    }
  } // namespace

  template <int dim>
  MixedCellSplit<dim>::MixedCellSplit(
    const std::vector<std::unique_ptr<Material<dim>>> &materials)
  {
    // The elastic (unloading) stiffness at the reference state: what the
    // models' CFL wave speed gives, and what a plastic model unloads with.
    const Tensor<2, dim> I = unit_symmetric_tensor<dim>();
    for (const auto &m : materials)
      modulus.push_back(m->density * m->wave_speed(I) * m->wave_speed(I));
  }

  template <int dim>
  bool
  MixedCellSplit<dim>::needed() const
  {
    return std::any_of(modulus.begin(), modulus.end(), [&](const double M) {
      return M != modulus.front();
    });
  }

  template <int dim>
  void
  MixedCellSplit<dim>::prepare(const BackgroundGrid<dim> &grid,
                               const ParticleSet<dim>    &particles,
                               const Stencil<dim>        &stencil,
                               const NodalFields<dim>    &fields,
                               const double               dt)
  {
    const CoreFields &f = particles.fields;
    cells_begin         = grid.cells.data();
    particle_set        = &particles;
    first_correction.assign(grid.cells.size(), -1);
    corrections.clear();
    unsigned int                                       k = 0;
    const ParticlesByCell<dim, const ParticleSet<dim>> by_cell(grid, particles);
    for (unsigned int c = 0; c < grid.cells.size(); ++c)
      {
        members.clear();
        bool mixed = false;
        by_cell.for_each(c, [&](const auto &p) {
          const ArrayView<const double> props = p.get_properties();
          const unsigned int            m     = particles.material_of(props);
          const double                  volume =
            props[f.initial_volume] *
            determinant(read_tensor<dim>(&props[f.deformation_gradient]));
          mixed = mixed || (!members.empty() &&
                            modulus[m] != modulus[members.front().material]);
          members.push_back({k++, m, volume, p.get_location(), props.data()});
        });
        if (!mixed)
          continue;
        const unsigned int before = corrections.size();
        split_cell(stencil, fields, f.stress, grid.cells[c].h, dt);
        if (corrections.size() > before)
          first_correction[c] = static_cast<int>(before);
      }
  }

  template <int dim>
  void
  MixedCellSplit<dim>::split_cell(const Stencil<dim>     &stencil,
                                  const NodalFields<dim> &fields,
                                  const unsigned int      stress_field,
                                  const double            h,
                                  const double            dt)
  {
    const unsigned int  n_materials = modulus.size();
    std::vector<double> volume(n_materials), rate(n_materials),
      stress(n_materials);
    Tensor<1, dim> n;
    if (!interface_normal(members, modulus, h, volume, n))
      return;
    const CellRate cell =
      normal_sums(members, stencil, fields, stress_field, n, rate, stress);
    // Compliance C = sum phi_m / M_m; the stress the materials share after
    // the step, s* = (sum phi_m s_m / M_m + dt d) / C, keeps the volume
    // change: sum phi_m (s* - s_m) / (M_m dt) = d.
    double compliance = 0, shared = 0;
    for (unsigned int m = 0; m < n_materials; ++m)
      if (volume[m] > 0)
        {
          stress[m] /= volume[m];
          rate[m] /= volume[m];
          compliance += volume[m] / cell.total_volume / modulus[m];
          shared += volume[m] / cell.total_volume * stress[m] / modulus[m];
        }
    const double relaxed = shared / compliance;
    // The rate split alone (equal stress increments) and the part that
    // equalises the stresses the materials bring, scaled down where it
    // would tear.
    const double scale = relaxation_scale(volume, stress, modulus, relaxed);
    const Tensor<2, dim> nn = outer_product(n, n);
    for (unsigned int m = 0; m < n_materials; ++m)
      corrections.push_back(
        volume[m] > 0 ?
          (cell.mean_rate / (modulus[m] * compliance) +
           scale * (relaxed - stress[m]) / (modulus[m] * dt) - rate[m]) *
            nn :
          Tensor<2, dim>());
  }

#define DEALMPM_INSTANTIATE(dim) template class MixedCellSplit<dim>;
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
