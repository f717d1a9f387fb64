#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <dealmpm/fem/solid_region.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <sstream>

namespace dealmpm
{
  namespace
  {
    /** Per dof of the locally owned cells: the sorted global indices of
     * the vertices of the mesh object (vertex, line, face, cell) its
     * support point sits on, and its component; the same on any
     * partition (k <= 2: one support point per object). */
    template <int dim>
    std::map<types::global_dof_index, std::string>
    dof_keys(const DoFHandler<dim> &dof_handler)
    {
      const FiniteElement<dim>            &fe   = dof_handler.get_fe();
      const std::vector<Point<dim>>       &unit = fe.get_unit_support_points();
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      std::map<types::global_dof_index, std::string> keys;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(dofs);
            for (unsigned int i = 0; i < dofs.size(); ++i)
              {
                std::vector<unsigned int> vertices;
                for (const unsigned int v : cell->vertex_indices())
                  {
                    bool on = true;
                    for (unsigned int d = 0; d < dim; ++d)
                      {
                        const double x     = unit[i][d];
                        const bool   upper = (v >> d) & 1u;
                        if ((x < 1e-12 && upper) || (x > 1 - 1e-12 && !upper))
                          on = false;
                      }
                    if (on)
                      vertices.push_back(cell->vertex_index(v));
                  }
                std::sort(vertices.begin(), vertices.end());
                std::string key =
                  std::to_string(fe.system_to_component_index(i).first);
                for (const unsigned int v : vertices)
                  key += "," + std::to_string(v);
                keys[dofs[i]] = key;
              }
          }
      return keys;
    }

    /** Each owned dof's node (index into @p nodes). */
    template <typename Node>
    std::map<types::global_dof_index, unsigned int>
    node_of_dofs(const std::vector<Node> &nodes, const IndexSet &owned)
    {
      std::map<types::global_dof_index, unsigned int> map;
      for (unsigned int k = 0; k < nodes.size(); ++k)
        for (const unsigned int dof : nodes[k].dof)
          map[owned.nth_index_in_set(dof)] = k;
      return map;
    }

    void
    write_hex(std::ostream &out, const double x)
    {
      out << ' ' << std::hexfloat << x << std::defaultfloat;
    }

