#pragma once

#include <deal.II/base/function.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <dealmpm/base/base_motion.h>
#include <dealmpm/base/load_curve.h>
#include <dealmpm/materials/material.h>

#include <array>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

namespace dealmpm
{
  using namespace dealii;

  /** Conditions on a region's boundary ids; ids not named are free. A node
   * on several named ids takes the first of: fixed, displacement,
   * velocity, bonded, shaken (tractions add up). */
  template <int dim>
  struct RegionBoundaryConditions
  {
    std::set<types::boundary_id> fixed;
    /** u = value * displacement_curve(t) from the start position. */
    std::map<types::boundary_id, Tensor<1, dim>> displacement;
    LoadCurve                                    displacement_curve;
    /** v = value * velocity_curve(t). */
    std::map<types::boundary_id, Tensor<1, dim>> velocity;
    LoadCurve                                    velocity_curve;
    /** Nominal traction (force per reference area) * traction_curve(t). */
    std::map<types::boundary_id, Tensor<1, dim>> traction;
    LoadCurve                                    traction_curve;
    /** Nodes that move with the background grid (fem/bonded_coupling.h):
     * their velocity is set from outside before advance(). */
    std::set<types::boundary_id> bonded;
    /** Nodes on the base (section 'Base shaking'): they move with the
     * record (rigid) or meet the ground beyond through dashpots with the
     * incoming wave (compliant). */
    std::set<types::boundary_id> shaken;
    const BaseMotion<dim> *base = nullptr; ///< set when shaken isn't empty
  };

  /** Body force per unit mass at reference position X, position x,
   * velocity v and time t (gravity, a rotating frame). */
  template <int dim>
  using BodyForce = std::function<Tensor<1, dim>(const Point<dim>     &X,
                                                 const Point<dim>     &x,
                                                 const Tensor<1, dim> &v,
                                                 const double          t)>;

  /**
   * A finite element solid region: its own distributed triangulation in
   * the reference configuration, vector FE_Q(k) displacement, Gauss-Lobatto
   * lumped mass and total-Lagrangian explicit dynamics by central
   * differences (leapfrog: v at half steps, u at whole steps), the same
   * structure as the MPM step (forces of the state at the start, then
   * v += dt f / m, then x += dt v). The stress at each quadrature point
   * comes from a dealmpm Material, which keeps its internal variables
   * there: L = grad_X v F^-1 of the half step that made F, so incremental
   * (hypoelastic, plastic) models see the same step as on particles.
   * doc/research.md section 1.4.
   */
  template <int dim>
  class SolidRegion
  {
  public:
    /** A support point of the mesh (all dim components owned here). */
    struct Node
    {
      enum class Kind
      {
        free,
        fixed,
        displacement,
        velocity,
        bonded,
        shaken
      };
      std::array<unsigned int, dim> dof; ///< local indices of the owned dofs
      Point<dim>                    X;   ///< reference position
      Kind                          kind = Kind::free;
      /** The prescribed u or v; shaken: the outward normal times the
       * node's share of the base's area. */
      Tensor<1, dim> value;
    };

    SolidRegion(const MPI_Comm       comm,
                const Material<dim> &material,
                const unsigned int   degree);

    /** @name Set-up (source/fem/solid_region_setup.cc) */
    /** @{ */

    /** The mesh in the reference configuration: to be made (or read)
     * before setup(). */
    parallel::distributed::Triangulation<dim> &
    get_triangulation()
    {
      return triangulation;
    }

    /** After the triangulation is made: DoFs, the lumped mass, the nodes
     * and their conditions, the tractions' nodal forces, the
     * quadrature-point state. */
    void
    setup(const RegionBoundaryConditions<dim> &conditions);

    /** Only fixed ids (the region alone). */
    void
    setup(const std::set<types::boundary_id> &fixed);

    /** Anti-locking by F-bar (source/fem/solid_region_step.cc): each
     * cell's points share its mean volume change, so that a Q1 region of
     * a nearly incompressible or plastic material does not lock. Off by
     * default. */
    void
    use_f_bar(const bool on)
    {
      f_bar = on;
    }

    /** v = @p velocity at the nodes (at t = 0, the first half step's). */
    void
    set_velocity(const Function<dim> &velocity);

