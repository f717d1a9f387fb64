// compare_statistics a.csv b.csv tolerance: every column but wall_time and
// the particles per rank of every row must agree to the relative tolerance,
// relative to the largest magnitude in the column's group: the momentum
// components together, the energies together, any other column alone. So a
// momentum component that is zero up to round-off (the sideways momentum of a
// settling column) is measured against the momentum there is, not against its
// own noise. A value that is not a finite number (NaN, inf) in either file
// fails: a NaN compares unequal to everything yet passes every "difference >
// tolerance" test, and an inf in a column would make every difference in
// it relative to infinity.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  std::vector<std::vector<std::string>>
  read_csv(const char *path)
  {
    std::ifstream                         in(path);
    std::vector<std::vector<std::string>> rows;
    for (std::string line; std::getline(in, line);)
      {
        std::vector<std::string> cells;
        std::stringstream        s(line);
        for (std::string cell; std::getline(s, cell, ',');)
          cells.push_back(cell);
        rows.push_back(cells);
      }
    return rows;
  }
} // namespace

int
main(int argc, char **argv)
{
  if (argc != 4)
    {
      std::cerr << "usage: compare_statistics a.csv b.csv relative_tolerance\n";
      return 2;
    }
  const auto   a         = read_csv(argv[1]);
  const auto   b         = read_csv(argv[2]);
  const double tolerance = std::stod(argv[3]);
  if (a.size() < 2 || a.size() != b.size() || a[0] != b[0])
    {
      std::cerr << "different shapes: " << a.size() << " vs " << b.size()
                << " rows\n";
      return 1;
    }
  for (std::size_t r = 1; r < a.size(); ++r)
    if (a[r].size() != a[0].size() || b[r].size() != a[0].size())
      {
        std::cerr << "different shapes: row " << r << " has " << a[r].size()
                  << " vs " << b[r].size() << " values, the header "
                  << a[0].size() << "\n";
        return 1;
      }
  const auto group = [](const std::string &name) {
    if (name.rfind("momentum", 0) == 0)
      return std::string("momentum");
    if (name.size() > 6 && name.compare(name.size() - 6, 6, "energy") == 0)
      return std::string("energy");
    // The components of a vector (a region's support force) share a scale.
    if (name.size() > 2 && name[name.size() - 2] == '_' &&
        std::string("xyz").find(name.back()) != std::string::npos)
      return name.substr(0, name.size() - 2);
    return name;
  };
  int    failures = 0;
  double worst    = 0;
  for (std::size_t c = 0; c < a[0].size(); ++c)
    {
      // The wall time and the particles per rank may differ.
      if (a[0][c] == "wall_time" || a[0][c].rfind("particles_per_rank", 0) == 0)
        continue;
      double scale = 0;
      for (std::size_t g = 0; g < a[0].size(); ++g)
        if (group(a[0][g]) == group(a[0][c]))
          for (std::size_t r = 1; r < a.size(); ++r)
            scale = std::max(scale, std::abs(std::stod(a[r][g])));
      // Drifts and losses are already relative (differences of nearly equal
      // sums, round-off against 1), J and CFL numbers are of order one.
      for (const std::string ratio :
           {"energy_drift", "momentum_drift", "mass_loss", "min_J", "max_cfl"})
        if (a[0][c] == ratio)
          scale = std::max(scale, 1.);
      for (std::size_t r = 1; r < a.size(); ++r)
        {
          const double x = std::stod(a[r][c]), y = std::stod(b[r][c]);
          if (!std::isfinite(x) || !std::isfinite(y))
            {
              if (failures++ < 10)
                std::cerr << a[0][c] << " row " << r << ": " << x << " vs " << y
                          << " (not a finite number)\n";
              continue;
            }
          const double difference = scale > 0 ? std::abs(x - y) / scale : 0.;
          worst                   = std::max(worst, difference);
          if (difference > tolerance)
            {
              if (failures++ < 10)
                std::cerr << a[0][c] << " row " << r << ": " << x << " vs " << y
                          << "\n";
            }
        }
    }
  std::cout << "largest relative difference: " << worst << " (tolerance "
            << tolerance << ")\n";
  return failures == 0 ? 0 : 1;
}
