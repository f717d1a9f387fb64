#pragma once

#include <dealmpm/grid/background_grid.h>
#include <dealmpm/grid/nodal_fields.h>
#include <dealmpm/materials/material.h>
#include <dealmpm/particles/particle_set.h>
#include <dealmpm/transfer/stencil.h>

#include <memory>
#include <vector>

namespace dealmpm
{
  /**
   * Strain rates split by stiffness in cells that hold two materials of
   * different stiffness.
   *
   * The grid gives every particle of a cell (nearly) the same velocity
   * gradient, so in a cell shared by a stiff and a soft body both take the
   * same strain rate (iso-strain): where a stiff block rests on a soft
   * layer, the stiff particles in the shared cells take the soft layer's
   * compression times a modulus 1e4 larger (benchmarks/hard-cases.md, case
   * 7b). Across a layer, though, the traction is continuous (iso-stress):
   * the normal strain rate divides among the materials in inverse
   * proportion to their moduli. This class does that along the cell's
   * interface normal n, the direction from the softest material's centroid
   * to the stiffest one's: with V_m, M_m the volume and P-wave modulus of
   * material m in the cell (M = rho0 c^2 at F = I, the model's elastic
   * stiffness) and d_m the volume mean of its particles' n.L.n, the cell's
   * mean d = sum V_m d_m / V is kept and divided as
   *   d_m* = d / (M_m sum_k (V_k / V) / M_k),
   * each particle's L gaining (d_m* - d_m) n (x) n. The volume change of
   * the cell is the grid's; only its share among the materials changes, so
   * the internal work stays the grid's where the normal stress is
   * continuous. Cells whose materials are interleaved (centroids closer
   * than 1e-3 h) are left alone: a mixture has no layer to split along.
   * The tangential rates stay shared: a fluid's zero shear modulus has no
   * inverse, and a resting layer is loaded normally.
   */
  template <int dim>
  class MixedCellSplit
  {
  public:
    /** With each material's modulus rho0 c^2 at F = I. */
    explicit MixedCellSplit(
      const std::vector<std::unique_ptr<Material<dim>>> &materials);

    /** With the P-wave modulus of each material index. */
    explicit MixedCellSplit(const std::vector<double> &modulus)
      : modulus(modulus)
    {}

    /** Whether the materials differ in stiffness (else the split is the
     * identity, and the run does not prepare it). */
    bool
    needed() const;

    /** The corrections of this step (of size @p dt), from the nodal
     * velocity @p fields that the deformation sweep will read. */
    void
    prepare(const BackgroundGrid<dim> &grid,
            const ParticleSet<dim>    &particles,
            const Stencil<dim>        &stencil,
            const NodalFields<dim>    &fields,
            const double               dt);

    /** Called by the deformation sweep on each particle's L. */
    DEAL_II_ALWAYS_INLINE void
    operator()(const GridCell<dim>     &cell,
               const ArrayView<double> &props,
               Tensor<2, dim>          &L) const
    {
      const int first = first_correction[&cell - cells_begin];
      if (first >= 0)
        L += corrections[first +
                         static_cast<int>(particle_set->material_of(props))];
    }

    /** Cells split in the last prepare() on this rank. */
    unsigned int
    n_split_cells() const
    {
      return static_cast<unsigned int>(corrections.size() / modulus.size());
    }

    /** P-wave modulus per material index. */
    std::vector<double> modulus;

  private:
    /** Per local cell (grid.cells' order): the first of its corrections, one
     * per material index, or -1 where nothing is split. */
    std::vector<int>            first_correction;
    std::vector<Tensor<2, dim>> corrections;
    const GridCell<dim>        *cells_begin  = nullptr;
    const ParticleSet<dim>     *particle_set = nullptr;

    /** One particle of the cell being prepared. */
    struct Member
    {
      unsigned int   k; ///< place in the stencil
      unsigned int   material;
      double         volume;
      Tensor<1, dim> x;
      const double  *props;
    };
    std::vector<Member> members;

    /** The corrections of the cell whose particles are in members (h: its
     * shortest edge). */
    void
    split_cell(const Stencil<dim>     &stencil,
               const NodalFields<dim> &fields,
               const unsigned int      stress_field,
               const double            h,
               const double            dt);
  };
} // namespace dealmpm
