#include <deal.II/base/utilities.h>

#include <dealmpm/base/load_curve.h>

#include <algorithm>
#include <cmath>

namespace dealmpm
{
  LoadCurve
  LoadCurve::read(const SceneReader &reader, const std::string &entry)
  {
    const std::string expected =
      "a table 'time: factor, time: factor, ...' with increasing times "
      "(e.g. '0: 0, 0.01: 1'), or nothing for a factor 1";
    LoadCurve curve;
    for (const auto &item :
         Utilities::split_string_list(reader.get(entry), ','))
      {
        const auto parts = Utilities::split_string_list(item, ':');
        double     t = std::nan(""), f = std::nan("");
        try
          {
            if (parts.size() == 2)
              {
                t = Utilities::string_to_double(parts[0]);
                f = Utilities::string_to_double(parts[1]);
              }
          }
        catch (...)
          {}
        if (!std::isfinite(t) || !std::isfinite(f) ||
            (!curve.points.empty() && !(t > curve.points.back().first)))
          reader.fail(entry, expected);
        curve.points.emplace_back(t, f);
      }
    return curve;
  }

  double
  LoadCurve::operator()(const double t) const
  {
    if (points.empty())
      return 1.;
    if (t <= points.front().first)
      return points.front().second;
    if (t >= points.back().first)
      return points.back().second;
    const auto   next   = std::upper_bound(points.begin(),
                                       points.end(),
                                       t,
                                       [](const double s, const auto &p) {
                                         return s < p.first;
                                       });
    const auto   before = next - 1;
    const double w      = (t - before->first) / (next->first - before->first);
    return (1 - w) * before->second + w * next->second;
  }

  namespace
  {
    /** The integral of the curve through @p points (at least one) from
     * the first point's time to @p t: the trapezoids of the whole
     * segments and the part of the one @p t is in; constant outside. */
    double
    from_first_point(const std::vector<std::pair<double, double>> &points,
                     const double                                  t)
    {
      double sum = 0;
      for (std::size_t k = 0; k + 1 < points.size(); ++k)
        {
          const auto [t0, f0] = points[k];
          const auto [t1, f1] = points[k + 1];
          if (t <= t0)
            return sum + f0 * (t - t0);
          const double s = std::min(t, t1) - t0; // the part in this segment
          sum += s * (f0 + 0.5 * (f1 - f0) * s / (t1 - t0));
          if (t <= t1)
            return sum;
        }
      const auto [t_last, f_last] = points.back();
      return sum + f_last * (t - t_last);
    }
  } // namespace

  double
  LoadCurve::integral(const double t) const
  {
    if (points.empty())
      return t;
    return from_first_point(points, t) - from_first_point(points, 0.);
  }
} // namespace dealmpm
