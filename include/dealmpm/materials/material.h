#pragma once

#include <deal.II/base/array_view.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <dealmpm/base/property_layout.h>
#include <dealmpm/base/registry.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

namespace dealmpm
{
  using namespace dealii;

  /**
   * A constitutive model: advances the Cauchy stress of one material point
   * over a step, gives the wave speed for the CFL limit and the stored energy
   * for the statistics. Models that need history (plastic strain, damage)
   * list their internal variables; the particle property layout grows by
   * them only when the model is used in a scene. In 2D the state is plane
   * strain.
   */
  template <int dim>
  class Material
  {
  public:
    virtual ~Material() = default;

    /** Per-particle internal variables, named for output. */
    virtual std::vector<FieldDescription>
    internal_variables() const
    {
      return {};
    }

    /** Initial values of the internal variables. */
    virtual void
    initialize_internal_variables(ArrayView<double> /*internal*/) const
    {}

    /**
     * Advance the stress over dt. L is the velocity gradient of the step, F
     * the already updated deformation gradient.
     */
    virtual void
    update_stress(const Tensor<2, dim>    &L,
                  const Tensor<2, dim>    &F,
                  const double             dt,
                  SymmetricTensor<2, dim> &stress,
                  ArrayView<double>        internal) const = 0;

    /**
     * update_stress() at @p F.size() points at once (an FEM region's
     * cell), each with its n_internal = internal.size() / F.size() internal
     * variables in turn. Point by point unless a model overrides it to let
     * the compiler overlap the points' work.
     */
    virtual void
    update_stresses(const ArrayView<const Tensor<2, dim>>    &L,
                    const ArrayView<const Tensor<2, dim>>    &F,
                    const double                              dt,
                    const ArrayView<SymmetricTensor<2, dim>> &stress,
                    const ArrayView<double>                  &internal) const
    {
      const std::size_t n_internal = internal.size() / F.size();
      for (std::size_t q = 0; q < F.size(); ++q)
        update_stress(L[q],
                      F[q],
                      dt,
                      stress[q],
                      ArrayView<double>(internal.begin() + q * n_internal,
                                        n_internal));
    }

    /** Dilatational (P-)wave speed at the current state. */
    virtual double
    wave_speed(const Tensor<2, dim> &F) const = 0;

    /** The wave speed of a state whose moduli depend on its history, not
     * on F alone (Modified Cam-Clay's grow with the pressure its elastic
     * strain carries): wave_speed(F) for every other model. */
    virtual double
    wave_speed_of_state(const Tensor<2, dim> &F,
                        ArrayView<const double> /*internal*/) const
    {
      return wave_speed(F);
    }

    /** The largest wave_speed_of_state() over the points @p F (an FEM
     * region's cell; zero for none), each with its internal.size() /
     * F.size() internal variables in turn. Point by point unless a model
     * whose speed is the square root of a modulus takes the root once:
     * sqrt and the division by the density are monotone and correctly
     * rounded, so the largest is the same number. */
    virtual double
    max_wave_speed(const ArrayView<const Tensor<2, dim>> &F,
                   const ArrayView<const double>         &internal) const
    {
      const std::size_t n = F.size() == 0 ? 0 : internal.size() / F.size();
      double            largest = 0;
      for (std::size_t q = 0; q < F.size(); ++q)
        largest = std::max(largest,
                           wave_speed_of_state(F[q],
                                               ArrayView<const double>(
                                                 internal.data() + q * n, n)));
      return largest;
    }

    /**
     * The out-of-plane normal stress sigma_zz of a plane-strain (2D) point.
     * It does no work (D_zz = 0), so it is not part of the step, but it
     * belongs in the pressure and the von Mises stress a user computes.
     * Models with history keep it among their internal variables. Only
     * called in 2D.
     */
    virtual double
    out_of_plane_stress(const Tensor<2, dim>          &F,
                        const SymmetricTensor<2, dim> &stress,
                        ArrayView<const double>        internal) const = 0;

    /** Stored energy per unit reference volume. */
    virtual double
    strain_energy_density(const Tensor<2, dim>          &F,
                          const SymmetricTensor<2, dim> &stress,
                          ArrayView<const double>        internal) const = 0;

