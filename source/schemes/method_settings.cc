#include <dealmpm/schemes/method_settings.h>
#include <dealmpm/transfer/kernel.h>

namespace dealmpm
{
  namespace
  {
    /** The scheme: where the momentum balance is written and when the stress
     * is updated. */
    void
    declare_scheme_entries(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Formulation",
        "updated Lagrangian",
        Patterns::Selection(formulation_pattern()),
        "Where the momentum balance is written. 'updated Lagrangian' (the "
        "usual MPM): on the current configuration, shape functions at the "
        "particles' current positions every step; bodies may separate, flow, "
        "meet and touch walls anywhere. 'total Lagrangian' (de Vaucorbeil et "
        "al. 2020): on the reference configuration, shape functions computed "
        "once at the particles' initial positions, F from the reference "
        "gradient of the grid velocity; no cell crossing (very large "
        "distortion of one body stays accurate: twist, bending, a clamped "
        "end) and no relocation, but particles interact only with those "
        "that share grid nodes with them at the start: no fluids, no "
        "contact between bodies that start apart, and walls act only where "
        "the body touches them at the start. 'Mixed-material cells' has no "
        "effect (no particle changes cell).");
      prm.declare_entry(
        "Stress update",
        "MUSL",
        Patterns::Selection(update_scheme_pattern()),
        "When the stress is updated: 'MUSL' (last, with the grid velocity "
        "re-mapped from the updated particles: robust where nodes carry "
        "little mass; the default, chosen by the defaults study in "
        "benchmarks/README.md), 'USL' (last, with the step's new grid "
        "velocity; one sweep, about 1.5x faster, but with linear shape "
        "functions unstable when particles cross cells), 'USF' (first, with "
        "the velocity at the start of the step; gains energy).");
    }

    /** How velocities pass between grid and particles: the shape function
     * and the particle velocity's update. */
    void
    declare_transfer_entries(ParameterHandler &prm)
    {
      prm.declare_entry("Shape function",
                        "linear",
                        Patterns::Selection(shape_function_pattern()),
                        shape_function_documentation());
      prm.declare_entry(
        "Velocity update",
        "FLIP",
        Patterns::Selection("FLIP|PIC|blend|APIC"),
        "Particle velocity from the grid: FLIP (increment, little "
        "dissipation), PIC (interpolated velocity, dissipative), "
        "blend (Blend factor x FLIP + (1 - Blend factor) x PIC), or APIC "
        "(Jiang et al. 2015: PIC plus a per-particle affine velocity, "
        "conserves angular momentum; adds dim x dim doubles per particle; "
        "with USL or USF).");
      prm.declare_entry("Blend factor",
                        "0.99",
                        Patterns::Double(),
                        "FLIP fraction for 'blend', in [0, 1].");
    }

