#pragma once

#include <dealmpm/effects/heat_conduction.h>
#include <dealmpm/fem/bonded_coupling.h>
#include <dealmpm/fem/solid_region.h>

namespace dealmpm
{
  /**
   * An FEM region's heat in the heat conduction effect's step (a
   * HeatPartner): the region conducts on its own mesh (SolidRegion's
   * heat), and its bonded nodes are the grid's, as for their momentum:
   * each gives the grid nodes of its cell its capacity C and heat C T
   * with the linear weights, and its conducted heat Q, and takes back the
   * grid's temperature there, sum N_I T_I (as it takes v*). Taking only
   * the increments (as particles do) would keep a bonded node's start
   * difference from the grid for ever: a region bonded hot to a cold
   * body would never reach their common temperature. The heat the node
   * gains by taking the grid's temperature instead of its own plus the
   * increments, D = C (sum N_I T_I - T - sum N_I dT_I), it owes the grid:
   * its next step's conducted heat carries -D / dt there, and the heat
   * stored counts D out meanwhile, so the heat crossing the bond is
   * conserved to round-off.
   */
  template <int dim>
  class RegionHeat : public HeatPartner<dim>
  {
  public:
    /** @p bonded: the region's bonded coupling, or none. */
    RegionHeat(SolidRegion<dim> &solid, BondedCoupling<dim> *bonded);

    void
    add_capacity(NodalVector &capacity, NodalVector &heat) const override;

    void
    add_power(NodalVector &power) const override;

    /** The region's conducted heat of the step (before its bonded nodes
     * are deposited), with what they owe the grid. Collective. */
    void
    conduct(const double dt);

    typename HeatPartner<dim>::Flows
    advance(const NodalVector &increment,
            const NodalVector &temperature,
            const MPI_Comm     comm,
            const double       dt) override;

    double
    stored_heat() const override;

    double
    signal_rate() const override
    {
      return solid.heat_signal_rate();
    }

  private:
    SolidRegion<dim>    &solid;
    BondedCoupling<dim> *bonded;
  };
} // namespace dealmpm
