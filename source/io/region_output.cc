#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/utilities.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>

#include <dealmpm/io/hdf5_points.h>
#include <dealmpm/io/output_folder.h>
#include <dealmpm/io/region_output.h>
#include <dealmpm/io/vtu_writer.h>

namespace dealmpm
{
  namespace
  {
    /** The (k + 1)^dim points of a cell's lattice at spacing 1 / k in the
     * reference cell, x fastest: the corners of its k^dim sub-cells. */
    template <int dim>
    Quadrature<dim>
    lattice(const unsigned int k)
    {
      std::vector<Point<dim>> points;
      const unsigned int      n = Utilities::pow(k + 1, dim);
      for (unsigned int i = 0; i < n; ++i)
        {
          Point<dim>   p;
          unsigned int rest = i;
          for (unsigned int d = 0; d < dim; ++d, rest /= k + 1)
            p[d] = double(rest % (k + 1)) / k;
          points.push_back(p);
        }
      return Quadrature<dim>(points);
    }

    /** The sub-cells of a cell's lattice (quads or hexahedra in VTK's
     * order), its points numbered from @p first. */
    template <int dim>
    void
    add_sub_cells(const unsigned int k,
                  const std::size_t  first,
                  VtuPointCloud     &cloud)
    {
      static const unsigned int corner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
      const unsigned int        side         = k + 1;
      for (unsigned int c = 0; c < Utilities::pow(k, dim); ++c)
        {
          const unsigned int i = c % k, j = (c / k) % k, l = c / (k * k);
          for (unsigned int top = 0; top < (dim == 3 ? 2u : 1u); ++top)
            for (const auto &q : corner)
              cloud.connectivity.push_back(
                first + (i + q[0]) + side * (j + q[1]) +
                (dim == 3 ? side * side * (l + top) : 0));
        }
    }

    /** The arrays of a region's output, by index into cloud.arrays. */
    struct RegionArrays
    {
      unsigned int              rank, velocity, displacement, stress, von_mises;
      std::vector<unsigned int> internal;
    };

    /** Named and typed as the particles' arrays are (particle_output.cc),
     * so that one ParaView setting colours both. */
    RegionArrays
    add_region_arrays(VtuPointCloud                       &cloud,
                      const std::vector<FieldDescription> &internal)
    {
      RegionArrays a;
      a.rank         = cloud.add_array("mpi_rank", VtuType::Int32, 1);
      a.velocity     = cloud.add_array("velocity", VtuType::Float32, 3);
      a.displacement = cloud.add_array("displacement", VtuType::Float32, 3);
      a.stress       = cloud.add_array("stress", VtuType::Float32, 9);
      a.von_mises    = cloud.add_array("von_mises", VtuType::Float32, 1);
      for (const FieldDescription &f : internal)
        a.internal.push_back(
          cloud.add_array(f.name, VtuType::Float32, f.n_components));
      return a;
    }

    /** <directory>/<base>.h5 of all ranks' @p cloud, its Grid named
     * @p base; returns the XDMF Grid element. */
    std::string
    write_hdf5(const VtuPointCloud &cloud,
               const std::string   &directory,
               const std::string   &base,
               const double         time,
               const MPI_Comm       comm)
    {
      return Hdf5PointCloud::write(cloud,
                                   directory + "/" + base + ".h5",
                                   step_folder + "/" + base + ".h5",
                                   time,
                                   comm,
                                   base);
    }
  } // namespace

