#pragma once

#include <string>
#include <utility>
#include <vector>

namespace dealmpm
{
  /**
   * A time series that ParaView opens, rewritten whole at each output
   * through a temporary file renamed over it: whenever a run stops, even by
   * SIGKILL, the series on disk is complete and lists only files that exist
   * (the caller adds an entry only after its files are written).
   *
   * The path's extension says the kind: a .pvd file lists each output's
   * file (an entry is its name), an .xdmf file holds each output's XDMF
   * Grid element (an entry is the element, which names its HDF5 file).
   */
  class OutputSeries
  {
  public:
    /** Add (time, entry) and write the series to @p path; throws
     * OutputError and forgets the entry when it cannot be written. */
    void
    add_and_write(const double       time,
                  const std::string &entry,
                  const std::string &path);

    /** Write the series as it is (a resumed run's, from its checkpoint);
     * throws OutputError. */
    void
    write(const std::string &path) const;

    bool
    empty() const
    {
      return entries.empty();
    }

    /** Whether the entries are XDMF Grid elements (an .xdmf series), not
     * file names (a .pvd series). */
    bool
    holds_xdmf() const
    {
      return !entries.empty() &&
             entries.front().second.find("<Grid") != std::string::npos;
    }

    bool
    operator==(const OutputSeries &other) const
    {
      return entries == other.entries;
    }

    /** Needs <boost/serialization/{vector,utility,string}.hpp>. */
    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int /*version*/)
    {
      archive &entries;
    }

  private:
    std::vector<std::pair<double, std::string>> entries;
  };
} // namespace dealmpm
