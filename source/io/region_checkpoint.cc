#include <dealmpm/base/errors.h>
#include <dealmpm/io/output_file.h>
#include <dealmpm/io/region_checkpoint.h>

#include <fstream>
#include <sstream>

namespace dealmpm
{
  namespace
  {
    std::string
    region_file(const std::string &folder,
                const unsigned int region,
                const unsigned int rank)
    {
      return folder + "/fem_region_" + std::to_string(region + 1) + "." +
             std::to_string(rank) + ".txt";
    }
  } // namespace

  template <int dim>
  void
  save_fem_regions(const FemRegions<dim> &regions,
                   const std::string     &folder,
                   const MPI_Comm         comm)
  {
    const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
    std::string        problem;
    for (unsigned int r = 0; r < regions.list().size(); ++r)
      try
        {
          OutputFile file(region_file(folder, r, rank));
          file.write(regions.saved_state(r));
          file.commit();
        }
      catch (const OutputError &e)
        {
          problem = e.what();
        }
    agree_on_output_error(problem, "", comm);
  }

  template <int dim>
  void
  restore_fem_regions(FemRegions<dim>   &regions,
                      const std::string &folder,
                      const unsigned int n_saved_ranks,
                      const MPI_Comm     comm)
  {
    const bool root = Utilities::MPI::this_mpi_process(comm) == 0;
    for (unsigned int r = 0; r < regions.list().size(); ++r)
      {
        std::vector<std::string> parts;
        for (unsigned int rank = 0; rank < n_saved_ranks; ++rank)
          {
            const std::string file = region_file(folder, r, rank);
            std::ifstream     in(file);
            if (!in)
              throw InputError(file +
                               ": cannot be read (the checkpoint "
                               "has no state of " +
                               regions.list()[r].name + ")");
            std::ostringstream text;
            text << in.rdbuf();
            parts.push_back(text.str());
          }
        regions.restore_state(r, parts, root);
      }
  }

#define DEALMPM_INSTANTIATE(dim)                          \
  template void save_fem_regions(const FemRegions<dim> &, \
                                 const std::string &,     \
                                 const MPI_Comm);         \
  template void restore_fem_regions(FemRegions<dim> &,    \
                                    const std::string &,  \
                                    const unsigned int,   \
                                    const MPI_Comm);
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