    /** u = @p displacement at the nodes, from the reference positions;
     * the quadrature points' F and stress follow at the next
     * compute_forces() (tests: the forces against the energy's
     * derivative). */
    void
    set_displacement(const Function<dim> &displacement);

    /** @} */
    /** @name The step (source/fem/solid_region_step.cc) */
    /** @{ */

    /** The largest stable step times @p cfl: the smallest node spacing
     * (h / k) over the dilatational wave speed. Collective. */
    double
    stable_time_step(const double cfl) const;

    /** The largest wave speed over node spacing (1/s) of this rank's
     * cells, the inverse of the stable step; the deformed spacing. Not
     * collective: the step reduces it with the particles' rate. Kept up to
     * date with the quadrature points' F (the force loop computes it). */
    double
    local_signal_rate() const
    {
      return signal_rate;
    }

    /** f = f_int(u) + tractions + m b at the start of a step of size dt
     * from @p time (the internal force's stress is advanced over the last
     * step). A @p uniform body force depends on t alone: it is called
     * once. Collective. */
    void
    compute_forces(const double          time,
                   const double          dt,
                   const BodyForce<dim> &body_force = {},
                   const bool            uniform    = false);

    /** v += dt f / m on free nodes, the prescribed velocities, bonded
     * nodes as set; then u += dt v. */
    void
    advance(const double time, const double dt);

    /** compute_forces() and advance(). Collective. */
    void
    step(const double          dt,
         const double          time       = 0,
         const BodyForce<dim> &body_force = {});

    /** @} */
    /** @name Statistics (source/fem/solid_region_statistics.cc) */
    /** @{ */

    double
    kinetic_energy() const;
    double
    strain_energy() const;
    /** Energy dissipated by the material (plastic work) so far. */
    double
    dissipated_work() const;
    /** sum_i m_i potential(x_i) (a potential given per unit mass). */
    double
    potential_energy(
      const std::function<double(const Point<dim> &)> &potential) const;
    Tensor<1, dim>
    momentum() const;
    /** sum_i x_i x m_i v_i (the z component in 2D). */
    Tensor<1, 3>
    angular_momentum() const;
    double
    total_mass() const;
    /** The force the supports (fixed and prescribed nodes) exerted on
     * the region in the last step: sum m dv / dt - f over their nodes.
     * Collective. */
    Tensor<1, dim>
    support_force() const;
    /** support_force() averaged over the steps since the last
     * start_statistics_row() (weighted by their size;
     * zero before any): the supports' force without the explicit step's
     * ringing, for the statistics' rows. Collective. */
    Tensor<1, dim>
    mean_support_force() const;
    void
    start_statistics_row();
    /** Whether any boundary is fixed or prescribed. */
    bool
    has_supports() const;
    /** A potential (per unit mass, the effects' fields) that changes in
     * time at fixed positions (a gravity ramp) works on the region: call
     * with the potential as it is after the effects' forces of a step
     * (@p before_step true, the positions still the step's start) and
     * after the step; the difference is counted as work. Local. */
    void
    track_potential(const std::function<double(const Point<dim> &)> &potential,
                    const bool before_step);

    /** Work of the tractions, prescribed motions and time-dependent
     * potentials so far (this rank's nodes), for the energy balance. */
    double
    external_work() const
    {
      return work;
    }

    /** Component @p component of the velocity of the node at @p x (within
     * 1e-10 of the region's size), on every rank; NaN if there is none. */
    double
    node_velocity(const Point<dim> &x, const unsigned int component) const;

    /** Per owned cell, the mean over its quadrature points of the full
     * 3 x 3 stress (2D: with sigma_zz), the von Mises stress and each
     * internal variable component (for output). */
    void
    cell_means(std::vector<SymmetricTensor<2, 3>> &cell_stress,
               std::vector<double>                &cell_von_mises,
               std::vector<std::vector<double>>   &cell_internal) const;

    /** The largest node spacing (edge over degree) on faces with ids
     * @p ids. Collective. */
    double
    largest_node_spacing_on(const std::set<types::boundary_id> &ids) const;

