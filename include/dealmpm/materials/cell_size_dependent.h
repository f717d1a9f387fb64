#pragma once

#include <dealmpm/materials/material.h>

#include <memory>
#include <vector>

namespace dealmpm
{
  /**
   * The part of a model whose response depends on the grid's cell size: a
   * softening law localises in a band about a cell wide, and a
   * regularisation length ties its softening to the band's width instead
   * (Mohr-Coulomb's). The simulation gives such a model the grid's smallest
   * cell edge once the grid is made; a model used without a grid (a unit
   * test at a material point) is given one by hand.
   */
  class CellSizeDependent
  {
  public:
    virtual ~CellSizeDependent() = default;

    /** Whether the model's parameters ask for the cell size. */
    virtual bool
    needs_cell_size() const = 0;

    /** The edge @p h (m) of the cells a band forms in. */
    virtual void
    set_cell_size(const double h) = 0;
  };

  /** The model's CellSizeDependent part, also through a damage wrapper;
   * nullptr for a model that has none or does not need the cell size. */
  template <int dim>
  CellSizeDependent *
  needing_cell_size(Material<dim> &material);
} // namespace dealmpm
