#pragma once

#include <dealmpm/base/property_layout.h>
#include <dealmpm/grid/nodal_fields.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace dealmpm
{
  /**
   * The nodal fields of a run by name: the core fields every step uses
   * (NodalFields: mass, momentum, force, v*, increment), and fields kept
   * once per body, allocated only when a part asks for them before
   * reinit() (contact asks for a velocity per body; nothing else pays).
   * Every vector has the grid's node layout and is rebuilt with reinit()
   * when the grid changes.
   */
  template <int dim>
  class NodalFieldSet
  {
  public:
    NodalFields<dim> core;

    /** With body fields (contact), each body's own NodalFields and its
     * mass gradient sum_p m_p grad N_i(x_p) (which points out of the body:
     * minus the nodal mass's gradient in the node's position); the core
     * fields are then their sums (the centre-of-mass field). Empty
     * otherwise. */
    std::vector<NodalFields<dim>>             body;
    std::vector<std::array<NodalVector, dim>> mass_gradient;

    /** Give each body its own nodal fields from the next reinit() on: P2G
     * then maps each particle to its body's fields, and G2P reads them. */
    void
    request_body_fields()
    {
      with_body_fields = true;
    }

    bool
    has_body_fields() const
    {
      return with_body_fields;
    }

    /** Ask for @p field once per body; the same name twice must agree in
     * components. */
    void
    request_per_body(const FieldDescription &field)
    {
      for (const PerBody &f : per_body_fields)
        if (f.name == field.name)
          {
            if (f.n_components != field.n_components)
              throw std::logic_error("nodal field '" + field.name +
                                     "' asked for with two sizes");
            return;
          }
      per_body_fields.push_back({field.name, field.n_components, {}});
    }

    /** Size every field for the grid's nodes, the per-body ones for
     * @p n_bodies bodies. */
    void
    reinit(
      const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner,
      const unsigned int                                        n_bodies)
    {
      core.reinit(partitioner);
      if (with_body_fields)
        {
          body.resize(n_bodies);
          mass_gradient.resize(n_bodies);
          for (unsigned int b = 0; b < n_bodies; ++b)
            {
              body[b].reinit(partitioner);
              for (NodalVector &v : mass_gradient[b])
                v.reinit(partitioner);
            }
        }
      for (PerBody &f : per_body_fields)
        {
          f.vectors.resize(n_bodies * f.n_components);
          for (NodalVector &v : f.vectors)
            v.reinit(partitioner);
        }
    }

    bool
    has(const std::string &name) const
    {
      for (const PerBody &f : per_body_fields)
        if (f.name == name)
          return true;
      return false;
    }

    /** Component @p c of field @p name of body @p b (0-based). */
    NodalVector &
    per_body(const std::string &name, const unsigned int b, const unsigned c)
    {
      PerBody &f = find(name);
      return f.vectors.at(b * f.n_components + c);
    }

    const NodalVector &
    per_body(const std::string &name,
             const unsigned int b,
             const unsigned     c) const
    {
      return const_cast<NodalFieldSet &>(*this).per_body(name, b, c);
    }

    /** How many nodal vectors are allocated, the core ones included. */
    unsigned int
    n_vectors() const
    {
      unsigned int n = (1 + 4 * dim) * (1 + body.size()) + dim * body.size();
      for (const PerBody &f : per_body_fields)
        n += f.vectors.size();
      return n;
    }

  private:
    struct PerBody
    {
      std::string              name;
      unsigned int             n_components;
      std::vector<NodalVector> vectors; ///< body-major
    };

    PerBody &
    find(const std::string &name)
    {
      for (PerBody &f : per_body_fields)
        if (f.name == name)
          return f;
      throw std::out_of_range("no nodal field '" + name + "'");
    }

    std::vector<PerBody> per_body_fields;
    bool                 with_body_fields = false;
  };
} // namespace dealmpm