    /** @} */
    /** @name Saved state (source/fem/solid_region_state.cc) */
    /** @{ */

    /** This rank's part of the region's state (its dofs' u and v by the
     * mesh object they sit on, its cells' quadrature-point state by cell
     * id, the step size and the work), as text; load_state() of the
     * parts of all ranks restores it on any number of ranks, after
     * setup(). */
    std::string
    save_state() const;
    void
    load_state(const std::vector<std::string> &parts);

    /** @} */
    /** @name The couplings' nodes (fem/bonded_coupling.h,
     * fem/region_contact.h; source/fem/solid_region.cc) */
    /** @{ */

    /** The owned nodes, ordered by global dof index. */
    const std::vector<Node> &
    get_nodes() const
    {
      return nodes;
    }

    /** How many sets of reference gradients the owned cells share (one
     * for a box region, about one a cell for a curved mesh). */
    std::size_t
    n_gradient_sets() const
    {
      return reference.grad.size() /
             std::max<std::size_t>(dim * reference.n_scalar * reference.n_q, 1);
    }

    /** Current position of an owned node. */
    Point<dim>
    position(const Node &node) const;
    /** Its lumped mass. */
    double
    mass_of(const Node &node) const
    {
      return mass.local_element(node.dof[0]);
    }
    Tensor<1, dim>
    velocity_of(const Node &node) const
    {
      return node_vector(velocity, node);
    }
    /** The force of the last compute_forces(). */
    Tensor<1, dim>
    force_of(const Node &node) const
    {
      return node_vector(force, node);
    }

    /** Per owned node (by index into get_nodes()), the outward normal
     * times the node's share of the current area of the faces with ids
     * @p ids (Nanson: J F^-T N dA); zero off them. Collective. */
    std::vector<Tensor<1, dim>>
    area_normals(const std::set<types::boundary_id> &ids) const;

    /** Keep an affine matrix B per node for APIC of the bonded nodes
     * (fem/bonded_coupling.h), zero at first; saved with the state. */
    void
    use_affine();
    /** dim columns of B when use_affine() was called, else none. */
    unsigned int
    n_affine_columns() const
    {
      return static_cast<unsigned int>(affine.size());
    }
    /** B = sum N v_I (x) (x_I - x) of a node (use_affine()). */
    Tensor<2, dim>
    affine_of(const Node &node) const;
    void
    set_affine(const Node &node, const Tensor<2, dim> &B);

    /** The bonded coupling's read-back: node @p bonded[k] (an index into
     * get_nodes()) takes the velocity @p v[k] and, unless @p B is empty
     * (use_affine()), B[k]; advance() keeps them. */
    void
    set_bonded_velocities(const std::vector<unsigned int>   &bonded,
                          const std::vector<Tensor<1, dim>> &v,
                          const std::vector<Tensor<2, dim>> &B);

    /** Contact (fem/region_contact.h): node @p indices[k] (into
     * get_nodes()) gets the velocity change @p change[k], which the next
     * advance() adds to it if it is free, after its update; the other
     * nodes none. */
    void
    set_velocity_corrections(const std::vector<unsigned int>   &indices,
                             const std::vector<Tensor<1, dim>> &change);

    /** @} */
    /** @name Heat (effect 'heat conduction'; source/fem/solid_region_heat.cc)
     * Each node carries a temperature T_i, with the lumped heat capacity
     * C_i = c m_i; the conducted heat Q_i = -int k grad_x T . grad_x N_i
     * dv over the current configuration (k J C^-1 on the reference
     * cells); the nodes advance T_i += dt Q_i / C_i (forward Euler, as the
     * grid's nodes), those on fixed-temperature ids hold theirs and bonded
     * nodes take theirs from the grid (fem/region_heat.h). */
    /** @{ */

