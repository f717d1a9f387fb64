#pragma once

#include <deal.II/base/parameter_handler.h>

#include <dealmpm/base/scene_reader.h>
#include <dealmpm/fem/bonded_coupling.h>
#include <dealmpm/fem/region_contact.h>
#include <dealmpm/fem/region_heat.h>
#include <dealmpm/fem/solid_region.h>
#include <dealmpm/grid/background_grid.h>
#include <dealmpm/materials/material.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace dealmpm
{
  /**
   * A scene's "FEM region N" section: the mesh (a rectangle or a Gmsh
   * file of its own), the degree, the material (one of the scene's
   * 'Material N' sections), the initial velocity, the boundary conditions
   * and the boundary ids bonded to MPM bodies.
   */
  template <int dim>
  struct FemRegionSettings
  {
    static void
    declare_parameters(ParameterHandler &prm);

    /** Read the current section (the reader is in it); one-line failures
     * for bad values, numbers of materials or bodies out of range. */
    static FemRegionSettings
    read(SceneReader                                       &reader,
         const std::vector<std::unique_ptr<Material<dim>>> &materials,
         const unsigned int                                 n_bodies);

    unsigned int degree = 1;
    /** 'Anti-locking', resolved: F-bar by name, or 'automatic' (the
     * default) for Q1 cells of a material that locks in linear cells. */
    bool                          f_bar    = false;
    unsigned int                  material = 0; ///< 0-based
    Tensor<1, dim>                initial_velocity;
    RegionBoundaryConditions<dim> conditions;
    /** Bonded boundary id -> body (0-based). */
    std::map<types::boundary_id, unsigned int> bonded_to;
    /** Contact boundary id -> friction coefficient. */
    std::map<types::boundary_id, double> contact;
    /** Boundary id -> temperature held there, heat flux into the region
     * (W/m^2), convection coefficient (W/m^2/K) (effect 'heat
     * conduction'). */
    std::map<types::boundary_id, double> fixed_temperatures, heat_fluxes,
      convection;
  };

  /** A region of the run: its settings, the solid and, when it has
   * bonded or contact boundaries, their coupling. */
  template <int dim>
  struct FemRegion
  {
    std::string                          name; ///< "FEM region 1"
    FemRegionSettings<dim>               settings;
    std::unique_ptr<SolidRegion<dim>>    solid;
    std::unique_ptr<BondedCoupling<dim>> bonded;
    std::unique_ptr<RegionContact<dim>>  contact;
    /** With the effect 'heat conduction': the region's heat. */
    std::unique_ptr<RegionHeat<dim>> heat;
  };

  /** Make region @p index (0-based) from its section: the mesh, the
   * checks against the scene (ids the mesh has, inside the background
   * grid, bonded nodes no coarser than its cells), the solid set up with
   * its initial velocity; @p base is the scene's base motion (effect
   * 'base shaking'), or none; with @p heat (effect 'heat conduction') the
   * region carries a temperature too. Collective; InputError on bad
   * input. */
  template <int dim>
  FemRegion<dim>
  make_fem_region(SceneReader                                       &reader,
                  const unsigned int                                 index,
                  const std::vector<std::unique_ptr<Material<dim>>> &materials,
                  const unsigned int                                 n_bodies,
                  const BackgroundGrid<dim>                         &grid,
                  const BaseMotion<dim>                             *base,
                  const HeatConduction<dim>                         *heat);
} // namespace dealmpm
