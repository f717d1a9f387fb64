#include <dealmpm/grid/grid_update.h>
#include <dealmpm/grid/nodal_exchange.h>

#include <algorithm>

namespace dealmpm
{
  namespace
  {
    /** increment_weight = min(1, m / @p stable_mass) on the owned nodes
     * (sized on first use); its ghosts are left to the caller. */
    template <int dim>
    void
    set_owned_increment_weights(NodalFields<dim> &fields,
                                const double      stable_mass)
    {
      if (fields.increment_weight.size() != fields.mass.size())
        fields.increment_weight.reinit(fields.mass);
      const unsigned int n_owned = fields.mass.locally_owned_size();
      const double      *mass    = fields.mass.begin();
      double            *w       = fields.increment_weight.begin();
      for (unsigned int i = 0; i < n_owned; ++i)
        w[i] = std::min(1., mass[i] / stable_mass);
    }

    /** Whether a node, owned or ghost, is light: 0 < w < 1 (empty nodes,
     * w = 0, are in no particle's stencil). Most steps of most scenes have
     * none: then G2P is left without weights. When there are some, G2P
     * looks at each cell's weights as it reads the cell's nodes (no pass
     * over the grid here). */
    template <int dim>
    void
    find_light_nodes(NodalFields<dim> &fields)
    {
      const double      *w = fields.increment_weight.begin();
      const unsigned int n_local =
        fields.increment_weight.locally_owned_size() +
        fields.increment_weight.get_partitioner()->n_ghost_indices();
      fields.has_light_nodes = std::any_of(w, w + n_local, [](const double x) {
        return x > 0 && x < 1;
      });
    }
  } // namespace

  template <int dim>
  void
  set_increment_weights(NodalFields<dim> &fields, const double stable_mass)
  {
    set_owned_increment_weights(fields, stable_mass);
    fields.increment_weight.update_ghost_values();
    find_light_nodes(fields);
  }

  template <int dim>
  void
  update_nodal_velocity(NodalFields<dim>              &fields,
                        const double                   dt,
                        const double                   mass_threshold,
                        const BoundaryConditions<dim> &boundary_conditions,
                        const double                   stable_mass)
  {
    const unsigned int n_owned = fields.mass.locally_owned_size();
    const double      *mass    = fields.mass.begin();
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double *p  = fields.momentum[d].begin();
        const double *f  = fields.force[d].begin();
        double       *v  = fields.velocity[d].begin();
        double       *dv = fields.velocity_increment[d].begin();
        for (unsigned int i = 0; i < n_owned; ++i)
          if (mass[i] > mass_threshold)
            {
              dv[i] = dt * f[i] / mass[i];
              v[i]  = p[i] / mass[i] + dv[i];
            }
          else
            v[i] = dv[i] = 0.;
      }
    boundary_conditions.project_with_increment(fields.velocity,
                                               fields.velocity_increment);

    // One message per neighbour for the ghosts of v*, the increment and
    // the weights.
    NodalExchange ghosts;
    ghosts.add(fields.velocity);
    ghosts.add(fields.velocity_increment);
    if (stable_mass > 0)
      {
        set_owned_increment_weights(fields, stable_mass);
        ghosts.add(fields.increment_weight);
      }
    ghosts.copy_owners_to_ghosts();
    if (stable_mass > 0)
      find_light_nodes(fields);
    else
      fields.has_light_nodes = false; // no stale weights in G2P
  }

  template <int dim>
  void
  velocity_from_momentum(NodalFields<dim>              &fields,
                         const double                   mass_threshold,
                         const BoundaryConditions<dim> &boundary_conditions)
  {
    const unsigned int n_owned = fields.mass.locally_owned_size();
    const double      *mass    = fields.mass.begin();
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double *p = fields.momentum[d].begin();
        double       *v = fields.velocity[d].begin();
        for (unsigned int i = 0; i < n_owned; ++i)
          v[i] = mass[i] > mass_threshold ? p[i] / mass[i] : 0.;
      }
    boundary_conditions.project(fields.velocity);
    NodalExchange ghosts;
    ghosts.add(fields.velocity);
    ghosts.copy_owners_to_ghosts();
  }

#define DEALMPM_INSTANTIATE(dim)                                         \
  template void set_increment_weights(NodalFields<dim> &, double);       \
  template void velocity_from_momentum(NodalFields<dim> &,               \
                                       double,                           \
                                       const BoundaryConditions<dim> &); \
  template void update_nodal_velocity(NodalFields<dim> &,                \
                                      double,                            \
                                      double,                            \
                                      const BoundaryConditions<dim> &,   \
                                      double);
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
