#include <dealmpm/io/output_file.h>
#include <dealmpm/io/pvd_series.h>

#include <iomanip>
#include <sstream>

namespace dealmpm
{
  void
  PvdSeries::add_and_write(const double       time,
                           const std::string &file,
                           const std::string &pvd_path)
  {
    entries.emplace_back(time, file);
    try
      {
        write(pvd_path);
      }
    catch (...)
      {
        entries.pop_back();
        throw;
      }
  }

  void
  PvdSeries::write(const std::string &pvd_path) const
  {
    std::ostringstream xml;
    // Enough digits to tell apart the times of outputs a step apart.
    xml << std::setprecision(12)
        << "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"Collection\" version=\"0.1\" "
           "byte_order=\"LittleEndian\">\n  <Collection>\n";
    for (const auto &[t, name] : entries)
      xml << "    <DataSet timestep=\"" << t
          << "\" group=\"\" part=\"0\" file=\"" << name << "\"/>\n";
    xml << "  </Collection>\n</VTKFile>\n";
    OutputFile out(pvd_path);
    out.write(xml.str());
    out.commit();
  }
} // namespace dealmpm
