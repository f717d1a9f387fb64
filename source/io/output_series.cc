#include <dealmpm/io/output_file.h>
#include <dealmpm/io/output_series.h>

#include <iomanip>
#include <sstream>

namespace dealmpm
{
  namespace
  {
    /** An XDMF temporal series of @p entries' Grid elements. */
    std::string
    xdmf_series(const std::vector<std::pair<double, std::string>> &entries)
    {
      std::string text = "<?xml version=\"1.0\" ?>\n"
                         "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
                         "<Xdmf Version=\"2.0\">\n <Domain>\n"
                         "  <Grid Name=\"series\" GridType=\"Collection\" "
                         "CollectionType=\"Temporal\">\n";
      for (const auto &entry : entries)
        text += entry.second;
      return text + "  </Grid>\n </Domain>\n</Xdmf>\n";
    }
  } // namespace

  void
  OutputSeries::add_and_write(const double       time,
                              const std::string &entry,
                              const std::string &path)
  {
    entries.emplace_back(time, entry);
    try
      {
        write(path);
      }
    catch (...)
      {
        entries.pop_back();
        throw;
      }
  }

  void
  OutputSeries::write(const std::string &path) const
  {
    if (path.size() > 5 && path.substr(path.size() - 5) == ".xdmf")
      {
        OutputFile out(path);
        out.write(xdmf_series(entries));
        out.commit();
        return;
      }
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
    OutputFile out(path);
    out.write(xml.str());
    out.commit();
  }
} // namespace dealmpm
