#pragma once

#include <deal.II/base/function_parser.h>

#include <dealmpm/base/load_curve.h>
#include <dealmpm/effects/dissipates_at_nodes.h>
#include <dealmpm/effects/effect.h>
#include <dealmpm/grid/boundary_nodes.h>
#include <dealmpm/materials/thermal_expansion.h>

#include <map>
#include <set>
#include <vector>

namespace dealmpm
{
  /**
   * What holds heat on the grid besides the particles (an FEM region,
   * fem/region_heat.h), which the heat conduction effect's step calls in
   * turn: it adds its capacity and heat to the grid's nodes before the
   * nodes' temperature is found, its conducted power before they advance,
   * and takes their temperature increments back.
   */
  template <int dim>
  class HeatPartner
  {
  public:
    virtual ~HeatPartner() = default;

    /** Add C and C T to the grid's nodes (local entries, ghosts
     * included; the effect compresses). */
    virtual void
    add_capacity(NodalVector &capacity, NodalVector &heat) const = 0;

    /** Add the power it gives the grid's nodes (W; ghosts included). */
    virtual void
    add_power(NodalVector &power) const = 0;

    /** What advance() counted in the step: the heat its held boundaries
     * gave and the heat its sources generated. */
    struct Flows
    {
      double given     = 0;
      double generated = 0;
    };

    /** Take the nodes' increments and new temperatures (@p increment,
     * @p temperature, with ghosts) and advance its own temperatures by
     * @p dt. Collective. */
    virtual Flows
    advance(const NodalVector &increment,
            const NodalVector &temperature,
            const MPI_Comm     comm,
            const double       dt) = 0;

    /** sum C T of this rank's part. */
    virtual double
    stored_heat() const = 0;

    /** The inverse of its conduction's stable step (this rank's part). */
    virtual double
    signal_rate() const = 0;

    /** What dissipates work at the grid's nodes on its behalf (the
     * friction of an FEM region's contact), heating them as the effects
     * that do; none by default. */
    virtual const DissipatesAtNodes *
    friction_source() const
    {
      return nullptr;
    }
  };

  /**
   * Heat conduction in the particles (effect 'heat conduction'): each
   * particle carries a temperature T (K), its material a conductivity k
   * (W/m/K) and a specific heat c (J/kg/K). Every step, after the grid
   * update:
   * - the heat capacity m c and the heat m c T go to the nodes with the
   *   mass's weights, C_i = sum N_ip m_p c_p, T_i = sum N_ip m_p c_p T_p /
   *   C_i; nodes on the 'Fixed temperatures' boundaries take theirs;
   * - the conducted heat, as the internal force is: Q_i = -sum_p V_p k_p
   *   grad T_p . grad N_ip with grad T_p = sum_j T_j grad N_jp;
   * - each node's temperature changes by dT_i = dt Q_i / C_i, a fixed node's
   *   by T_fixed - T_i (lumped capacity, forward Euler);
   * and after G2P every particle by sum N_ip dT_i, the same increment for
   * every shape function and scheme. A 'Heat source' s(x, t) (W/m^3) adds
   * sum_p N_ip V_p s(x_p, t) to Q_i, a boundary flux q A_i, convection
   * h A_i (T_ambient - T_i) (A_i the node's share of the faces' area).
   *
   * A material with a 'Thermal expansion' alpha > 0 is wrapped in
   * ThermallyExpanding (materials/thermal_expansion.h): each temperature
   * increment grows its particles' thermal stretch, which the stress
   * update divides out of F. A body is stress-free at its initial
   * temperature.
   *
   * The step obeys dt <= CFL h^2 rho c / (2 dim k) (signal_rate()), which
   * on fine cells of a good conductor is below the wave's CFL step.
   * Statistics: heat_stored (sum m c T, J; per metre of thickness in 2D)
   * and heat_in (the heat the fixed boundaries have given so far, what
   * they hand to the particles beside them and conduct to the nodes
   * next to them) and heat_generated (by the source); heat_stored -
   * heat_in - heat_generated stays at its start unless heat is lost at
   * nodes too light to hold a temperature.
   */
  template <int dim>
  class HeatConduction : public Effect<dim>
  {
  public:
    struct Settings
    {
      /** The initial temperature, an expression of x, y (, z). */
      std::string initial_temperature;
      /** One value for every material, or one per material. */
      std::vector<double>                  conductivity;
      std::vector<double>                  specific_heat;
      std::map<types::boundary_id, double> fixed_temperatures;
      /** Heat flux into the material (W/m^2) on grid boundary ids, times
       * flux_curve(t). */
      std::map<types::boundary_id, double> heat_fluxes;
      LoadCurve                            flux_curve;
      /** Convection coefficients (W/m^2/K) on grid boundary ids, to the
       * ambient temperature. */
      std::map<types::boundary_id, double> convection;
      double                               ambient_temperature = 293.15;
      /** Factors on the fixed temperatures (the grid's and the FEM
       * regions') and on the ambient temperature against time, taken at
       * the step's end. */
      LoadCurve temperature_curve, ambient_curve;
      /** Linear expansion coefficient (1/K), one or one per material. */
      std::vector<double> thermal_expansion = {0.};
      /** Heat generated per unit volume (W/m^3), an expression of x, y
       * (, z), t; "0": none, and no loop for it. */
      std::string heat_source = "0";
      /** The fraction of the work a material dissipates (plastic,
       * viscous) that heats it. */
      double taylor_quinney = 0.9;
      /** The share of the work friction dissipates (walls, contact) that
       * heats the material; the rest goes into the walls. */
      double friction_heat = 1;
    };

