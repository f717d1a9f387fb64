#include <dealmpm/base/errors.h>
#include <dealmpm/io/hdf5_points.h>
#include <dealmpm/io/output_file.h>

#include <cstdio>
#include <cstring>
#include <hdf5.h>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace dealmpm
{
  using namespace dealii;

  namespace
  {
    /** How the file stores a type (little endian, as VTU and ParaView on
     * every current machine). */
    hid_t
    stored_type(const VtuType type)
    {
      switch (type)
        {
          case VtuType::Int32:
            return H5T_STD_I32LE;
          case VtuType::Int64:
            return H5T_STD_I64LE;
          case VtuType::Float32:
            return H5T_IEEE_F32LE;
          case VtuType::Float64:
            break;
        }
      return H5T_IEEE_F64LE;
    }

    /** XDMF's NumberType and Precision of a type. */
    std::string
    xdmf_type(const VtuType type)
    {
      switch (type)
        {
          case VtuType::Int32:
            return "NumberType=\"Int\" Precision=\"4\"";
          case VtuType::Int64:
            return "NumberType=\"Int\" Precision=\"8\"";
          case VtuType::Float32:
            return "NumberType=\"Float\" Precision=\"4\"";
          case VtuType::Float64:
            break;
        }
      return "NumberType=\"Float\" Precision=\"8\"";
    }

    /** XDMF's attribute type for a number of components (a 3 x 3 tensor
     * has 9; others are listed as matrices). */
    const char *
    attribute_type(const unsigned int n_components)
    {
      switch (n_components)
        {
          case 1:
            return "Scalar";
          case 3:
            return "Vector";
          case 9:
            return "Tensor";
          case 6:
            return "Tensor6";
        }
      return "Matrix";
    }

    /** XDMF's topology of a VTK cell type. */
    const char *
    topology_type(const std::uint8_t vtk_type)
    {
      switch (vtk_type)
        {
          case 5:
            return "Triangle";
          case 9:
            return "Quadrilateral";
          case 12:
            return "Hexahedron";
          case 13:
            return "Wedge";
        }
      throw std::logic_error("no XDMF topology for VTK cell type " +
                             std::to_string(vtk_type));
    }

    /** The /cells rows of this rank: its connectivity, shifted past the
     * points of the ranks before it. */
    std::vector<std::int64_t>
    shifted_cells(const VtuPointCloud &cloud, const std::int64_t offset)
    {
      std::vector<std::int64_t> cells = cloud.connectivity;
      for (std::int64_t &i : cells)
        i += offset;
      return cells;
    }

    /** The HDF5 calls of one file on every rank, each call made on every
     * rank even after one failed (collective calls must match); the first
     * failure's text is kept for agree_on_output_error(). */
    class ParallelFile
    {
    public:
      ParallelFile(const std::string &path, const MPI_Comm comm)
        : path(path)
      {
        H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); // our own messages
        const hid_t access = H5Pcreate(H5P_FILE_ACCESS);
        H5Pset_fapl_mpio(access, comm, MPI_INFO_NULL);
        file =
          check(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access),
                "cannot be created");
        H5Pclose(access);
        transfer = H5Pcreate(H5P_DATASET_XFER);
        H5Pset_dxpl_mpio(transfer, H5FD_MPIO_COLLECTIVE);
      }

      ~ParallelFile()
      {
        H5Pclose(transfer);
        if (file >= 0)
          H5Fclose(file);
      }

      /** Write rows [offset, offset + n) of the n_total x n_columns
       * dataset @p name from @p data (memory type @p memory). */
      void
      write(const std::string &name,
            const hid_t        stored,
            const hid_t        memory,
            const void        *data,
            const hsize_t      n_total,
            const hsize_t      offset,
            const hsize_t      n,
            const hsize_t      n_columns)
      {
        const hsize_t dims[2]  = {n_total, n_columns};
        const hid_t   in_file  = H5Screate_simple(2, dims, nullptr);
        const hid_t   set      = check(H5Dcreate2(file,
                                           name.c_str(),
                                           stored,
                                           in_file,
                                           H5P_DEFAULT,
                                           H5P_DEFAULT,
                                           H5P_DEFAULT),
                                "has no room for " + name);
        const hsize_t start[2] = {offset, 0}, count[2] = {n, n_columns};
        const hid_t   in_memory = H5Screate_simple(2, count, nullptr);
        if (n > 0)
          H5Sselect_hyperslab(
            in_file, H5S_SELECT_SET, start, nullptr, count, nullptr);
        else
          {
            H5Sselect_none(in_file);
            H5Sselect_none(in_memory);
          }
        check(H5Dwrite(set, memory, in_memory, in_file, transfer, data),
              "could not take " + name);
        H5Sclose(in_memory);
        H5Sclose(in_file);
        if (set >= 0)
          H5Dclose(set);
      }

      /** Close the file (collective); returns the first failure's text. */
      std::string
      close()
      {
        if (file >= 0)
          check(H5Fclose(file), "could not be closed");
        file = -1;
        return problem;
      }

    private:
      template <typename Id>
      Id
      check(const Id id, const std::string &what)
      {
        if (id < 0 && problem.empty())
          problem = "output file " + path + " " + what;
        return id;
      }

      std::string path, problem;
      hid_t       file = -1, transfer = -1;
    };
  } // namespace

  namespace
  {
    /** A rank's rows of a dataset of all ranks: how many in all, where its
     * own start and how many it has. */
    struct Rows
    {
      hsize_t total, offset, n;
    };

    /** Collective: the rows when this rank has @p n of them, in rank
     * order. */
    Rows
    rows_of(const unsigned long long n, const MPI_Comm comm)
    {
      unsigned long long before = 0;
      MPI_Exscan(&n, &before, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, comm);
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        before = 0; // MPI leaves rank 0's undefined
      return {Utilities::MPI::sum(n, comm), before, n};
    }

    /** The XDMF Grid element of a file @p name written by
     * Hdf5PointCloud::write(). */
    std::string
    xdmf_grid(const VtuPointCloud &cloud,
              const std::string   &name,
              const std::string   &grid_name,
              const double         time,
              const Rows          &points,
              const Rows          &cells)
    {
      const hsize_t      total = points.total;
      std::ostringstream grid;
      grid << std::setprecision(17);
      grid << "   <Grid Name=\"" << xml_escaped(grid_name)
           << "\" GridType=\"Uniform\">\n"
           << "    <Time Value=\"" << time << "\"/>\n"
           << "    <Geometry GeometryType=\"XYZ\">\n"
           << "     <DataItem Dimensions=\"" << total
           << " 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">"
           << xml_escaped(name) << ":/points</DataItem>\n"
           << "    </Geometry>\n";
      if (cloud.cell_type != 1)
        grid << "    <Topology TopologyType=\""
             << topology_type(cloud.cell_type) << "\" NumberOfElements=\""
             << cells.total << "\">\n"
             << "     <DataItem Dimensions=\"" << cells.total << " "
             << cloud.points_per_cell
             << "\" NumberType=\"Int\" Precision=\"8\" Format=\"HDF\">"
             << xml_escaped(name) << ":/cells</DataItem>\n"
             << "    </Topology>\n";
      else
        grid << "    <Topology TopologyType=\"Polyvertex\" NumberOfElements=\""
             << total << "\" NodesPerElement=\"1\"/>\n";
      for (const VtuArray &a : cloud.arrays)
        grid << "    <Attribute Name=\"" << xml_escaped(a.name)
             << "\" AttributeType=\"" << attribute_type(a.n_components)
             << "\" Center=\"Node\">\n"
             << "     <DataItem Dimensions=\"" << total << " " << a.n_components
             << "\" " << xdmf_type(a.type) << " Format=\"HDF\">"
             << xml_escaped(name) << ":/" << xml_escaped(a.name)
             << "</DataItem>\n"
             << "    </Attribute>\n";
      grid << "   </Grid>\n";
      return grid.str();
    }
  } // namespace

  std::string
  Hdf5PointCloud::write(const VtuPointCloud &cloud,
                        const std::string   &path,
                        const std::string   &name,
                        const double         time,
                        const MPI_Comm       comm,
                        const std::string   &grid_name)
  {
    const Rows        points    = rows_of(cloud.n_points(), comm);
    const std::string temporary = path + ".tmp";
    ParallelFile      file(temporary, comm);
    file.write("points",
               H5T_IEEE_F64LE,
               H5T_NATIVE_DOUBLE,
               cloud.points.data(),
               points.total,
               points.offset,
               points.n,
               3);
    for (const VtuArray &a : cloud.arrays)
      {
        const bool integers =
          a.type == VtuType::Int32 || a.type == VtuType::Int64;
        file.write(a.name,
                   stored_type(a.type),
                   integers ? H5T_NATIVE_INT64 : H5T_NATIVE_DOUBLE,
                   integers ? static_cast<const void *>(a.integers.data()) :
                              static_cast<const void *>(a.reals.data()),
                   points.total,
                   points.offset,
                   points.n,
                   a.n_components);
      }
    // Cells or not is the same on every rank (cell_type), also on one
    // without points.
    const bool has_cells = cloud.cell_type != 1;
    const Rows cells =
      rows_of(has_cells ? cloud.connectivity.size() / cloud.points_per_cell : 0,
              comm);
    if (has_cells)
      file.write("cells",
                 H5T_STD_I64LE,
                 H5T_NATIVE_INT64,
                 shifted_cells(cloud, points.offset).data(),
                 cells.total,
                 cells.offset,
                 cells.n,
                 cloud.points_per_cell);
    std::string problem = file.close();
    if (problem.empty() && Utilities::MPI::this_mpi_process(comm) == 0 &&
        std::rename(temporary.c_str(), path.c_str()) != 0)
      problem = "output file " + path + ": " + std::strerror(errno);
    agree_on_output_error(problem, "", comm);
    return xdmf_grid(cloud, name, grid_name, time, points, cells);
  }
} // namespace dealmpm
