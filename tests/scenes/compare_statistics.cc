// compare_statistics a.csv b.csv tolerance: every column but wall_time of
// every row must agree to the relative tolerance (relative to the column's
// largest magnitude, so that quantities that are zero up to round-off, like
// the total momentum of the colliding disks, compare sensibly).
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
  int    failures = 0;
  double worst    = 0;
  for (std::size_t c = 0; c < a[0].size(); ++c)
    {
      if (a[0][c] == "wall_time")
        continue;
      double scale = 0;
      for (std::size_t r = 1; r < a.size(); ++r)
        scale = std::max(scale, std::abs(std::stod(a[r][c])));
      for (std::size_t r = 1; r < a.size(); ++r)
        {
          const double x = std::stod(a[r][c]), y = std::stod(b[r][c]);
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
