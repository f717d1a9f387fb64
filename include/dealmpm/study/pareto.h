#pragma once

#include <vector>

namespace dealmpm
{
  /**
   * Which of the points (cost, error) are Pareto-optimal: no other point is
   * at least as cheap and at least as accurate and better in one of the two.
   * Points with a non-finite value are never optimal and never dominate.
   */
  std::vector<bool>
  pareto_optimal(const std::vector<double> &cost,
                 const std::vector<double> &error);
} // namespace dealmpm