    struct HeatSettings
    {
      double conductivity  = 0; ///< k (W/m/K)
      double specific_heat = 0; ///< c (J/kg/K)
      /** Temperature (K) held on the region's boundary ids. */
      std::map<types::boundary_id, double> fixed;
      /** The model whose dissipated work (of the internal variables at
       * the quadrature points) heats the region by the Taylor-Quinney
       * fraction, or none. */
      const Material<dim> *working        = nullptr;
      double               taylor_quinney = 0;
      /** A thermally expanding material (materials/thermal_expansion.h):
       * its thermal stretch's index among the internal variables and its
       * growth per kelvin (0: none). */
      unsigned int stretch_index      = 0;
      double       stretch_per_kelvin = 0;
      /** Heat flux into the region (W/m^2) on its boundary ids, times
       * (*flux_curve)(t) at mid-step; convection coefficients h (W/m^2/K)
       * on its ids, to the ambient temperature; both over the current
       * area. */
      std::map<types::boundary_id, double> fluxes, convection;
      const LoadCurve                     *flux_curve = nullptr;
      double                               ambient    = 0;
      /** Factors on the fixed temperatures and the ambient temperature
       * against time (at the step's end), or none: 1. */
      const LoadCurve *temperature_curve = nullptr, *ambient_curve = nullptr;
      /** Heat generated per unit current volume (W/m^3), a function of
       * the current position and the time, or none. */
      Function<dim> *source = nullptr;
      /** Where the model keeps a temperature of its own among the
       * internal variables (Johnson-Cook), which the nodes' then set at
       * every point; -1: none. */
      int model_temperature = -1;
    };

    /** What advance_temperature() counted in the step: the heat the
     * boundaries gave (held nodes, fluxes, convection) and the heat the
     * material's work and the source generated. */
    struct HeatStep
    {
      double given     = 0;
      double generated = 0;
    };

    /** Carry a temperature, @p initial at each node's reference position
     * (those on fixed ids take theirs in the first step); saved with the
     * state. After setup(). */
    void
    use_heat(const HeatSettings &settings, const Function<dim> &initial);

    bool
    carries_heat() const
    {
      return temperature.size() > 0;
    }

    /** Q from the current temperatures and deformation (the step's
     * start: the increments advance_temperature() finds are from here),
     * with the source's power at @p time and the fluxes' at mid-step;
     * the convection's share of the faces' area per node. Collective. */
    void
    conduct(const double time, const double dt);

    /** T += dt Q / C at the nodes neither held nor bonded (with
     * convection at the new temperature, backward Euler), then the heat
     * of the material's work since the last call at every node not held;
     * the thermal stretch of an expanding material grows by each
     * point's temperature increment in the step. Returns what the held
     * nodes gave (what keeps them at their temperature, -dt Q) and what
     * the work generated. Collective. */
    HeatStep
    advance_temperature(const double dt);

    /** Bonded node @p indices[k] (into get_nodes()) changes its
     * temperature by @p change[k]. */
    void
    add_to_temperatures(const std::vector<unsigned int> &indices,
                        const std::vector<double>       &change);

    /** Heat a bonded node owes the grid (fem/region_heat.h), saved with
     * the state: stored_heat() counts it out. */
    double &
    heat_debt_of(const unsigned int k)
    {
      return heat.debt[k];
    }

    /** Node @p k's conducted heat grows by @p power (after conduct()). */
    void
    add_conducted_heat(const unsigned int k, const double power)
    {
      conducted.local_element(nodes[k].dof[0]) += power;
    }

    double
    temperature_of(const Node &node) const
    {
      return temperature.local_element(node.dof[0]);
    }
    double
    heat_capacity_of(const Node &node) const
    {
      return heat.settings.specific_heat * mass_of(node);
    }
    double
    conducted_heat_of(const Node &node) const
    {
      return conducted.local_element(node.dof[0]);
    }

    /** sum C_i T_i over this rank's nodes. */
    double
    stored_heat() const;

    /** 2 dim k J / (rho c (lambda_min h)^2) at this rank's points (h
     * the cell's node spacing in the reference configuration, lambda_min
     * the smallest stretch), the inverse of the conduction's stable
     * step; 0 without heat. */
    double
    heat_signal_rate() const;

    /** The nodes' temperature (at each of a node's dofs), with ghosts;
     * empty without heat. */
    const LinearAlgebra::distributed::Vector<double> &
    get_temperature() const
    {
      return temperature;
    }

    /** @} */
    /** @name For output and tests */
    /** @{ */

