#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_tools.h>

#include <dealmpm/base/errors.h>
#include <dealmpm/fem/fem_region.h>
#include <dealmpm/grid/boundary_conditions.h>

#include <algorithm>
#include <sstream>

namespace dealmpm
{
  namespace
  {
    /** The prescribed displacements, velocities and tractions per
     * boundary id, and their load curves. */
    void
    declare_prescribed_loads(ParameterHandler &prm)
    {
      const std::string vectors =
        "Per boundary id a vector, items separated by ';', e.g. '1: 0, -0.01; "
        "3: 0.01, 0'";
      prm.declare_entry("Prescribed displacement",
                        "",
                        Patterns::Anything(),
                        vectors + " (m): the nodes' displacement from their "
                                  "start is that vector times 'Displacement "
                                  "curve'.");
      prm.declare_entry("Displacement curve",
                        "",
                        Patterns::Anything(),
                        "Factor of 'Prescribed displacement' against time, "
                        "'t0: f0, t1: f1, ...' piecewise linear, constant "
                        "outside; empty for 1.");
      prm.declare_entry("Prescribed velocity",
                        "",
                        Patterns::Anything(),
                        vectors + " (m/s), times 'Velocity curve'.");
      prm.declare_entry("Velocity curve",
                        "",
                        Patterns::Anything(),
                        "Factor of 'Prescribed velocity' against time, like "
                        "'Displacement curve'.");
      prm.declare_entry("Traction",
                        "",
                        Patterns::Anything(),
                        vectors + " (Pa): force per unit reference area "
                                  "(nominal, a dead load), times 'Traction "
                                  "curve'.");
      prm.declare_entry("Traction curve",
                        "",
                        Patterns::Anything(),
                        "Factor of 'Traction' against time, like "
                        "'Displacement curve'.");
    }