    HeatConduction(const Settings &settings, const SceneReader &reader);

    std::vector<FieldDescription>
    particle_fields() const override
    {
      std::vector<FieldDescription> fields = {{"temperature", 1},
                                              {"temperature_gradient", dim}};
      if (heats_by_work)
        fields.push_back({"heated_work", 1});
      return fields;
    }

    /** Note which materials heat by the work they dissipate (Johnson-Cook
     * then takes its temperature from here), and wrap each material with
     * a thermal expansion coefficient > 0 in ThermallyExpanding; in 2D its
     * model must have an elastic response. */
    void
    wrap_materials(MaterialSections<dim> &sections,
                   SceneReader           &reader) override;

    /** The fixed temperatures' ids must be on the grid, and the bodies'
     * materials have their conductivity and specific heat. */
    void
    setup(const EffectSetup<dim> &setup, SceneReader &reader) override;

    void
    grid_changed(const BackgroundGrid<dim> &grid) override;

    /** Each particle's initial temperature. */
    void
    initialize_particles(ParticleSet<dim> &particles) const override;

    /** Maps the heat and conducts it to the nodes, with the partners'
     * (after the grid update: after the FEM regions' forces, which
     * conduct in the regions and place their bonded nodes). */
    void
    after_grid_update(const EffectContext<dim> &state,
                      NodalFields<dim>         &fields) override;

    /** Gives each particle its nodes' temperature increments and the
     * Taylor-Quinney share of the work it dissipated in the step. */
    void
    after_g2p(const EffectContext<dim> &state,
              ParticleSet<dim>         &particles) override;

    double
    signal_rate(const ParticleSet<dim>    &particles,
                const BackgroundGrid<dim> &grid) const override;

    std::vector<std::pair<std::string, double>>
    statistics_columns() const override
    {
      return {{"heat_stored", stored},
              {"heat_in", heat_in},
              {"heat_generated", generated}};
    }

    /** The boundaries' and the sources' heat, and the heat stored (this
     * rank's shares): a resumed run's first row has them before its
     * first sweep. */
    std::vector<double>
    saved_state() const override
    {
      return {heat_in, generated, stored};
    }

    void
    restore_state(const std::vector<double> &state) override
    {
      heat_in   = state.at(0);
      generated = state.at(1);
      stored    = state.at(2);
    }

    /** Whether the section gives material @p m a conductivity and a
     * specific heat. */
    bool
    knows_material(const unsigned int m) const
    {
      return (settings.conductivity.size() == 1 ||
              m < settings.conductivity.size()) &&
             (settings.specific_heat.size() == 1 ||
              m < settings.specific_heat.size());
    }

    /** Material @p m's conductivity and specific heat, for an FEM region
     * of that material, and the initial temperature. */
    double
    conductivity_of(const unsigned int m) const
    {
      return of_material(settings.conductivity, m);
    }
    double
    specific_heat_of(const unsigned int m) const
    {
      return of_material(settings.specific_heat, m);
    }
    const Function<dim> &
    initial_temperature() const
    {
      return initial;
    }

    /** Material @p m's model whose dissipated work heats it (by
     * taylor_quinney()), or none; its expanding wrapper, or none. */
    const Material<dim> *
    working_model(const unsigned int m) const
    {
      return working.empty() ? nullptr : working[m];
    }
    double
    taylor_quinney() const
    {
      return settings.taylor_quinney;
    }
    const ThermallyExpanding<dim> *
    expanding_model(const unsigned int m) const
    {
      return expanding.empty() ? nullptr : expanding[m];
    }
    /** Where material @p m's model keeps its own temperature among its
     * internal variables (Johnson-Cook), which conduction sets; or -1. */
    int
    model_temperature_index(const unsigned int m) const
    {
      return johnson_cook_temperature.empty() ? -1 :
                                                johnson_cook_temperature[m];
    }