    const parallel::distributed::Triangulation<dim> &
    get_triangulation() const
    {
      return triangulation;
    }
    const DoFHandler<dim> &
    get_dof_handler() const
    {
      return dof_handler;
    }
    /** The polynomial degree k of the FE_Q(k) displacement. */
    unsigned int
    degree() const
    {
      return fe.degree;
    }
    MPI_Comm
    get_communicator() const
    {
      return comm;
    }
    /** Owned entries, with ghosts when updated. */
    const LinearAlgebra::distributed::Vector<double> &
    get_displacement() const
    {
      return displacement;
    }
    const LinearAlgebra::distributed::Vector<double> &
    get_velocity() const
    {
      return velocity;
    }
    /** The lumped mass per dof. */
    const LinearAlgebra::distributed::Vector<double> &
    get_mass() const
    {
      return mass;
    }
    const Material<dim> &
    get_material() const
    {
      return material;
    }

    /** @} */

  private:
    /** What the per-step loops need of the owned cells, fixed in the
     * reference configuration (total Lagrangian), computed once by
     * setup(): FEValues and FEFaceValues cost more than the loops
     * themselves on regions of a few hundred cells. */
    struct ReferenceData
    {
      unsigned int n_dofs = 0, n_scalar = 0, n_q = 0, n_face_q = 0;
      /** Per dof of a cell, node by node (i = s * dim + component): its
       * component, its scalar shape function s and its index in the FE. */
      std::vector<unsigned int> component, scalar, fe_index;
      /** Per cell: the local indices of its dofs (cell-major) and its
       * centre (for messages). */
      std::vector<unsigned int> local_dofs;
      std::vector<Point<dim>>   centre;
      /** Per cell: its smallest vertex distance (the time step's length). */
      std::vector<double> min_vertex_distance;
      /** Per cell and quadrature point: JxW. */
      std::vector<double> JxW;
      /** The reference gradients of the scalar shape functions at a
       * cell's points, as [direction][shape function][point] (the force
       * loop's order), once per distinct set: the cells of a box region
       * share one (1.5 KB a 3D Q1 cell, read every step, where a cell's
       * own state is about 1 KB). gradient_set[c] is cell c's. */
      std::vector<double>       grad;
      std::vector<unsigned int> gradient_set;

      /** Cell @p c's gradients. */
      const double *
      gradients(const unsigned int c) const
      {
        return &grad[std::size_t(gradient_set[c]) * dim * n_scalar * n_q];
      }
      /** Per boundary face: its cell, its boundary id; per face
       * quadrature point the reference normal times JxW and the scalar
       * shape functions' values and reference gradients. */
      std::vector<unsigned int>       face_cell;
      std::vector<types::boundary_id> face_id;
      std::vector<Tensor<1, dim>>     face_normal_dA, face_grad;
      std::vector<double>             face_value;
    };

    /** Set-up: the DoFs and the nodal vectors. */
    void
    distribute_dofs();
    /** m_i = int rho N_i^2 dV with Gauss-Lobatto points (lumped). */
    void
    make_lumped_mass();
    /** The owned nodes with the conditions of their faces' ids. */
    void
    make_nodes();
    /** A compliant base: each shaken node's outward normal times its
     * share of the base's area (its Node::value). */
    void
    set_base_areas();
    /** The owned nodes (keyed by their x dof), without conditions. */
    std::map<types::global_dof_index, Node>
    find_owned_nodes() const;
    /** Each owned node on a boundary face takes the face's condition. */
    void
    apply_face_conditions(std::map<types::global_dof_index, Node> &found) const;
    /** Nominal tractions: int N_i t dA over the reference faces. */
    void
    make_traction_force();
    /** Stress, F = I and the material's initial internal variables at
     * every quadrature point; no step made, no work done. */
    void
    make_quadrature_state();
    void
    make_reference_data();
    /** The reference data of cell @p values is at (JxW, gradients); its
     * gradients are a set already in @p known (hash of the bytes -> set)
     * if one is the same to the bit. */
    void
    add_cell_reference(
      const FEValues<dim, dim>                           &values,
      std::unordered_multimap<std::size_t, unsigned int> &known);
    /** The reference data of the boundary face @p face_values is at, of
     * owned cell @p cell, with id @p id. */
    void
    add_face_reference(const FEFaceValues<dim, dim> &face_values,
                       const unsigned int            cell,
                       const types::boundary_id      id);

