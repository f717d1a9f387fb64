#include <deal.II/base/mpi.h>

#include <dealmpm/io/output_file.h>
#include <dealmpm/io/particle_csv.h>

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace dealmpm
{
  template <int dim>
  void
  write_particle_csv(const ParticleSet<dim> &particles,
                     const std::string      &path,
                     const MPI_Comm          comm)
  {
    const CoreFields &f = particles.fields;
    std::vector<std::pair<types::particle_index, std::string>> rows;
    for (const auto &p : particles.handler)
      {
        const auto         props = p.get_properties();
        std::ostringstream line;
        line << std::setprecision(12) << p.get_id();
        for (unsigned int d = 0; d < dim; ++d)
          line << ',' << p.get_location()[d];
        for (unsigned int d = 0; d < dim; ++d)
          line << ',' << props[f.velocity + d];
        for (unsigned int d = 0; d < dim; ++d)
          line << ',' << props[f.displacement + d];
        line << ','
             << determinant(read_tensor<dim>(&props[f.deformation_gradient]))
             << ',' << particles.body_of(props) + 1; // as 'Body N' counts
        rows.emplace_back(p.get_id(), line.str());
      }
    const auto gathered = Utilities::MPI::gather(comm, rows, 0);
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    std::vector<std::pair<types::particle_index, std::string>> all;
    for (const auto &part : gathered)
      all.insert(all.end(), part.begin(), part.end());
    std::sort(all.begin(), all.end());
    std::string text   = "id";
    const char *axes[] = {"x", "y", "z"};
    for (const std::string prefix : {"", "v", "u"})
      for (unsigned int d = 0; d < dim; ++d)
        text += ',' + prefix + axes[d];
    text += ",J,body\n";
    for (const auto &row : all)
      text += row.second + '\n';
    OutputFile out(path);
    out.write(text);
    out.commit();
  }

#define DEALMPM_INSTANTIATE(dim)                             \
  template void write_particle_csv(const ParticleSet<dim> &, \
                                   const std::string &,      \
                                   MPI_Comm);
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
