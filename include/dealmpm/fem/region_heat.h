#pragma once

#include <dealmpm/effects/heat_conduction.h>
#include <dealmpm/fem/bonded_coupling.h>
#include <dealmpm/fem/region_contact.h>
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
   *
   * The friction of the region's contact heats the MPM material at the
   * grid's nodes where it acts (friction_source()), by the effect's
   * 'Friction heat' share: the region, which takes no heat across a
   * contact, gets none of it.
   */
  template <int dim>
  class RegionHeat : public HeatPartner<dim>
  {
  public:
    /** @p bonded, @p contact: the region's couplings, or none. */
    RegionHeat(SolidRegion<dim>         &solid,
               BondedCoupling<dim>      *bonded,
               const RegionContact<dim> *contact);

    void
    add_capacity(NodalVector &capacity, NodalVector &heat) const override;

    void
    add_power(NodalVector &power) const override;

    /** The region's conducted heat of the step from @p time (before its
     * bonded nodes are deposited), with what they owe the grid.
     * Collective. */
    void
    conduct(const double time, const double dt);

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

    const DissipatesAtNodes *
    friction_source() const override
    {
      return contact;
    }

  private:
    SolidRegion<dim>         &solid;
    BondedCoupling<dim>      *bonded;
    const RegionContact<dim> *contact;
  };
} // namespace dealmpm