    /** The step: f = -int grad N : P (F) with the stress advanced over
     * dt; the signal rate of the new F. */
    void
    internal_force(const double dt);
    /** The force loop on owned cell @p cell, for FE_Q(k) with n nodes
     * and n quadrature points: F, the stress advanced over @p dt, the
     * nodal forces added to force; returns the cell's signal rate. */
    template <int n>
    double
    cell_force(const unsigned int cell, const double dt);
    /** The rate of local_signal_rate() from the quadrature points' F. */
    void
    update_signal_rate();
    /** RunError unless J > 0 at owned cell @p cell. */
    void
    check_orientation(const double J, const unsigned int cell) const
    {
      if (!(J > 0))
        report_inverted(J, cell);
    }
    [[noreturn]] void
    report_inverted(const double J, const unsigned int cell) const;
    /** The velocity a node takes in the step from @p time by @p dt. */
    Tensor<1, dim>
    new_velocity(const unsigned int k,
                 const double       time,
                 const double       dt) const;
    /** The velocity of node @p k after the step's forces, without its
     * conditions. */
    Tensor<1, dim>
    free_velocity(const unsigned int k, const double dt) const;
    /** A prescribed node taking @p v: the support's work and reaction. */
    void
    add_support_reaction(const Node           &node,
                         const Tensor<1, dim> &v,
                         const double          dt);
    /** The tractions' work over the step just made (f_t . v). */
    void
    add_traction_work(const double time, const double dt);

    /** grad_X of the field @p w (ghosts updated) on cell @p cell at the
     * point whose reference gradients of the scalar shape functions start
     * at @p grad (n_scalar of them). */
    Tensor<2, dim>
    reference_gradient(const LinearAlgebra::distributed::Vector<double> &w,
                       const unsigned int                                cell,
                       const Tensor<1, dim> *grad) const;

    Tensor<1, dim>
    node_vector(const LinearAlgebra::distributed::Vector<double> &v,
                const Node                                       &node) const;

    /** Statistics: the integral over the region (reference volume, all
     * ranks) of density(k, internal variables) at quadrature point k. */
    template <typename Density>
    double
    integral(const Density &density) const;

    /** potential_energy() of this rank's nodes. */
    double
    local_potential_energy(
      const std::function<double(const Point<dim> &)> &potential) const;

    /** A cell's conducted heat into 'conducted' (ghost entries too). */
    void
    cell_conduction(const unsigned int cell);
    /** The heat of the work dissipated since the last call, at the nodes
     * (into 'conducted', zeroed first), the held nodes' share dropped;
     * returns what it added (this rank's). Collective. */
    double
    heat_by_work();
    /** Every point's dissipated work counts as turned into heat (at
     * the start, and after a saved state is loaded). */
    void
    mark_work_heated();
    /** Per owned node (index into nodes), sum over the faces with an id
     * in @p per_id of per_id[id] times the node's share of the face's
     * current area (Nanson). Collective. */
    std::vector<double>
    face_shares(const std::map<types::boundary_id, double> &per_id) const;
    /** The source's power into 'conducted' (before its compress), its
     * heat over the step into heat.step. */
    void
    add_source(const double time, const double dt);
    /** The fluxes' power into 'conducted' (owned entries, after its
     * compress) and the nodes' h A (heat.convective); convection is
     * explicit at the bonded nodes (their Q goes to the grid), backward
     * Euler at the others in advance_temperature(). The heat given over
     * the step into heat.step. Collective. */
    void
    add_boundary_heat(const double time, const double dt);
    /** Every point's model temperature (settings.model_temperature) from
     * the nodes'. */
    void
    set_model_temperatures();
    /** The scalar field @p v (at each node's x dof, with ghosts) at
     * quadrature point @p q of owned cell @p c. */
    double
    value_at_point(const LinearAlgebra::distributed::Vector<double> &v,
                   const std::size_t                                 c,
                   const unsigned int                                q) const;
    /** The current outward normal times area of point @p q of boundary
     * face @p face (Nanson: J F^-T N dA; displacement's ghosts
     * updated). */
    Tensor<1, dim>
    current_normal_area(const std::size_t face, const unsigned int q) const;
    /** Each point's thermal stretch grows by its share of the nodes'
     * temperature increments (@p increment, with ghosts). */
    void
    expand(const LinearAlgebra::distributed::Vector<double> &increment);

