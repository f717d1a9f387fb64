#pragma once

#include <string>
#include <utility>
#include <vector>

namespace dealmpm
{
  /**
   * A .pvd time series (what ParaView opens), rewritten whole at each output
   * through a temporary file renamed over it: whenever a run stops, even by
   * SIGKILL, the series on disk is complete and lists only files that exist
   * (the caller adds an entry only after its files are written).
   */
  class PvdSeries
  {
  public:
    /** Add (time, file) and write the series to @p pvd_path; throws
     * OutputError and forgets the entry when it cannot be written. */
    void
    add_and_write(const double       time,
                  const std::string &file,
                  const std::string &pvd_path);

    /** Write the series as it is (a resumed run's, from its checkpoint);
     * throws OutputError. */
    void
    write(const std::string &pvd_path) const;

    bool
    empty() const
    {
      return entries.empty();
    }

    bool
    operator==(const PvdSeries &other) const
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
