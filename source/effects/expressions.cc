#include <dealmpm/effects/expressions.h>

#include <iostream>
#include <sstream>

namespace dealmpm
{
  std::string
  coordinate_names(const int dim, const bool with_time)
  {
    const std::string names[] = {"x", "y", "z"};
    std::string       list;
    for (int d = 0; d < dim; ++d)
      list += (d > 0 ? "," : "") + names[d];
    return with_time ? list + ",t" : list;
  }

  template <int dim>
  void
  parse_expressions(FunctionParser<dim>            &function,
                    const std::vector<std::string> &expressions,
                    const bool                      with_time,
                    const SceneReader              &reader,
                    const std::string              &entry,
                    const std::string              &expected)
  {
    std::ostringstream quiet;
    std::streambuf    *cerr = std::cerr.rdbuf(quiet.rdbuf());
    bool               ok   = true;
    try
      {
        function.initialize(coordinate_names(dim, with_time),
                            expressions,
                            {{"pi", numbers::PI}},
                            with_time);
        for (unsigned int c = 0; c < expressions.size(); ++c)
          function.value(Point<dim>(), c);
      }
    catch (...)
      {
        ok = false;
      }
    std::cerr.rdbuf(cerr);
    if (!ok)
      reader.fail(entry, expected);
  }

  template void
  parse_expressions(FunctionParser<2> &,
                    const std::vector<std::string> &,
                    bool,
                    const SceneReader &,
                    const std::string &,
                    const std::string &);
  template void
  parse_expressions(FunctionParser<3> &,
                    const std::vector<std::string> &,
                    bool,
                    const SceneReader &,
                    const std::string &,
                    const std::string &);
} // namespace dealmpm
