#include <dealmpm/materials/cell_size_dependent.h>
#include <dealmpm/materials/damaged_material.h>

namespace dealmpm
{
  template <int dim>
  CellSizeDependent *
  needing_cell_size(Material<dim> &material)
  {
    if (auto *damaged = dynamic_cast<DamagedMaterial<dim> *>(&material))
      return needing_cell_size(damaged->inner_model());
    auto *dependent = dynamic_cast<CellSizeDependent *>(&material);
    return dependent != nullptr && dependent->needs_cell_size() ? dependent :
                                                                  nullptr;
  }

  template CellSizeDependent *
  needing_cell_size(Material<2> &);
  template CellSizeDependent *
  needing_cell_size(Material<3> &);
} // namespace dealmpm