    double
    read_hex(std::istream &in)
    {
      std::string word;
      in >> word;
      return std::strtod(word.c_str(), nullptr);
    }
  } // namespace

  template <int dim>
  std::string
  SolidRegion<dim>::save_state() const
  {
    std::ostringstream out;
    out << "step";
    write_hex(out, last_dt);
    write_hex(out, work);
    write_hex(out, row_time);
    for (unsigned int d = 0; d < dim; ++d)
      write_hex(out, row_impulse[d]);
    out << '\n';
    const IndexSet &owned = dof_handler.locally_owned_dofs();
    const auto      node  = node_of_dofs(nodes, owned);
    for (const auto &[dof, key] : dof_keys(dof_handler))
      if (owned.is_element(dof))
        {
          out << "dof " << key;
          write_hex(out, displacement(dof));
          write_hex(out, velocity(dof));
          for (const auto &column : affine)
            write_hex(out, column(dof));
          if (carries_heat())
            {
              // The temperature and the node's debt (region_heat.h).
              write_hex(out, temperature(dof));
              write_hex(out, heat.debt[node.at(dof)]);
            }
          out << '\n';
        }
    const unsigned int n_q = QGauss<dim>(fe.degree + 1).size();
    std::size_t        k   = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          out << "cell " << cell->id().to_string();
          for (unsigned int q = 0; q < n_q; ++q, ++k)
            {
              for (unsigned int c = 0; c < stress[k].n_independent_components;
                   ++c)
                write_hex(out, stress[k].access_raw_entry(c));
              for (unsigned int i = 0; i < dim; ++i)
                for (unsigned int j = 0; j < dim; ++j)
                  write_hex(out, deformation[k][i][j]);
              for (unsigned int j = 0; j < n_internal; ++j)
                write_hex(out, internal[k * n_internal + j]);
            }
          out << '\n';
        }
    return out.str();
  }

  template <int dim>
  typename SolidRegion<dim>::SavedParts
  SolidRegion<dim>::read_parts(const std::vector<std::string> &parts) const
  {
    SavedParts saved;
    saved.last_dt  = last_dt;
    saved.row_time = row_time;
    for (const std::string &part : parts)
      {
        std::istringstream lines(part);
        std::string        line;
        while (std::getline(lines, line))
          {
            std::istringstream in(line);
            std::string        kind, key;
            in >> kind;
            if (kind == "step")
              {
                saved.last_dt = read_hex(in);
                saved.work += read_hex(in);
                saved.row_time = read_hex(in);
                for (unsigned int d = 0; d < dim; ++d)
                  saved.impulse[d] += read_hex(in);
              }
            else if (kind == "dof")
              {
                in >> key;
                std::vector<double> &values = saved.dofs[key];
                for (in >> std::ws; !in.eof(); in >> std::ws)
                  values.push_back(read_hex(in));
              }
            else if (kind == "cell")
              {
                in >> key;
                std::getline(in, saved.cells[key]);
              }
          }
      }
    return saved;
  }

  template <int dim>
  void
  SolidRegion<dim>::load_state(const std::vector<std::string> &parts)
  {
    const SavedParts saved = read_parts(parts);
    last_dt                = saved.last_dt;
    row_time               = saved.row_time;
    const bool first       = Utilities::MPI::this_mpi_process(comm) == 0;
    work                   = first ? saved.work : 0.;
    row_impulse            = first ? saved.impulse : Tensor<1, dim>();
    load_dofs(saved.dofs);
    load_cells(saved.cells);
    // The saved run had heated by all the work done (each step does).
    if (carries_heat())
      mark_work_heated();
  }

  template <int dim>
  void
  SolidRegion<dim>::load_dofs(
    const std::map<std::string, std::vector<double>> &dofs)
  {
    // Per dof: u, v, the affine columns and the temperature.
    const IndexSet   &owned  = dof_handler.locally_owned_dofs();
    const std::size_t n_heat = carries_heat() ? 2 : 0;
    const auto        node   = node_of_dofs(nodes, owned);
    for (const auto &[dof, key] : dof_keys(dof_handler))
      if (owned.is_element(dof))
        {
          const auto found = dofs.find(key);
          AssertThrow(found != dofs.end() &&
                        found->second.size() >= 2 + affine.size() + n_heat,
                      ExcMessage("the saved FEM region has no node " + key));
          displacement(dof) = found->second[0];
          velocity(dof)     = found->second[1];
          for (unsigned int j = 0; j < affine.size(); ++j)
            affine[j](dof) = found->second[2 + j];
          if (n_heat > 0)
            {
              temperature(dof)        = found->second[2 + affine.size()];
              heat.debt[node.at(dof)] = found->second[3 + affine.size()];
            }
        }
    if (n_heat > 0)
      temperature.update_ghost_values();
    displacement.update_ghost_values();
    velocity.update_ghost_values();
  }

  template <int dim>
  void
  SolidRegion<dim>::load_cells(const std::map<std::string, std::string> &cells)
  {
    const unsigned int n_q = QGauss<dim>(fe.degree + 1).size();
    std::size_t        k   = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const auto found = cells.find(cell->id().to_string());
          AssertThrow(found != cells.end(),
                      ExcMessage("the saved FEM region has no cell " +
                                 cell->id().to_string()));
          std::istringstream in(found->second);
          for (unsigned int q = 0; q < n_q; ++q, ++k)
            {
              for (unsigned int c = 0; c < stress[k].n_independent_components;
                   ++c)
                stress[k].access_raw_entry(c) = read_hex(in);
              for (unsigned int i = 0; i < dim; ++i)
                for (unsigned int j = 0; j < dim; ++j)
                  deformation[k][i][j] = read_hex(in);
              for (unsigned int j = 0; j < n_internal; ++j)
                internal[k * n_internal + j] = read_hex(in);
            }
        }
    update_signal_rate();
  }

#define DEALMPM_INSTANTIATE(dim)                             \
  template std::string SolidRegion<dim>::save_state() const; \
  template void SolidRegion<dim>::load_state(const std::vector<std::string> &);
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
