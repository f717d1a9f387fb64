#include <deal.II/base/mpi.h>

#include <dealmpm/fem/region_contact.h>
#include <dealmpm/grid/nodal_exchange.h>
#include <dealmpm/transfer/stencil_order.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace dealmpm
{
  namespace
  {
    /** How far the domain of the particle at @p x (its initial volume's
     * cube of side 2 @p half_side, carried by @p F: a parallelepiped)
     * is from the plane through @p surface with unit normal @p n, on the
     * normal's side (negative: it reaches past the plane). */
    template <int dim>
    double
    domain_distance(const Point<dim>     &x,
                    const double          half_side,
                    const Tensor<2, dim> &F,
                    const Point<dim>     &surface,
                    const Tensor<1, dim> &n)
    {
      // The half-extent along n: the sum over the half-edges F (a e_d)
      // of |n . F a e_d|.
      const Tensor<1, dim> Ftn    = transpose(F) * n;
      double               extent = 0;
      for (unsigned int d = 0; d < dim; ++d)
        extent += half_side * std::abs(Ftn[d]);
      return (x - surface) * n - extent;
    }
  } // namespace

  template <int dim>
  RegionContact<dim>::RegionContact(
    SolidRegion<dim>                           &region,
    const std::map<types::boundary_id, double> &friction)
    : region(region)
  {
    for (const auto &item : friction)
      ids.insert(item.first);
    // A node's mu: that of the first of its faces' ids (the area normals
    // of an id say which nodes are on its faces).
    const auto         &nodes = region.get_nodes();
    std::vector<double> node_mu(nodes.size(), -1.);
    for (const auto &[id, coefficient] : friction)
      {
        const std::vector<Tensor<1, dim>> a = region.area_normals({id});
        for (unsigned int k = 0; k < nodes.size(); ++k)
          if (a[k].norm() > 0 && node_mu[k] < 0)
            node_mu[k] = coefficient;
      }
    for (unsigned int k = 0; k < nodes.size(); ++k)
      if (node_mu[k] >= 0 &&
          nodes[k].kind != SolidRegion<dim>::Node::Kind::bonded)
        {
          local.push_back(k);
          local_mu.push_back(node_mu[k]);
        }
  }

  template <int dim>
  void
  RegionContact<dim>::grid_changed(const BackgroundGrid<dim> &grid)
  {
    points.grid_changed(grid);
    for (NodalVector *v : {&mass, &mu})
      v->reinit(grid.partitioner);
    for (unsigned int d = 0; d < dim; ++d)
      for (auto *v : {&momentum[d], &normal[d], &position[d], &change[d]})
        v->reinit(grid.partitioner);
    gap.clear(); // sized for the MPM fields in measure_gaps()
  }

  template <int dim>
  void
  RegionContact<dim>::correct(NodalFields<dim>  &fields,
                              const unsigned int i,
                              const double       gap_i,
                              const double       mass_threshold,
                              const double       dt)
  {
    const double m_a = fields.mass.local_element(i);
    const double m_b = mass.local_element(i);
    if (!(m_a > mass_threshold) || !(m_b > 0))
      return;
    Tensor<1, dim> v_a, v_b, n;
    for (unsigned int d = 0; d < dim; ++d)
      {
        v_a[d] = fields.velocity[d].local_element(i);
        v_b[d] =
          momentum[d].local_element(i) / m_b + change[d].local_element(i);
        n[d] = normal[d].local_element(i);
      }
    if (!(n.norm() > 0))
      return;
    n /= n.norm();
    // n points out of the region, towards the MPM material.
    const Tensor<1, dim> relative =
      m_b / (m_a + m_b) * (v_a - v_b); // v_a - v_cm
    const double approach = relative * n;
    if (!(approach < 0))
      return;
    // Apart at the end of the step: no contact yet (the gap check).
    if (!(gap_i + (v_a - v_b) * n * dt < 0))
      return;
    const Tensor<1, dim> tangential    = relative - approach * n;
    const double         slip          = tangential.norm();
    const double         mu_i          = mu.local_element(i) / m_b;
    Tensor<1, dim>       normal_change = -approach * n;
    Tensor<1, dim>       friction_change;
    if (slip > 0)
      friction_change = -std::min(1., mu_i * (-approach) / slip) * tangential;
    const Tensor<1, dim> dv_a  = normal_change + friction_change;
    const Tensor<1, dim> dv_b  = -m_a / m_b * dv_a;
    const Tensor<1, dim> a_new = v_a + dv_a, b_new = v_b + dv_b;
    work_done += m_a * (dv_a * a_new) + m_b * (dv_b * b_new);
    const double friction = m_a * (friction_change * (a_new - b_new));
    friction_done += friction;
    if (friction < 0)
      dissipated.emplace_back(i, -friction);
    for (unsigned int d = 0; d < dim; ++d)
      {
        fields.velocity[d].local_element(i) += dv_a[d];
        fields.velocity_increment[d].local_element(i) += dv_a[d];
        change[d].local_element(i) += dv_b[d];
      }
  }

  template <int dim>
  std::vector<double>
  RegionContact<dim>::node_values(const double dt) const
  {
    using Kind = typename SolidRegion<dim>::Node::Kind;
    // x, m, m v_predicted, a n, mu per node.
    const std::vector<Tensor<1, dim>> area = region.area_normals(ids);
    std::vector<double>               mine;
    mine.reserve(local.size() * n_values);
    for (unsigned int j = 0; j < local.size(); ++j)
      {
        const auto      &node = region.get_nodes()[local[j]];
        const Point<dim> x    = region.position(node);
        const double     m    = region.mass_of(node);
        Tensor<1, dim>   v    = region.velocity_of(node);
        if (node.kind == Kind::free)
          v += dt / m * region.force_of(node);
        append_components<dim>(mine, x);
        mine.push_back(m);
        append_components<dim>(mine, m * v);
        append_components<dim>(mine, area[local[j]]);
        mine.push_back(local_mu[j]);
      }
    return mine;
  }

  template <int dim>
  void
  RegionContact<dim>::spread_to_grid()
  {
    for (NodalVector *v : {&mass, &mu})
      {
        *v = 0;
        v->zero_out_ghost_values();
      }
    for (unsigned int d = 0; d < dim; ++d)
      for (NodalVector *v :
           {&momentum[d], &normal[d], &position[d], &change[d]})
        {
          *v = 0;
          v->zero_out_ghost_values();
        }
    for (const auto &p : points.placed())
      for (unsigned int n = 0; n < p.nodes.size(); ++n)
        {
          const double       w = p.weights[n];
          const unsigned int i = p.nodes[n];
          const double       m = points.value(p.point, dim);
          mass.local_element(i) += w * m;
          mu.local_element(i) += w * m * points.value(p.point, 3 * dim + 1);
          for (unsigned int d = 0; d < dim; ++d)
            {
              momentum[d].local_element(i) +=
                w * points.value(p.point, dim + 1 + d);
              normal[d].local_element(i) +=
                w * points.value(p.point, 2 * dim + 1 + d);
              position[d].local_element(i) += w * m * points.value(p.point, d);
            }
        }
    NodalExchange sums;
    sums.add(mass).add(mu).add(momentum).add(normal).add(position);
    sums.sum_ghosts_into_owners();
    // The gaps are measured from the particles, which reach ghost nodes.
    NodalExchange().add(mass).add(normal).add(position).copy_owners_to_ghosts();
  }

  template <int dim>
  void
  RegionContact<dim>::measure_gaps(const BackgroundGrid<dim> &grid,
                                   const ParticleSet<dim>    &particles,
                                   const Stencil<dim>        &stencil,
                                   const unsigned int         n_fields)
  {
    if (gap.size() != n_fields)
      {
        gap.resize(n_fields);
        for (NodalVector &g : gap)
          g.reinit(grid.partitioner);
      }
    // Ghost entries too: the particles of this rank reach them.
    const double far = std::numeric_limits<double>::max();
    for (NodalVector &g : gap)
      for (unsigned int i = 0; i < g.get_partitioner()->locally_owned_size() +
                                     g.get_partitioner()->n_ghost_indices();
           ++i)
        g.local_element(i) = far;
    const CoreFields &f = particles.fields;
    for_each_particle_in_stencil_order(
      grid,
      particles,
      [&](const std::size_t k, const auto &p, const GridCell<dim> &) {
        // Most particles reach no node of the region: leave them at once.
        bool near = false;
        for (unsigned int e = stencil.begin[k]; e < stencil.begin[k + 1]; ++e)
          near = near || mass.local_element(stencil.node[e]) > 0;
        if (!near)
          return;
        const auto   props = p.get_properties();
        NodalVector &g     = gap[n_fields == 1 ? 0 : particles.body_of(props)];
        const double half_side =
          0.5 * std::pow(props[f.initial_volume], 1. / dim);
        const Tensor<2, dim> F =
          read_tensor<dim>(&props[0] + f.deformation_gradient);
        for (unsigned int e = stencil.begin[k]; e < stencil.begin[k + 1]; ++e)
          {
            const unsigned int i = stencil.node[e];
            if (!(stencil.N[e] > 0) || !(mass.local_element(i) > 0))
              continue;
            Tensor<1, dim> n;
            Point<dim>     surface;
            for (unsigned int d = 0; d < dim; ++d)
              {
                n[d]       = normal[d].local_element(i);
                surface[d] = position[d].local_element(i);
              }
            if (!(n.norm() > 0))
              continue;
            const double distance =
              domain_distance(p.get_location(),
                              half_side,
                              F,
                              surface / mass.local_element(i),
                              n / n.norm());
            g.local_element(i) = std::min(g.local_element(i), distance);
          }
      });
    for (NodalVector &g : gap)
      g.compress(VectorOperation::min);
  }

  template <int dim>
  void
  RegionContact<dim>::correct_all(NodalFieldSet<dim> &set,
                                  const double        mass_threshold,
                                  const double        dt)
  {
    // The MPM fields the region meets: each body's when bodies have
    // their own (contact between them), else the one core field. Pairs
    // are corrected one after the other, the region's field velocity
    // carried from pair to pair, each exact in momentum.
    std::vector<NodalFields<dim> *> mpm_fields;
    if (set.has_body_fields())
      for (NodalFields<dim> &body : set.body)
        mpm_fields.push_back(&body);
    else
      mpm_fields.push_back(&set.core);
    dissipated.clear();
    const unsigned int n_owned = mass.locally_owned_size();
    for (unsigned int b = 0; b < mpm_fields.size(); ++b)
      for (unsigned int i = 0; i < n_owned; ++i)
        correct(*mpm_fields[b], i, gap[b].local_element(i), mass_threshold, dt);
    NodalExchange ghosts;
    for (NodalFields<dim> *fields : mpm_fields)
      ghosts.add(fields->velocity).add(fields->velocity_increment);
    ghosts.add(change).copy_owners_to_ghosts();
  }

  template <int dim>
  void
  RegionContact<dim>::pass_back_changes(const BackgroundGrid<dim> &grid)
  {
    std::vector<double> dv(dim * points.n_points(), 0.);
    for (const auto &p : points.placed())
      for (unsigned int n = 0; n < p.nodes.size(); ++n)
        for (unsigned int d = 0; d < dim; ++d)
          dv[dim * p.point + d] +=
            p.weights[n] * change[d].local_element(p.nodes[n]);
    const std::vector<double> mine_dv =
      points.sum_to_owners(dv, dim, grid.comm, false);
    std::vector<Tensor<1, dim>> correction(local.size());
    for (unsigned int j = 0; j < local.size(); ++j)
      for (unsigned int d = 0; d < dim; ++d)
        correction[j][d] = mine_dv[dim * j + d];
    region.set_velocity_corrections(local, correction);
  }

  template <int dim>
  void
  RegionContact<dim>::apply(const BackgroundGrid<dim> &grid,
                            NodalFieldSet<dim>        &set,
                            const ParticleSet<dim>    &particles,
                            const Stencil<dim>        &stencil,
                            const double               mass_threshold,
                            const double               dt)
  {
    points.gather_and_place(grid, node_values(dt), n_values);
    spread_to_grid();
    measure_gaps(grid,
                 particles,
                 stencil,
                 set.has_body_fields() ? set.body.size() : 1);
    correct_all(set, mass_threshold, dt);
    pass_back_changes(grid);
  }

  template class RegionContact<2>;
  template class RegionContact<3>;
} // namespace dealmpm
