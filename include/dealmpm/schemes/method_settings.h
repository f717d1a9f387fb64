#pragma once

#include <deal.II/base/parameter_handler.h>

#include <dealmpm/base/scene_reader.h>
#include <dealmpm/schemes/update_scheme.h>
#include <dealmpm/transfer/deformation_update.h>
#include <dealmpm/transfer/formulation.h>
#include <dealmpm/transfer/particle_update.h>

#include <string>

namespace dealmpm
{
  using namespace dealii;

  /**
   * The "MPM" section: the formulation, the stress update scheme, the
   * shape function, the
   * velocity transfer, the nodal mass threshold, what happens to
   * particles that leave the grid, cells of mixed materials, the
   * deformation gradient update and the particle update.
   */
  /** The volumetric anti-locking of the particles ('MPM/Anti-locking'). */
  enum class AntiLocking
  {
    none,
    f_bar,
    /** F-bar where a body's material takes it
     * (Material::particles_take_f_bar()), none elsewhere: made one of the
     * others by choose_anti_locking(). The .prm's default. */
    automatic
  };

  struct MethodSettings
  {
    Formulation  formulation   = Formulation::updated_lagrangian;
    UpdateScheme scheme        = UpdateScheme::MUSL;
    double       flip_fraction = 1; ///< 1 FLIP, 0 PIC
    bool         apic          = false;
    /** A name from shape_function_registry(). */
    std::string shape_function            = "linear";
    double      relative_mass_threshold   = 1e-9;
    bool        stop_when_particles_leave = false;
    /** Split the strain rate by stiffness in cells shared by materials of
     * different stiffness (MixedCellSplit). */
    bool split_mixed_cells = true;
    /** How F advances over a step. */
    DeformationUpdate deformation_update;
    /** A cell's particles share its volume change (FBar) or not. A scene
     * built in C++ gets none unless it asks ('automatic' is the .prm's
     * default). */
    AntiLocking anti_locking = AntiLocking::none;
    /** What 'automatic' chose and why, for the run's first lines ("anti-
     * locking F-bar (... Material 1 (J2 plasticity) ...)"), empty where it
     * had nothing to say. */
    std::string anti_locking_reason;
    /** How particles advance from the grid's acceleration. */
    ParticleUpdate particle_update;

    /** Declare the section's entries. */
    static void
    declare_parameters(ParameterHandler &prm);

    /** Read and check the section (the reader at the top level). */
    static MethodSettings
    read(SceneReader &reader);

    bool
    total_lagrangian() const
    {
      return formulation == Formulation::total_lagrangian;
    }
  };
} // namespace dealmpm
