#include <dealmpm/fem/region_heat.h>

namespace dealmpm
{
  template <int dim>
  RegionHeat<dim>::RegionHeat(SolidRegion<dim>         &solid,
                              BondedCoupling<dim>      *bonded,
                              const RegionContact<dim> *contact)
    : solid(solid)
    , bonded(bonded)
    , contact(contact)
  {
    if (bonded)
      bonded->carry_heat();
  }

  namespace
  {
    /** Add heat value @p k (BondedCoupling::heat_value()) of every
     * placed bonded node to @p to at the grid nodes, with the weights. */
    template <int dim>
    void
    add_weighted(BondedCoupling<dim> &bonded,
                 const unsigned int   k,
                 NodalVector         &to)
    {
      for (const auto &p : bonded.nodes_on_grid().placed())
        for (unsigned int n = 0; n < p.nodes.size(); ++n)
          to.local_element(p.nodes[n]) +=
            p.weights[n] * bonded.heat_value(p, k);
    }
  } // namespace

  template <int dim>
  void
  RegionHeat<dim>::add_capacity(NodalVector &capacity, NodalVector &heat) const
  {
    if (!bonded)
      return;
    add_weighted(*bonded, 0, capacity);
    add_weighted(*bonded, 1, heat);
  }

  template <int dim>
  void
  RegionHeat<dim>::add_power(NodalVector &power) const
  {
    if (bonded)
      add_weighted(*bonded, 2, power);
  }

  template <int dim>
  void
  RegionHeat<dim>::conduct(const double time, const double dt)
  {
    solid.conduct(time, dt);
    if (bonded)
      for (const unsigned int k : bonded->bonded_nodes())
        solid.add_conducted_heat(k, -solid.heat_debt_of(k) / dt);
  }

  template <int dim>
  typename HeatPartner<dim>::Flows
  RegionHeat<dim>::advance(const NodalVector &increment,
                           const NodalVector &temperature,
                           const MPI_Comm     comm,
                           const double       dt)
  {
    if (bonded)
      {
        // Per point: the increments' and the new temperatures' sums.
        NodesOnGrid<dim>   &points = bonded->nodes_on_grid();
        std::vector<double> sums(2 * points.n_points(), 0.);
        for (const auto &p : points.placed())
          for (unsigned int n = 0; n < p.nodes.size(); ++n)
            {
              sums[2 * p.point] +=
                p.weights[n] * increment.local_element(p.nodes[n]);
              sums[2 * p.point + 1] +=
                p.weights[n] * temperature.local_element(p.nodes[n]);
            }
        const std::vector<double> mine = points.sum_to_owners(sums, 2, comm);
        const std::vector<unsigned int> &local = bonded->bonded_nodes();
        std::vector<double>              change(local.size());
        for (std::size_t j = 0; j < local.size(); ++j)
          {
            const auto  &node = solid.get_nodes()[local[j]];
            const double T    = solid.temperature_of(node);
            change[j]         = mine[2 * j + 1] - T;
            solid.heat_debt_of(local[j]) =
              solid.heat_capacity_of(node) * (change[j] - mine[2 * j]);
          }
        solid.add_to_temperatures(local, change);
      }
    const auto step = solid.advance_temperature(dt);
    return {step.given, step.generated};
  }

  template <int dim>
  double
  RegionHeat<dim>::stored_heat() const
  {
    double owed = 0;
    if (bonded)
      for (const unsigned int k : bonded->bonded_nodes())
        owed += solid.heat_debt_of(k);
    return solid.stored_heat() - owed;
  }

  template class RegionHeat<2>;
  template class RegionHeat<3>;
} // namespace dealmpm