    /** Saved state: the "step" line's values, per dof key u, v and the
     * affine columns, per cell id the rest of its line. */
    struct SavedParts
    {
      double                                     last_dt = 0, work = 0;
      double                                     row_time = 0;
      Tensor<1, dim>                             impulse;
      std::map<std::string, std::vector<double>> dofs;
      std::map<std::string, std::string>         cells;
    };
    /** All ranks' parts read (the work and the impulse summed). */
    SavedParts
    read_parts(const std::vector<std::string> &parts) const;
    void
    load_dofs(const std::map<std::string, std::vector<double>> &dofs);
    void
    load_cells(const std::map<std::string, std::string> &cells);

    MPI_Comm                                  comm;
    parallel::distributed::Triangulation<dim> triangulation;
    FESystem<dim>                             fe;
    DoFHandler<dim>                           dof_handler;
    MappingQ1<dim>                            mapping;
    /** Owned, with the ghosts the cells need. */
    LinearAlgebra::distributed::Vector<double> displacement, velocity, mass,
      force;
    /** The owned nodes, ordered by global dof index. */
    std::vector<Node> nodes;
    /** Per node, a velocity change that advance() adds to free nodes
     * after their update and then clears (contact, fem/region_contact.h);
     * empty when unused. */
    std::vector<Tensor<1, dim>> velocity_correction;
    /** APIC for bonded nodes (fem/bonded_coupling.h): per column j, the
     * entry (c, j) of the node's B = sum N v_I (x) (x_I - x) at the dof of
     * its component c, like the velocity; empty unless used. */
    std::vector<LinearAlgebra::distributed::Vector<double>> affine;

    ReferenceData                              reference;
    const Material<dim>                       &material;
    RegionBoundaryConditions<dim>              conditions;
    LinearAlgebra::distributed::Vector<double> traction_force;
    /** Per owned cell and quadrature point: the stress, F and the
     * material's internal variables. */
    std::vector<SymmetricTensor<2, dim>> stress;
    std::vector<Tensor<2, dim>>          deformation;
    std::vector<double>                  internal;
    unsigned int                         n_internal = 0;
    bool                                 f_bar      = false; ///< use_f_bar()
    double last_dt     = 0; ///< the step that made the current displacement
    double signal_rate = 0; ///< local_signal_rate() of the current F
    double work        = 0;
    /** This rank's part of support_force(), and of its impulse since the
     * row started (over row_time). */
    Tensor<1, dim> support_reaction, row_impulse;
    double         row_time = 0;
    /** sum_i m_i potential(x_i) of this rank after the last step. */
    double last_potential = 0;
    /** Heat (use_heat()): T and Q at each of a node's dofs (all equal);
     * the held nodes (index into nodes) and their temperature. */
    LinearAlgebra::distributed::Vector<double> temperature, conducted;
    struct
    {
      HeatSettings                                 settings;
      std::vector<std::pair<unsigned int, double>> fixed_nodes;
      double                                       rho_c = 0;
      /** The scalar shape functions' values at the quadrature points
       * [s][q] (the same on every cell); per point the dissipated work
       * density already turned into heat. */
      std::vector<double> shape_values, heated_work;
      /** The owned temperatures at the step's start (conduct()). */
      std::vector<double> at_start;
      /** Per node, the heat it owes the grid (bonded nodes). */
      std::vector<double> debt;
      /** Per owned cell and quadrature point, its reference position
       * (with a source). */
      std::vector<Point<dim>> points;
      /** Per node, h A to the ambient temperature (conduct(); empty
       * without convection). */
      std::vector<double> convective;
      /** What conduct() counted for the step (fluxes, bonded
       * convection, source). */
      HeatStep step;
      /** The step's factor on the fixed temperatures and its ambient
       * temperature (conduct()). */
      double held_factor = 1, ambient = 0;
    } heat;
  };
} // namespace dealmpm
