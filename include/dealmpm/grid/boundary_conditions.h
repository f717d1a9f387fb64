#pragma once

#include <deal.II/base/tensor.h>

#include <dealmpm/base/registry.h>
#include <dealmpm/grid/background_grid.h>
#include <dealmpm/grid/nodal_fields.h>

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace dealmpm
{
  /**
   * A velocity condition on the nodes of the boundary faces of one id
   * ('Grid/Boundary conditions = id: name, ...'). Built in: 'no-slip',
   * 'slip', 'free' (boundary_condition_registry()); a user registers
   * another from C++.
   */
  template <int dim>
  class BoundaryCondition
  {
  public:
    virtual ~BoundaryCondition() = default;

    /** Whether the nodes lose every velocity component (no-slip). */
    virtual bool
    fixes_nodes() const
    {
      return false;
    }

    /** The directions whose velocity component the nodes lose on a face of
     * unit normal @p normal (its sign unspecified): slip the normal, free
     * none. */
    virtual std::vector<Tensor<1, dim>>
    removed_directions(const Tensor<1, dim> &normal) const = 0;
  };

  template <int dim>
  using BoundaryConditionRegistry =
    Registry<BoundaryCondition<dim>, std::unique_ptr<BoundaryCondition<dim>>()>;

  template <int dim>
  BoundaryConditionRegistry<dim> &
  boundary_condition_registry();

  /** Fail on @p entry unless every id of @p ids is one of @p grid_ids
   * (the message names them as the ids @p whose). */
  void
  check_grid_has_ids(const SceneReader                         &reader,
                     const std::string                         &entry,
                     const std::map<unsigned int, std::string> &ids,
                     const std::vector<types::boundary_id>     &grid_ids,
                     const std::string &whose = "the grid has");

  /**
   * Velocity conditions on grid nodes by boundary id, applied to the nodal
   * velocity v* of each step. A node on two slip faces that meet at a corner
   * (more than 30 degrees) loses both normal components, on a curved wall
   * only the averaged normal one; a node on any no-slip face is fixed. The
   * conditions are kept, so that rebuild() finds the nodes of a changed
   * grid.
   */
  template <int dim>
  class BoundaryConditions
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    /** Read "Grid/Boundary conditions" (id -> registered name); every id
     * must be one of @p grid_ids. */
    static std::map<types::boundary_id, std::string>
    read(SceneReader &reader, const std::vector<types::boundary_id> &grid_ids);

    /** Make the named conditions and find their nodes on @p grid. */
    void
    setup(const BackgroundGrid<dim>                       &grid,
          const std::map<types::boundary_id, std::string> &names);

    /** Find the nodes again after the grid changed. */
    void
    rebuild(const BackgroundGrid<dim> &grid);

    /** The condition's name per boundary id, as the scene gave them. */
    const std::map<types::boundary_id, std::string> &
    names() const
    {
      return condition_names;
    }

    /** Fail on @p entry unless every id of @p ids is on @p grid and has
     * the condition @p condition ("free" where the scene names none),
     * saying @p why. */
    void
    require(const SceneReader                  &reader,
            const std::string                  &entry,
            const std::set<types::boundary_id> &ids,
            const BackgroundGrid<dim>          &grid,
            const std::string                  &condition,
            const std::string                  &why) const;

    /** The ids whose condition constrains the nodes (slip, no-slip): walls
     * that particles do not cross (hold_at_walls()). */
    std::set<types::boundary_id>
    walls() const;

    /** The walls none of whose nodes has a nodal @p mass above @p threshold
     * (all ranks; collective): a body touches no such wall. */
    std::set<types::boundary_id>
    walls_without_mass(const BackgroundGrid<dim> &grid,
                       const NodalVector         &mass,
                       const double               threshold) const;

    /** Remove the constrained components of a nodal vector field on the
     * locally owned nodes. */
    void
    project(std::array<NodalVector, dim> &vector) const;

    /**
     * Project v* and change the increment by as much, so that the increment
     * stays v* - p / m with v* after the condition: the wall's reaction then
     * reaches FLIP particles as it reaches PIC ones (a particle moving into a
     * fixed node is stopped by it; projecting the increment as well would
     * leave it moving for ever).
     */
    void
    project_with_increment(std::array<NodalVector, dim> &velocity,
                           std::array<NodalVector, dim> &increment) const;

  private:
    struct Node
    {
      unsigned int                    local_index;
      unsigned int                    n_normals = 0;
      std::array<Tensor<1, dim>, dim> normals; ///< orthonormal
    };
    /** A constrained node: fixed, or the directions it loses. */
    struct Collected
    {
      bool                        fixed = false;
      std::vector<Tensor<1, dim>> directions; ///< sums of aligned normals
    };
    /** Per locally owned constrained node (local index): what it loses. */
    std::map<unsigned int, Collected>
    collect_nodes(const BackgroundGrid<dim> &grid) const;

    std::map<types::boundary_id, std::shared_ptr<const BoundaryCondition<dim>>>
                                              conditions;
    std::map<types::boundary_id, std::string> condition_names;
    std::vector<Node>                         nodes;
  };
} // namespace dealmpm