    /** The boundaries' flux curve and ambient temperature, and the
     * 'Heat source' (none when "0"), for FEM regions' boundaries and
     * volume. */
    const LoadCurve &
    flux_curve() const
    {
      return settings.flux_curve;
    }
    double
    ambient_temperature() const
    {
      return settings.ambient_temperature;
    }
    const LoadCurve &
    temperature_curve() const
    {
      return settings.temperature_curve;
    }
    const LoadCurve &
    ambient_curve() const
    {
      return settings.ambient_curve;
    }
    Function<dim> *
    heat_source() const
    {
      return has_source ? &source : nullptr;
    }

    /** @p partner's heat joins the grid's in every step from now on (it
     * outlives the effect's steps); its heat counts as stored. */
    void
    add_partner(HeatPartner<dim> &partner)
    {
      partners.push_back(&partner);
      stored += partner.stored_heat();
    }

  private:
    /** Material @p m's value of @p values (one for all, or one each). */
    static double
    of_material(const std::vector<double> &values, const unsigned int m)
    {
      return values.size() == 1 ? values[0] : values[m];
    }

    /** The heat of the work the effects dissipated at nodes in the step
     * (DissipatesAtNodes: friction) into the nodes' increments and new
     * temperatures, counted as generated. */
    void
    add_friction_heat(const EffectContext<dim> &state);

    /** The temperature rise of particle @p props (material @p m) by the
     * work it dissipated since the last call, counted as generated. */
    double
    heat_by_work(const ArrayView<double> &props,
                 const ParticleSet<dim>  &particles,
                 const unsigned int       m);

    /** k / (rho c) of particle @p props of material @p m. */
    double
    diffusivity_of(const ArrayView<const double> &props,
                   const ParticleSet<dim>        &particles,
                   const unsigned int             m) const;

    /** The particles' heat sum m c T on this rank. */
    double
    heat_of(const ParticleSet<dim> &particles) const;

    /** Nodal capacity and temperature from the particles (fixed nodes
     * held), with ghosts. */
    void
    map_temperature(const EffectContext<dim> &state);

    /** Adds the source's power sum_p N_ip V_p s(x_p, t) to the conducted
     * heat in 'increment' (before its compress); counts its heat. */
    void
    add_source(const EffectContext<dim> &state);

    /** Adds the boundary fluxes' power (times the curve at mid-step) to
     * the conducted heat in 'increment' (owned nodes, after its compress)
     * at nodes that hold material; counts it in heat_in. */
    void
    add_fluxes(const double time, const double dt);

    /** Turns the nodes' power in 'increment' into their temperature
     * increments, with convection and the held nodes, counts what the
     * boundaries gave, and sets 'temperature' to the nodes' new one. */
    void
    advance_nodes(const double dt);

    Settings                    settings;
    mutable FunctionParser<dim> initial;
    mutable FunctionParser<dim> source; ///< its time set where used
    bool                        has_source = false;
    /** Each material's model whose dissipated work heats it (before any
     * wrapper of this effect), or none; where a Johnson-Cook model keeps
     * its temperature among its internal variables, or -1. */
    std::vector<const Material<dim> *> working;
    std::vector<int>                   johnson_cook_temperature;
    bool                               heats_by_work = false;
    /** Each material's expanding wrapper, or none. */
    std::vector<const ThermallyExpanding<dim> *> expanding;
    /** Locally owned nodes on a fixed-temperature boundary, each once. */
    std::vector<std::pair<unsigned int, double>> fixed_nodes;
    std::vector<double>                          mapped_at_fixed;
    /** The step's temperature_curve factor and ambient temperature (at
     * its end). */
    double held_factor = 1, ambient = 0;
    /** Locally owned nodes on the flux (q A) and convection (h A)
     * boundaries, A a node's share of the faces' area; held nodes have
     * no convection. */
    std::vector<std::pair<unsigned int, double>> flux_nodes;
    std::vector<std::pair<unsigned int, double>> convection_nodes;
    NodalVector                                  capacity;
    NodalVector                                  temperature;
    NodalVector                                  increment;
    std::vector<HeatPartner<dim> *>              partners;
    mutable double                               stored = 0;
    /** The smallest cell size; the particles' largest k / (rho c), from
     * the last after_g2p (< 0: not yet, signal_rate() finds it). */
    double         h_min               = 1;
    mutable double largest_diffusivity = -1;
    double         heat_in             = 0;
    double         generated           = 0;
  };

  /** Register "heat conduction" in the effect table: its parameters
   * (section Heat conduction), their reading and checks. */
  template <int dim>
  void
  add_heat_conduction_effect(Registry<Effect<dim>> &registry);
} // namespace dealmpm
