// Pareto marking on a hand-made set of (wall time, error) points.
#include <dealmpm/study/pareto.h>

#include <gtest/gtest.h>

#include <limits>

using namespace dealmpm;

TEST(Pareto, MarksTheRunsNothingBeatsInBoth)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  //                               0     1     2     3     4    5    6    7
  const std::vector<double> cost  = {1.0, 2.0, 2.0, 3.0, 4.0, 0.5, nan, 3.0};
  const std::vector<double> error = {
    1e-2, 5e-3, 6e-3, 5e-3, 1e-3, 2e-2, 1e-9, 1e-3};
  // 0: cheapest below 2e-2; 1: beats 2 (same cost, smaller error) and 3
  // (same error, cheaper); 7 beats 4 (same error, cheaper); 5 is the
  // cheapest of all; 6 has no cost (a failed run) and takes no part.
  const std::vector<bool> expected = {
    true, true, false, false, false, true, false, true};
  EXPECT_EQ(pareto_optimal(cost, error), expected);
}

TEST(Pareto, EqualPointsAreBothOptimal)
{
  EXPECT_EQ(pareto_optimal({1., 1.}, {1e-3, 1e-3}),
            (std::vector<bool>{true, true}));
}
