#pragma once

#include <dealmpm/base/scene_reader.h>

#include <string>
#include <utility>
#include <vector>

namespace dealmpm
{
  /**
   * A factor against time, piecewise linear through a table of (time,
   * factor) points with increasing times, constant before the first and
   * after the last. An empty table is 1 at all times.
   */
  class LoadCurve
  {
  public:
    LoadCurve() = default;

    /** The scene's text "t0: f0, t1: f1, ..." of entry @p entry (the
     * reader fails with one line on anything else). */
    static LoadCurve
    read(const SceneReader &reader, const std::string &entry);

    double
    operator()(const double t) const;

    /** The integral from 0 to @p t (negative for t < 0), exact for the
     * piecewise linear curve: a velocity from an acceleration record. */
    double
    integral(const double t) const;

  private:
    std::vector<std::pair<double, double>> points;
  };
} // namespace dealmpm
