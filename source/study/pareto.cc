#include <dealmpm/study/pareto.h>

#include <cmath>

namespace dealmpm
{
  std::vector<bool>
  pareto_optimal(const std::vector<double> &cost,
                 const std::vector<double> &error)
  {
    const std::size_t n = cost.size();
    std::vector<bool> optimal(n, false);
    const auto        valid = [&](const std::size_t i) {
      return std::isfinite(cost[i]) && std::isfinite(error[i]);
    };
    for (std::size_t i = 0; i < n; ++i)
      {
        if (!valid(i))
          continue;
        bool dominated = false;
        for (std::size_t j = 0; j < n && !dominated; ++j)
          dominated = j != i && valid(j) && cost[j] <= cost[i] &&
                      error[j] <= error[i] &&
                      (cost[j] < cost[i] || error[j] < error[i]);
        optimal[i] = !dominated;
      }
    return optimal;
  }
} // namespace dealmpm