    /** The guards: nodes too light to divide by, particles leaving the grid. */
    void
    declare_guard_entries(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Nodal mass threshold",
        "1e-9",
        Patterns::Double(),
        "Nodes with mass below this fraction of the mean particle "
        "mass are inactive (no velocity), in [0, 1e-3]: a guard "
        "against division by round-off, not a physical cut-off.");
      prm.declare_entry(
        "Particles leaving the grid",
        "remove",
        Patterns::Selection("remove|stop"),
        "Particles that cross a free boundary (a slip or no-slip wall puts "
        "them back on itself): 'remove': drop them with a warning and count "
        "them in the statistics; 'stop': end the run with a message.");
    }

    /** The particles' velocity gradient and F: mixed-material cells and the
     * deformation gradient's update. */
    void
    declare_deformation_entries(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Mixed-material cells",
        "split by stiffness",
        Patterns::Selection("split by stiffness|shared strain rate"),
        "Cells holding particles of materials of different stiffness (a "
        "stiff block resting on a soft layer): 'split by stiffness' divides "
        "the cell's normal strain rate across the interface in inverse "
        "proportion to each material's P-wave modulus (continuous traction, "
        "as in a layered solid), keeping the cell's volume change; 'shared "
        "strain rate' gives every particle the grid's velocity gradient, so "
        "that a stiff particle takes a soft neighbour's strain. Costs one "
        "pass over the particles per step, and nothing in scenes whose "
        "materials are equally stiff.");
      prm.declare_entry(
        "Deformation gradient update",
        "first order",
        Patterns::Selection(DeformationUpdate::pattern()),
        "How F advances over a step, F <- dF F with dF approximating "
        "exp(dt L): 'first order' (I + dt L: the cheapest; J > 0 only while "
        "dt |L| is small), 'Taylor series' (the exponential's series up to "
        "the power 'Taylor terms'), 'Cayley' ((I - dt L / 2)^-1 (I + dt L / "
        "2): second order, and a rotation for a spin, so that rigid rotation "
        "keeps J = 1 exactly) or 'subcycle' ((I + dt L / N)^N, N = "
        "'Subcycles').");
      prm.declare_entry(
        "Anti-locking",
        "automatic",
        Patterns::Selection("automatic|none|F-bar"),
        "Volumetric locking: a linear cell with 2^dim particles gives each "
        "its own volume change, which a material that flows at constant "
        "volume (plasticity, nu near 0.5) cannot follow, so that failure "
        "loads come out high and unstable slopes stand. 'F-bar' gives the "
        "particles of each body in a cell the cell's mean volume rate (the "
        "trace of their velocity gradients, weighted by their reference "
        "volumes) and keeps their own rate of shape change (B-bar on the "
        "rate; Coombs et al. 2018, CMAME 333); 'none' leaves each particle "
        "its own. Updated Lagrangian and the explicit particle update only. "
        "'automatic' (the default): F-bar where a body's material is plastic "
        "or has a Poisson's ratio of 0.45 or more, except Johnson-Cook (its "
        "Taylor bars gain nothing from it), when the formulation and "
        "particle update allow it; none elsewhere. The run's first lines "
        "say what it chose. The study behind it: failure loads and slopes "
        "come out right with F-bar and too safe without; the granular "
        "collapse is less resolution-dependent with it "
        "(doc/guide/time-stepping-and-schemes.md).");
      prm.declare_entry("Taylor terms",
                        "4",
                        Patterns::Integer(1, 20),
                        "Highest power of dt L kept by 'Taylor series'.");
      prm.declare_entry("Subcycles",
                        "4",
                        Patterns::Integer(1, 1000),
                        "Number of substeps N of 'subcycle'.");
    }

    /** How particles advance from the grid's acceleration: explicit or
     * Newmark, and Newmark's parameters. */
    void
    declare_particle_update_entries(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Particle update",
        "explicit",
        Patterns::Selection(ParticleUpdate::pattern()),
        "How particles advance from the grid's acceleration a: 'explicit' "
        "(the usual MPM: v += dt a, then x moves with the new grid velocity; "
        "the velocity lags the position by half a step, so velocities and "
        "kinetic energy carry an O(dt) error) or 'Newmark' (Newmark's "
        "formulas with 'Newmark beta' and 'Newmark gamma', in Hughes and "
        "Liu's explicit predictor-corrector form: the force is taken at the "
        "predicted position, one force evaluation a step, the same stable "
        "step; velocities second order in dt with gamma = 1/2). Newmark "
        "needs 'Stress update = MUSL' (the particles' displacement velocity "
        "is re-mapped to the grid) and 'Velocity update = FLIP', and adds "
        "dim doubles per particle (the acceleration).");
      prm.declare_entry(
        "Newmark beta",
        "0",
        Patterns::Double(),
        "Newmark's beta, in [0, 0.5]: the weight of the new acceleration in "
        "the position (0: central differences; 0.25: average acceleration). "
        "In this explicit form the force is taken at the predicted position, "
        "so beta > 0 buys no stability; it changes the first step and puts "
        "the stored position beta dt^2 a from Newmark's, whose energy "
        "mismatch at the start of a run (of the order of the energy put in "
        "by then) can trip 'Checks/Energy growth limit'. 0 keeps positions "
        "and velocities consistent from the first step.");
      prm.declare_entry("Newmark gamma",
                        "0.5",
                        Patterns::Double(),
                        "Newmark's gamma, in [0.5, 1]: the weight of the new "
                        "acceleration in the velocity (0.5: no numerical "
                        "damping; above 0.5 damps the highest frequencies, "
                        "at the cost of first order in dt).");
    }
  } // namespace

  void
  MethodSettings::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("MPM");
    declare_scheme_entries(prm);
    declare_transfer_entries(prm);
    declare_guard_entries(prm);
    declare_deformation_entries(prm);
    declare_particle_update_entries(prm);
    prm.leave_subsection();
  }

  namespace
  {
    /** Newmark's parameters, and what it needs of the other entries. */
    void
    read_newmark(SceneReader &reader, MethodSettings &s)
    {
      ParticleUpdate &u = s.particle_update;
      u.beta            = reader.get_double("Newmark beta");
      u.gamma           = reader.get_double("Newmark gamma");
      if (!(u.beta >= 0 && u.beta <= 0.5))
        reader.fail("Newmark beta", "a number in [0, 0.5]");
      if (!(u.gamma >= 0.5 && u.gamma <= 1))
        reader.fail("Newmark gamma",
                    "a number in [0.5, 1] (below 0.5 the update gains "
                    "energy)");
      if (s.scheme != UpdateScheme::MUSL)
        reader.fail("Stress update",
                    "'MUSL' with 'Particle update = Newmark' (its "
                    "displacement velocity is re-mapped to the grid as "
                    "MUSL re-maps momentum)");
      if (s.flip_fraction != 1 || s.apic)
        reader.fail("Velocity update",
                    "'FLIP' with 'Particle update = Newmark' (Newmark "
                    "advances the velocity by the acceleration; PIC and "
                    "APIC replace it by the grid's)");
    }
  } // namespace

  MethodSettings
  MethodSettings::read(SceneReader &reader)
  {
    MethodSettings    s;
    SectionScope      mpm(reader, "MPM");
    const std::string update = reader.get("Velocity update");
    s.formulation            = parse_formulation(reader.get("Formulation"));
    s.scheme                 = parse_update_scheme(reader.get("Stress update"));
    s.apic                   = update == "APIC";
    s.shape_function         = reader.get("Shape function");
    s.flip_fraction =
      update == "FLIP" ?
        1. :
        (update == "blend" ? reader.get_double("Blend factor") : 0.);
    if (!(s.flip_fraction >= 0 && s.flip_fraction <= 1))
      reader.fail("Blend factor", "a number in [0, 1]");
    s.relative_mass_threshold = reader.get_nonnegative("Nodal mass threshold");
    if (s.relative_mass_threshold > 1e-3)
      reader.fail(
        "Nodal mass threshold",
        "a number in [0, 1e-3]: particles still use the nodes below it, "
        "which then have no velocity");
    s.stop_when_particles_leave =
      reader.get("Particles leaving the grid") == "stop";
    s.split_mixed_cells =
      reader.get("Mixed-material cells") == "split by stiffness";
    s.deformation_update.variant =
      DeformationUpdate::parse(reader.get("Deformation gradient update"));
    s.deformation_update.taylor_terms = reader.get_integer("Taylor terms");
    s.deformation_update.subcycles    = reader.get_integer("Subcycles");
    const std::string anti_locking    = reader.get("Anti-locking");
    s.anti_locking            = anti_locking == "F-bar" ? AntiLocking::f_bar :
                                anti_locking == "none"  ? AntiLocking::none :
                                                          AntiLocking::automatic;
    s.particle_update.newmark = reader.get("Particle update") == "Newmark";
    if (s.particle_update.newmark)
      read_newmark(reader, s);
    return s;
  }
} // namespace dealmpm