  template <int dim>
  VtuPointCloud
  region_cloud(const SolidRegion<dim> &region)
  {
    using Vector_ = LinearAlgebra::distributed::Vector<double>;
    Vector_ u(region.get_displacement()), v(region.get_velocity());
    u.update_ghost_values();
    v.update_ghost_values();
    // The temperature sits at each of a node's dofs: its x component.
    const bool                         heat = region.carries_heat();
    const Vector_                     &T    = region.get_temperature();
    std::vector<SymmetricTensor<2, 3>> stress;
    std::vector<double>                von_mises;
    std::vector<std::vector<double>>   internal;
    region.cell_means(stress, von_mises, internal);

    VtuPointCloud      cloud;
    const RegionArrays a =
      add_region_arrays(cloud, region.get_material().internal_variables());
    const unsigned int k        = region.degree(),
                       per_cell = Utilities::pow(k + 1, dim);
    const unsigned int temperature =
      heat ? cloud.add_array("temperature", VtuType::Float32, 1) : 0;
    cloud.resize(per_cell * stress.size());
    cloud.cell_type       = dim == 2 ? 9 : 12; // VTK_QUAD, VTK_HEXAHEDRON
    cloud.points_per_cell = Utilities::pow(2, dim);

    const MappingQ1<dim>             mapping;
    FEValues<dim>                    fe_values(mapping,
                            region.get_dof_handler().get_fe(),
                            lattice<dim>(k),
                            update_values | update_quadrature_points);
    const FEValuesExtractors::Vector vector(0);
    std::vector<Tensor<1, dim>> u_at(per_cell), v_at(per_cell), T_at(per_cell);
    std::size_t                 c = 0, i = 0;
    for (const auto &cell : region.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[vector].get_function_values(u, u_at);
          fe_values[vector].get_function_values(v, v_at);
          if (heat)
            fe_values[vector].get_function_values(T, T_at);
          add_sub_cells<dim>(k, i, cloud);
          for (unsigned int q = 0; q < per_cell; ++q, ++i)
            {
              // On the deformed mesh, as the particles are where they are.
              const Point<dim> x = fe_values.quadrature_point(q) + u_at[q];
              for (unsigned int d = 0; d < dim; ++d)
                {
                  cloud.points[3 * i + d]                       = x[d];
                  cloud.arrays[a.velocity].reals[3 * i + d]     = v_at[q][d];
                  cloud.arrays[a.displacement].reals[3 * i + d] = u_at[q][d];
                }
              // Per cell: its mean, constant in the cell.
              for (unsigned int r = 0; r < 3; ++r)
                for (unsigned int s = 0; s < 3; ++s)
                  cloud.arrays[a.stress].reals[9 * i + 3 * r + s] =
                    stress[c][r][s];
              cloud.arrays[a.von_mises].reals[i] = von_mises[c];
              cloud.arrays[a.rank].integers[i]   = cell->subdomain_id();
              if (heat)
                cloud.arrays[temperature].reals[i] = T_at[q][0];
              std::size_t j = 0;
              for (const unsigned int array : a.internal)
                {
                  VtuArray &values = cloud.arrays[array];
                  for (unsigned int m = 0; m < values.n_components; ++m, ++j)
                    values.reals[values.n_components * i + m] = internal[c][j];
                }
            }
          ++c;
        }
    return cloud;
  }

  template <int dim>
  std::string
  write_region_output(const SolidRegion<dim> &region,
                      const std::string      &directory,
                      const std::string      &base,
                      const OutputFormat      format,
                      const double            time)
  {
    const VtuPointCloud cloud = region_cloud(region);
    const MPI_Comm      comm  = region.get_communicator();
    if (format == OutputFormat::hdf5)
      return write_hdf5(cloud, directory, base, time, comm);
    // zlib's fastest level: a 3D region of 32k cells is 2 MB a rank raw.
    return write_vtu_pieces(cloud,
                            directory,
                            base,
                            Utilities::MPI::this_mpi_process(comm),
                            Utilities::MPI::n_mpi_processes(comm),
                            true);
  }

  template <int dim>
  std::string
  write_drawn_body(const DrawnBody<dim> &body,
                   const std::string    &directory,
                   const std::string    &base,
                   const OutputFormat    format,
                   const double          time,
                   const MPI_Comm        comm)
  {
    // Every rank knows it; rank 0 writes it.
    const bool         first = Utilities::MPI::this_mpi_process(comm) == 0;
    VtuPointCloud      cloud;
    const unsigned int velocity =
      cloud.add_array("velocity", VtuType::Float32, 3);
    cloud.resize(first ? body.points.size() : 0);
    cloud.cell_type       = body.cell_type;
    cloud.points_per_cell = body.points_per_cell();
    for (std::size_t i = 0; i < cloud.n_points(); ++i)
      for (unsigned int d = 0; d < dim; ++d)
        {
          cloud.points[3 * i + d]                 = body.points[i][d];
          cloud.arrays[velocity].reals[3 * i + d] = body.velocity[d];
        }
    if (first)
      cloud.connectivity.assign(body.connectivity.begin(),
                                body.connectivity.end());
    if (format == OutputFormat::hdf5)
      return write_hdf5(cloud, directory, base, time, comm);
    if (first)
      cloud.write_vtu(directory + "/" + base + ".vtu");
    return base + ".vtu";
  }

  template VtuPointCloud
  region_cloud(const SolidRegion<2> &);
  template VtuPointCloud
  region_cloud(const SolidRegion<3> &);
  template std::string
  write_region_output(const SolidRegion<2> &,
                      const std::string &,
                      const std::string &,
                      OutputFormat,
                      double);
  template std::string
  write_region_output(const SolidRegion<3> &,
                      const std::string &,
                      const std::string &,
                      OutputFormat,
                      double);
  template std::string
  write_drawn_body(const DrawnBody<2> &,
                   const std::string &,
                   const std::string &,
                   OutputFormat,
                   double,
                   MPI_Comm);
  template std::string
  write_drawn_body(const DrawnBody<3> &,
                   const std::string &,
                   const std::string &,
                   OutputFormat,
                   double,
                   MPI_Comm);
} // namespace dealmpm
