#pragma once

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/particles/particle_handler.h>

#include <dealmpm/base/property_layout.h>
#include <dealmpm/particles/particle_order.h>

#include <memory>
#include <vector>

namespace dealmpm
{
  using namespace dealii;

  /** Offsets of the fields every particle has. */
  struct CoreFields
  {
    unsigned int mass;
    unsigned int initial_volume;
    unsigned int velocity;
    unsigned int displacement;
    unsigned int deformation_gradient; ///< dim x dim, row-major
    unsigned int stress;               ///< symmetric, deal.II's unrolled order
    unsigned int body;
    unsigned int material;
    /** APIC's B_p = sum N v_i (x) (x_i - x_p) (dim x dim), or
     * invalid_unsigned_int when the scene does not use APIC (then no particle
     * stores it). */
    unsigned int affine_velocity;
    /** Newmark's particle acceleration (dim), or invalid_unsigned_int when
     * the scene does not use Newmark. */
    unsigned int acceleration;
    /** GIMP's initial particle-domain half-lengths (dim), or
     * invalid_unsigned_int for kernels without a particle domain. */
    unsigned int domain_half_length;
  };

  /**
   * The material points: deal.II's ParticleHandler (positions, cells, ids,
   * MPI ownership) with a property layout of core fields and the internal
   * variables of the material models in use.
   */
  template <int dim>
  class ParticleSet
  {
  public:
    /**
     * The layout is built from what the parts of the run ask for, in this
     * order: the core fields, @p method_fields (the shape function's and
     * the transfer's: "domain_half_length", "apic_B",
     * "acceleration"), per material index
     * the model's @p internal_variables (models that share a name share
     * storage), then the listed effects' @p effect_fields.
     */
    ParticleSet(
      const Triangulation<dim>                         &tria,
      const Mapping<dim>                               &mapping,
      const std::vector<std::string>                   &model_names,
      const std::vector<std::vector<FieldDescription>> &internal_variables,
      const std::vector<FieldDescription>              &method_fields = {},
      const std::vector<FieldDescription>              &effect_fields = {});

    PropertyLayout layout;
    CoreFields     fields;
    /** Offset of each material's internal variables (per material index). */
    std::vector<unsigned int>       internal_offset;
    std::vector<unsigned int>       n_internal;
    Particles::ParticleHandler<dim> handler;

    /** Sort the particles into their ranks and cells (deal.II's sort);
     * the step's order is rebuilt on its next use. */
    void
    sort()
    {
      handler.sort_particles_into_subdomains_and_cells();
      changed();
    }

    /** Say that the handler's particles or their cells changed other than
     * through sort(): an insertion or removal, a grid change, a restore.
     * Every such change must say so, or the step would visit handles that
     * are no longer these particles'. */
    void
    changed()
    {
      order.invalidate();
    }

    /** The step's order of this rank's particles over @p grid's cells,
     * rebuilt here when the particles or the grid changed. */
    const ParticleOrder<dim> &
    order_over(const BackgroundGrid<dim> &grid) const
    {
      if (!order.is_valid_for(grid))
        order.rebuild(grid, handler);
      return order;
    }

  private:
    mutable ParticleOrder<dim> order;
  };

  /** Read and write small tensors from a particle's property array. */
  template <int dim>
  inline Tensor<1, dim>
  read_vector(const double *p)
  {
    Tensor<1, dim> t;
    for (unsigned int d = 0; d < dim; ++d)
      t[d] = p[d];
    return t;
  }

  template <int dim>
  inline void
  write_vector(double *p, const Tensor<1, dim> &t)
  {
    for (unsigned int d = 0; d < dim; ++d)
      p[d] = t[d];
  }

  template <int dim>
  inline Tensor<2, dim>
  read_tensor(const double *p)
  {
    Tensor<2, dim> t;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        t[i][j] = p[i * dim + j];
    return t;
  }

  /** A particle's volume now, V0 det F, from its properties @p props. */
  template <int dim>
  inline double
  current_volume(const double *props, const CoreFields &f)
  {
    return props[f.initial_volume] *
           determinant(read_tensor<dim>(props + f.deformation_gradient));
  }

  template <int dim>
  inline void
  write_tensor(double *p, const Tensor<2, dim> &t)
  {
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        p[i * dim + j] = t[i][j];
  }

  template <int dim>
  inline SymmetricTensor<2, dim>
  read_symmetric(const double *p)
  {
    SymmetricTensor<2, dim> t;
    for (unsigned int i = 0;
         i < SymmetricTensor<2, dim>::n_independent_components;
         ++i)
      t.access_raw_entry(i) = p[i];
    return t;
  }

  template <int dim>
  inline void
  write_symmetric(double *p, const SymmetricTensor<2, dim> &t)
  {
    for (unsigned int i = 0;
         i < SymmetricTensor<2, dim>::n_independent_components;
         ++i)
      p[i] = t.access_raw_entry(i);
  }
} // namespace dealmpm