    /**
     * Work dissipated so far (plastic work, a fluid's viscous work) per
     * unit reference volume, for
     * the energy balance; only models for which dissipates() is true.
     */
    virtual double
    dissipated_energy_density(ArrayView<const double> /*internal*/) const
    {
      return 0;
    }

    /** Whether the model dissipates work (the statistics then have a
     * dissipated_work column). */
    virtual bool
    dissipates() const
    {
      return false;
    }

    /** Whether F is reset to J^(1/dim) I after each stress update (fluids:
     * only the volume matters, and a stirred F loses its accuracy). */
    virtual bool
    resets_deformation() const
    {
      return false;
    }

    /** Whether an ill-conditioned F may be replaced after the stress
     * update by another of the same J that gives the same stress and
     * state (renormalise_deformation()): models whose response depends on
     * F only through an elastic strain they carry. A grain sheared without
     * end (the floor of a granular flow) otherwise grows F's condition
     * number past what doubles resolve. Updated Lagrangian only. */
    virtual bool
    renormalises_deformation() const
    {
      return false;
    }

    /** Replace @p F by an F' of the same determinant with the same
     * response, and the state @p internal (after its update) by the one
     * that matches F'. Called only if renormalises_deformation(). */
    virtual void
    renormalise_deformation(Tensor<2, dim> & /*F*/,
                            ArrayView<double> /*internal*/) const
    {}

    /** Whether a linear cell with 2^dim points locks with this model:
     * plastic flow (at or near constant volume), or an elastic Poisson's
     * ratio of 0.45 or more. An FEM region's 'Anti-locking = automatic'
     * chooses F-bar for such a material (the study behind it:
     * doc/guide/time-stepping-and-schemes.md#anti-locking-f-bar). */
    virtual bool
    locks_in_linear_cells() const
    {
      return false;
    }

    /** Whether 'MPM/Anti-locking = automatic' (the particles' default)
     * gives this model's particles F-bar: where the model locks, unless
     * its measured cases show F-bar in MPM without a gain for its price (a
     * model that says no says why). */
    virtual bool
    particles_take_f_bar() const
    {
      return locks_in_linear_cells();
    }

    /** Reference mass density, set from the scene's material section. */
    double density = 0;
  };

  /**
   * The full 3 x 3 Cauchy stress of a point: the stress itself in 3D; in 2D
   * (plane strain) the in-plane stress with the model's sigma_zz.
   */
  template <int dim>
  SymmetricTensor<2, 3>
  full_stress(const Material<dim>           &material,
              const Tensor<2, dim>          &F,
              const SymmetricTensor<2, dim> &stress,
              ArrayView<const double>        internal)
  {
    SymmetricTensor<2, 3> full;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        full[i][j] = stress[i][j];
    if constexpr (dim == 2)
      full[2][2] = material.out_of_plane_stress(F, stress, internal);
    return full;
  }

  /**
   * The table of material models. Built-in models are registered on first
   * use; user code adds its own with material_registry<dim>().add(...).
   * Each model reads its parameters from a subsection named after it inside
   * the scene's "Material N" section.
   */
  template <int dim>
  Registry<Material<dim>> &
  material_registry();

  /** Lame constants from Young's modulus and Poisson's ratio. */
  struct LameParameters
  {
    double lambda;
    double mu;

    /** Poisson's ratio 0.45 or more (to round-off: a scene's 0.45
     * counts): nearly incompressible, locking in linear cells
     * (Material::locks_in_linear_cells()). */
    bool
    nearly_incompressible() const
    {
      return lambda / (2 * (lambda + mu)) >= 0.45 - 1e-12;
    }
  };

  /** Declare "Young's modulus" and "Poisson's ratio" in the current section. */
  void
  declare_elastic_constants(ParameterHandler &prm,
                            const double      youngs_modulus,
                            const double      poissons_ratio);

  /** Read and check (E > 0, -1 < nu < 0.5) the entries declared above. */
  LameParameters
  read_elastic_constants(SceneReader &reader);
} // namespace dealmpm
