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
} // namespace dealmpm