    /** The region's entries of the effect 'heat conduction'. */
    void
    declare_heat_entries(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Fixed temperatures",
        "",
        Patterns::Anything(),
        "With the effect 'heat conduction': temperature (K) held on boundary "
        "ids of the region's mesh, e.g. '0: 373.15'. The region conducts with "
        "its material's Conductivity and Specific heat (section Heat "
        "conduction) from its Initial temperature, and its bonded boundaries "
        "pass heat to the MPM body.");
      prm.declare_entry(
        "Heat fluxes",
        "",
        Patterns::Anything(),
        "With the effect 'heat conduction': heat flux into the region (W/m^2, "
        "< 0: out) on boundary ids of its mesh, e.g. '1: 5e4', over the "
        "faces' current area, times section Heat conduction's 'Flux curve'.");
      prm.declare_entry(
        "Convection",
        "",
        Patterns::Anything(),
        "With the effect 'heat conduction': convection coefficient h (W/m^2/K) "
        "on boundary ids of the region's mesh, e.g. '1: 25': the faces give "
        "h (T_ambient - T) per current area, T_ambient section Heat "
        "conduction's 'Ambient temperature'.");
    }
  } // namespace

  template <int dim>
  void
  FemRegionSettings<dim>::declare_parameters(ParameterHandler &prm)
  {
    declare_mesh_entries<dim>(prm);
    prm.declare_entry("Degree",
                      "1",
                      Patterns::Integer(1, 2),
                      "Polynomial degree k of the FE_Q(k) displacement: 1 or "
                      "2 (Q2 bends and nearly incompressible solids without "
                      "locking).");
    prm.declare_entry(
      "Anti-locking",
      "automatic",
      Patterns::Selection("automatic|none|F-bar"),
      "Volumetric locking of Q1 cells: a material that deforms at constant "
      "volume (plasticity, nu near 0.5) cannot follow a Q1 field with a "
      "volume change of its own at every point, and the region comes out "
      "too stiff. 'F-bar' gives each cell's points the cell's mean volume "
      "change and keeps their own change of shape (de Souza Neto et al. "
      "1996; the forces are the derivative of the energy, which an elastic "
      "region keeps); 'none' leaves each point its own. 'automatic': F-bar "
      "for Q1 cells of a plastic material or one with a Poisson's ratio of "
      "0.45 or more, none otherwise (Q2 cells lock far less).");
    prm.declare_entry("Material",
                      "1",
                      Patterns::Integer(1),
                      "The region's material: the number N of a 'Material "
                      "N' section (any solid model; its internal variables "
                      "live at the quadrature points).");
    prm.declare_entry("Initial velocity",
                      repeat_value<dim>("0"),
                      Patterns::List(Patterns::Double(), dim, dim),
                      "Velocity of every node at t = 0 (m/s).");
    prm.declare_entry("Fixed boundaries",
                      "",
                      Patterns::List(Patterns::Integer(0)),
                      "Boundary ids of the region's mesh held in place "
                      "(rectangle: 0/1 at x min/max, 2/3 at y min/max, 4/5 "
                      "at z min/max; a Gmsh file: its physical tags).");
    declare_prescribed_loads(prm);
    prm.declare_entry(
      "Shaken boundaries",
      "",
      Patterns::List(Patterns::Integer(0)),
      "Boundary ids of the region's mesh that are the base of effect 'base "
      "shaking' (section Base shaking: the record, rigid or compliant): "
      "rigid, their nodes move with the record; compliant, they meet the "
      "ground below through dashpots driven by the incoming wave, so that "
      "waves going down leave (a compliant base carries no weight: add the "
      "geostatic reaction as a 'Traction' on the same ids).");
    prm.declare_entry(
      "Bonded boundaries",
      "",
      Patterns::Anything(),
      "Per boundary id the MPM body (number N of 'Body N') it is bonded to, "
      "e.g. '1: 1': those nodes move with the grid's velocity (no slip, no "
      "gap) and give it their mass, momentum and force. Their spacing must "
      "not exceed the background cells' size. Needs 'MPM/Stress update = "
      "USL' and the updated Lagrangian formulation.");
    prm.declare_entry(
      "Contact boundaries",
      "",
      Patterns::Anything(),
      "Per boundary id a Coulomb friction coefficient, e.g. '2: 0.3': "
      "frictional contact of those faces with the MPM material through the "
      "background grid (no interpenetration beyond a cell; normals from the "
      "region's current surface); with the 'frictional contact' effect, "
      "each body meets the region on its own. Needs 'MPM/Stress update = "
      "USL'.");
    declare_heat_entries(prm);
  }

  namespace
  {
    /** "id: x, y; id: x, y" -> id -> vector. */
    template <int dim>
    std::map<types::boundary_id, Tensor<1, dim>>
    read_id_vectors(const SceneReader &reader, const std::string &entry)
    {
      std::map<types::boundary_id, Tensor<1, dim>> map;
      const std::string expected = "items 'id: " + repeat_value<dim>("v") +
                                   "' separated by ';', each boundary id once";
      for (const std::string &item :
           Utilities::split_string_list(reader.get(entry), ';'))
        {
          const auto colon = item.find(':');
          if (colon == std::string::npos)
            reader.fail(entry, expected);
          const std::vector<std::string> numbers =
            Utilities::split_string_list(item.substr(colon + 1), ',');
          long           id = -1;
          Tensor<1, dim> value;
          try
            {
              id = Utilities::string_to_int(item.substr(0, colon));
              if (numbers.size() != dim)
                throw std::invalid_argument("size");
              for (unsigned int d = 0; d < dim; ++d)
                value[d] = Utilities::string_to_double(numbers[d]);
            }
          catch (...)
            {
              reader.fail(entry, expected);
            }
          if (id < 0 || id >= numbers::internal_face_boundary_id ||
              map.count(id) > 0)
            reader.fail(entry, expected);
          map[id] = value;
        }
      return map;
    }

    /** Fail on @p entry unless the region's mesh has every id of @p ids. */
    template <typename Map>
    void
    check_ids(const SceneReader                     &reader,
              const std::string                     &entry,
              const Map                             &ids,
              const std::vector<types::boundary_id> &mesh_ids)
    {
      std::map<unsigned int, std::string> named;
      for (const auto &item : ids)
        named[item.first] = "";
      check_grid_has_ids(
        reader, entry, named, mesh_ids, "of the region's mesh");
    }
  } // namespace

  template <int dim>
  FemRegionSettings<dim>
  FemRegionSettings<dim>::read(
    SceneReader                                       &reader,
    const std::vector<std::unique_ptr<Material<dim>>> &materials,
    const unsigned int                                 n_bodies)
  {
    FemRegionSettings s;
    s.degree            = reader.get_integer("Degree");
    const long material = reader.get_integer("Material");
    if (material < 1 || material > static_cast<long>(materials.size()))
      reader.fail("Material",
                  "the number of a 'Material N' section, 1 to " +
                    std::to_string(materials.size()) +
                    " ('Number of materials')");
    s.material                     = material - 1;
    const std::string anti_locking = reader.get("Anti-locking");
    s.f_bar                        = anti_locking == "F-bar" ||
              (anti_locking == "automatic" && s.degree == 1 &&
               materials[s.material]->locks_in_linear_cells());
    s.initial_velocity = reader.get_vector<dim>("Initial velocity");
    RegionBoundaryConditions<dim> &bc = s.conditions;
    for (const double id : reader.get_doubles("Fixed boundaries"))
      bc.fixed.insert(static_cast<types::boundary_id>(id));
    bc.displacement = read_id_vectors<dim>(reader, "Prescribed displacement");
    bc.displacement_curve = LoadCurve::read(reader, "Displacement curve");
    bc.velocity           = read_id_vectors<dim>(reader, "Prescribed velocity");
    bc.velocity_curve     = LoadCurve::read(reader, "Velocity curve");
    bc.traction           = read_id_vectors<dim>(reader, "Traction");
    bc.traction_curve     = LoadCurve::read(reader, "Traction curve");
    for (const double id : reader.get_doubles("Shaken boundaries"))
      bc.shaken.insert(static_cast<types::boundary_id>(id));
    for (const auto &[id, text] :
         reader.get_id_map("Bonded boundaries", "a body number"))
      {
        long body = 0;
        try
          {
            body = Utilities::string_to_int(text);
          }
        catch (...)
          {}
        if (body < 1 || body > static_cast<long>(n_bodies))
          reader.fail("Bonded boundaries",
                      "'id: body' with bodies from 1 to " +
                        std::to_string(n_bodies) +
                        " ('Number of bodies'), not '" + text + "'");
        if (!s.bonded_to.empty() && s.bonded_to.begin()->second != body - 1)
          reader.fail("Bonded boundaries",
                      "every id bonded to the same body (a region bonds to "
                      "one body)");
        s.bonded_to[id] = body - 1;
        bc.bonded.insert(id);
      }
    for (const auto &[id, mu] :
         reader.get_id_nonnegatives("Contact boundaries"))
      {
        if (s.bonded_to.count(id))
          reader.fail("Contact boundaries",
                      "ids that are not bonded too (" + std::to_string(id) +
                        " is)");
        s.contact[id] = mu;
      }
    for (const auto &[id, T] : reader.get_id_nonnegatives("Fixed temperatures"))
      s.fixed_temperatures[static_cast<types::boundary_id>(id)] = T;
    for (const auto &[id, q] : reader.get_id_numbers("Heat fluxes", "W/m^2"))
      s.heat_fluxes[static_cast<types::boundary_id>(id)] = q;
    for (const auto &[id, h] : reader.get_id_nonnegatives("Convection"))
      s.convection[static_cast<types::boundary_id>(id)] = h;
    return s;
  }

  namespace
  {
    /** Fail unless the region's mesh has every boundary id its
     * conditions name. */
    template <int dim>
    void
    check_boundary_ids(const SceneReader            &reader,
                       const FemRegionSettings<dim> &s,
                       const Triangulation<dim>     &mesh)
    {
      const std::vector<types::boundary_id> ids = mesh.get_boundary_ids();
      std::map<types::boundary_id, int>     fixed;
      for (const types::boundary_id id : s.conditions.fixed)
        fixed[id] = 0;
      check_ids(reader, "Fixed boundaries", fixed, ids);
      check_ids(reader,
                "Prescribed displacement",
                s.conditions.displacement,
                ids);
      check_ids(reader, "Prescribed velocity", s.conditions.velocity, ids);
      check_ids(reader, "Traction", s.conditions.traction, ids);
      check_ids(reader, "Bonded boundaries", s.bonded_to, ids);
      check_ids(reader, "Contact boundaries", s.contact, ids);
      check_ids(reader, "Fixed temperatures", s.fixed_temperatures, ids);
      check_ids(reader, "Heat fluxes", s.heat_fluxes, ids);
      check_ids(reader, "Convection", s.convection, ids);
      std::map<types::boundary_id, int> shaken;
      for (const types::boundary_id id : s.conditions.shaken)
        shaken[id] = 0;
      check_ids(reader, "Shaken boundaries", shaken, ids);
    }

    /** Fail unless the shaken ids have a base motion and no other
     * condition (the base sets their velocity itself). */
    template <int dim>
    void
    check_shaken(const SceneReader            &reader,
                 const FemRegionSettings<dim> &s,
                 const BaseMotion<dim>        *base)
    {
      const RegionBoundaryConditions<dim> &bc = s.conditions;
      if (bc.shaken.empty())
        return;
      if (base == nullptr)
        reader.fail("Shaken boundaries",
                    "ids only with the effect 'base shaking' listed in "
                    "'Effects' (its section gives the record)");
      for (const types::boundary_id id : bc.shaken)
        if (bc.fixed.count(id) || bc.displacement.count(id) ||
            bc.velocity.count(id) || bc.bonded.count(id) || s.contact.count(id))
          reader.fail("Shaken boundaries",
                      "ids without another condition (id " +
                        std::to_string(id) +
                        " is fixed, prescribed, bonded or in contact too): "
                        "the base sets their velocity itself");
    }

    /** Fail unless every vertex is inside the background grid's box (the
     * nodes move on it). */
    template <int dim>
    void
    check_inside_grid(const SceneReader         &reader,
                      const Triangulation<dim>  &mesh,
                      const BackgroundGrid<dim> &grid)
    {
      const BoundingBox<dim> box = grid.bounding_box;
      for (const auto &cell : mesh.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int v : cell->vertex_indices())
            if (!box.point_inside(cell->vertex(v), 1e-12))
              {
                std::ostringstream where;
                where << cell->vertex(v);
                reader.fail(reader.get("Type") == "rectangle" ? "Upper corner" :
                                                                "Mesh file",
                            "a region inside the background grid ('Grid'), "
                            "which its vertex at (" +
                              where.str() + ") is not");
              }
    }

    /** Fail when the bonded boundaries' nodes are further apart than the
     * background cells: grid nodes between two of them would see none of
     * the region's mass. */
    template <int dim>
    void
    check_bonded_spacing(const SceneReader            &reader,
                         const FemRegionSettings<dim> &s,
                         const SolidRegion<dim>       &solid,
                         const BackgroundGrid<dim>    &grid)
    {
      double h_min = std::numeric_limits<double>::max();
      for (const GridCell<dim> &c : grid.cells)
        h_min = std::min(h_min, c.h);
      h_min = Utilities::MPI::min(h_min, grid.comm);
      std::set<types::boundary_id> bonded;
      for (const auto &item : s.bonded_to)
        bonded.insert(item.first);
      const double spacing = solid.largest_node_spacing_on(bonded);
      if (spacing > h_min * (1 + 1e-9))
        {
          std::ostringstream why;
          why << "boundaries whose node spacing (" << spacing
              << " m here) is at most the background cells' size (" << h_min
              << " m): refine the region there ('Cells', 'Degree') or "
                 "coarsen the grid";
          reader.fail("Bonded boundaries", why.str());
        }
    }

    /** The region's heat, with the effect @p heat (or none: then no
     * fixed temperatures). */
    template <int dim>
    void
    make_region_heat(const SceneReader         &reader,
                     FemRegion<dim>            &region,
                     const HeatConduction<dim> *heat)
    {
      const FemRegionSettings<dim> &s = region.settings;
      if (heat == nullptr)
        {
          for (const auto &[entry, values] :
               {std::make_pair("Fixed temperatures", &s.fixed_temperatures),
                std::make_pair("Heat fluxes", &s.heat_fluxes),
                std::make_pair("Convection", &s.convection)})
            if (!values->empty())
              reader.fail(entry,
                          "no entries unless 'Effects' lists 'heat "
                          "conduction'");
          return;
        }
      if (!heat->knows_material(s.material))
        reader.fail("Material",
                    "a material that section Heat conduction gives a "
                    "Conductivity and a Specific heat (material " +
                      std::to_string(s.material + 1) + " has none)");
      typename SolidRegion<dim>::HeatSettings settings;
      settings.conductivity      = heat->conductivity_of(s.material);
      settings.specific_heat     = heat->specific_heat_of(s.material);
      settings.fixed             = s.fixed_temperatures;
      settings.working           = heat->working_model(s.material);
      settings.taylor_quinney    = heat->taylor_quinney();
      settings.fluxes            = s.heat_fluxes;
      settings.convection        = s.convection;
      settings.flux_curve        = &heat->flux_curve();
      settings.ambient           = heat->ambient_temperature();
      settings.temperature_curve = &heat->temperature_curve();
      settings.ambient_curve     = &heat->ambient_curve();
      settings.source            = heat->heat_source();
      settings.model_temperature = heat->model_temperature_index(s.material);
      if (const auto *expanding = heat->expanding_model(s.material))
        {
          settings.stretch_index      = expanding->stretch_index();
          settings.stretch_per_kelvin = expanding->stretch_per_kelvin();
        }
      region.solid->use_heat(settings, heat->initial_temperature());
      region.heat = std::make_unique<RegionHeat<dim>>(*region.solid,
                                                      region.bonded.get(),
                                                      region.contact.get());
    }
  } // namespace

  template <int dim>
  FemRegion<dim>
  make_fem_region(SceneReader                                       &reader,
                  const unsigned int                                 index,
                  const std::vector<std::unique_ptr<Material<dim>>> &materials,
                  const unsigned int                                 n_bodies,
                  const BackgroundGrid<dim>                         &grid,
                  const BaseMotion<dim>                             *base,
                  const HeatConduction<dim>                         *heat)
  {
    FemRegion<dim> region;
    region.name = "FEM region " + std::to_string(index + 1);
    SectionScope section(reader, region.name);
    region.settings = FemRegionSettings<dim>::read(reader, materials, n_bodies);
    check_shaken(reader, region.settings, base);
    region.settings.conditions.base        = base;
    const FemRegionSettings<dim> &s        = region.settings;
    const Material<dim>          &material = *materials[s.material];
    if (material.resets_deformation())
      reader.fail("Material",
                  "a solid model (a fluid has no reference configuration "
                  "for a finite element mesh)");
    region.solid =
      std::make_unique<SolidRegion<dim>>(grid.comm, material, s.degree);
    SolidRegion<dim> &solid = *region.solid;
    solid.use_f_bar(s.f_bar);
    read_coarse_mesh<dim>(reader, solid.get_triangulation());
    check_boundary_ids(reader, s, solid.get_triangulation());
    check_inside_grid(reader, solid.get_triangulation(), grid);

    solid.setup(s.conditions);
    solid.set_velocity(Functions::ConstantFunction<dim>(std::vector<double>(
      &s.initial_velocity[0], &s.initial_velocity[0] + dim)));
    if (!s.bonded_to.empty())
      {
        check_bonded_spacing(reader, s, solid, grid);
        region.bonded =
          std::make_unique<BondedCoupling<dim>>(solid,
                                                s.bonded_to.begin()->second);
        region.bonded->grid_changed(grid);
      }
    if (!s.contact.empty())
      {
        region.contact = std::make_unique<RegionContact<dim>>(solid, s.contact);
        region.contact->grid_changed(grid);
      }
    make_region_heat(reader, region, heat);
    return region;
  }

  template struct FemRegionSettings<2>;
  template struct FemRegionSettings<3>;
  template FemRegion<2>
  make_fem_region(SceneReader &,
                  unsigned int,
                  const std::vector<std::unique_ptr<Material<2>>> &,
                  unsigned int,
                  const BackgroundGrid<2> &,
                  const BaseMotion<2> *,
                  const HeatConduction<2> *);
  template FemRegion<3>
  make_fem_region(SceneReader &,
                  unsigned int,
                  const std::vector<std::unique_ptr<Material<3>>> &,
                  unsigned int,
                  const BackgroundGrid<3> &,
                  const BaseMotion<3> *,
                  const HeatConduction<3> *);
} // namespace dealmpm
