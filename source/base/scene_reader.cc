#include <deal.II/base/utilities.h>

#include <dealmpm/base/errors.h>
#include <dealmpm/base/scene_reader.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

namespace dealmpm
{
  std::string
  quote_value(const std::string &value)
  {
    constexpr std::size_t longest = 200;
    if (value.size() <= longest)
      return value;
    return value.substr(0, longest) + "... (" + std::to_string(value.size()) +
           " characters)";
  }

  std::string
  override_path(const std::string &item)
  {
    const auto equal = item.find('=');
    if (equal == std::string::npos)
      return "";
    std::string path;
    for (const auto &part :
         Utilities::split_string_list(item.substr(0, equal), '/'))
      path += (path.empty() ? "" : "/") + part;
    return path;
  }

  SceneReader::SceneReader(ParameterHandler               &prm,
                           const std::string              &file_name,
                           const std::vector<std::string> &overrides)
    : prm(prm)
    , file(file_name)
  {
    for (const auto &item : overrides)
      overridden[override_path(item)] = item;
  }

  void
  SceneReader::enter(const std::string &section)
  {
    prm.enter_subsection(section);
    sections.push_back(section);
  }

  void
  SceneReader::leave()
  {
    prm.leave_subsection();
    sections.pop_back();
  }

  std::string
  SceneReader::path_of(const std::string &entry) const
  {
    std::string path;
    for (const auto &s : sections)
      path += s + "/";
    return path + entry;
  }

  void
  SceneReader::fail(const std::string &entry, const std::string &expected) const
  {
    throw InputError(where(entry) + ": expected " + expected);
  }

  std::string
  SceneReader::where(const std::string &entry) const
  {
    const auto item = overridden.find(path_of(entry));
    if (item != overridden.end())
      return "command line: -s '" + quote_value(item->second) + "'";
    // The entry may fail through others of its section (a body's Shape
    // through its Center): name the command line's overrides there too,
    // which the file does not show.
    std::string       also;
    const std::string section = path_of("");
    for (const auto &[path, item] : overridden)
      if (!section.empty() && path.rfind(section, 0) == 0)
        also += (also.empty() ? " (with the command line's -s '" : ", -s '") +
                quote_value(item) + "'";
    return file + ": entry '" + path_of(entry) + "' = '" +
           quote_value(prm.get(entry)) + "'" + (also.empty() ? "" : also + ")");
  }

  std::string
  SceneReader::get(const std::string &entry) const
  {
    return Utilities::trim(prm.get(entry));
  }

  bool
  SceneReader::get_bool(const std::string &entry) const
  {
    return prm.get_bool(entry);
  }

  double
  SceneReader::get_double(const std::string &entry) const
  {
    const std::string text = get(entry);
    try
      {
        const double value = Utilities::string_to_double(text);
        if (!std::isfinite(value))
          fail(entry, "a finite number");
        return value;
      }
    catch (const InputError &)
      {
        throw;
      }
    catch (...)
      {
        fail(entry, "a number");
      }
  }

  double
  SceneReader::get_positive(const std::string &entry) const
  {
    const double value = get_double(entry);
    if (!(value > 0))
      fail(entry, "a positive number");
    return value;
  }

  double
  SceneReader::get_nonnegative(const std::string &entry) const
  {
    const double value = get_double(entry);
    if (!(value >= 0))
      fail(entry, "a number >= 0");
    return value;
  }

  double
  SceneReader::get_in_open_range(const std::string &entry,
                                 const double       lower,
                                 const double       upper) const
  {
    const double value = get_double(entry);
    if (!(value > lower && value < upper))
      fail(entry,
           "a number strictly between " + Utilities::to_string(lower) +
             " and " + Utilities::to_string(upper));
    return value;
  }

  long
  SceneReader::get_integer(const std::string &entry) const
  {
    try
      {
        return Utilities::string_to_int(get(entry));
      }
    catch (...)
      {
        fail(entry, "an integer");
      }
  }

  std::string
  SceneReader::get_file(const std::string &entry,
                        const std::string &expected) const
  {
    std::filesystem::path       path(get(entry));
    const std::filesystem::path folder =
      std::filesystem::path(file).parent_path();
    if (!path.empty() && path.is_relative() && !folder.empty())
      path = folder / path;
    if (path.empty() || !std::ifstream(path))
      fail(entry, expected);
    return path.string();
  }

  std::vector<double>
  SceneReader::get_doubles(const std::string &entry) const
  {
    std::vector<double> values;
    for (const auto &item : Utilities::split_string_list(get(entry), ','))
      {
        try
          {
            values.push_back(Utilities::string_to_double(item));
          }
        catch (...)
          {
            fail(entry, "a comma-separated list of numbers");
          }
        if (!std::isfinite(values.back()))
          fail(entry, "finite numbers");
      }
    return values;
  }

  std::map<unsigned int, std::string>
  SceneReader::get_id_map(const std::string &entry,
                          const std::string &value_expected) const
  {
    const std::string expected =
      "a list of 'id: value' pairs, each id once (id a boundary id, value " +
      value_expected + ")";
    std::map<unsigned int, std::string> map;
    for (const auto &item : Utilities::split_string_list(get(entry), ','))
      {
        const auto parts = Utilities::split_string_list(item, ':');
        long       id    = -1;
        try
          {
            if (parts.size() == 2 && !parts[1].empty())
              id = Utilities::string_to_int(parts[0]);
          }
        catch (...)
          {}
        if (id < 0 ||
            id >= static_cast<long>(numbers::internal_face_boundary_id) ||
            map.count(id) > 0)
          fail(entry, expected);
        map[id] = parts[1];
      }
    return map;
  }

  std::map<unsigned int, double>
  SceneReader::get_id_nonnegatives(const std::string &entry) const
  {
    return id_values(entry, "a number >= 0", true);
  }

  std::map<unsigned int, double>
  SceneReader::get_id_numbers(const std::string &entry,
                              const std::string &unit) const
  {
    return id_values(entry, "a number (" + unit + ")", false);
  }

  std::map<unsigned int, double>
  SceneReader::id_values(const std::string &entry,
                         const std::string &expected,
                         const bool         nonnegative) const
  {
    std::map<unsigned int, double> map;
    for (const auto &[id, text] : get_id_map(entry, expected))
      {
        double value = std::numeric_limits<double>::quiet_NaN();
        try
          {
            value = Utilities::string_to_double(text);
          }
        catch (...)
          {}
        if (!std::isfinite(value) || (nonnegative && !(value >= 0.)))
          fail(entry,
               "a list of 'id: value' pairs, each id once (id a boundary "
               "id, value " +
                 expected + ")");
        map[id] = value;
      }
    return map;
  }

  template <int dim>
  Point<dim>
  SceneReader::get_point(const std::string &entry) const
  {
    const std::vector<double> values = get_doubles(entry);
    if (values.size() != dim)
      fail(entry,
           std::to_string(dim) + " comma-separated numbers (Dimension = " +
             std::to_string(dim) + ")");
    Point<dim> p;
    for (unsigned int d = 0; d < dim; ++d)
      p[d] = values[d];
    return p;
  }

  template <int dim>
  std::string
  repeat_value(const std::string &value)
  {
    std::string text = value;
    for (unsigned int d = 1; d < dim; ++d)
      text += ", " + value;
    return text;
  }

#define DEALMPM_INSTANTIATE(dim)                                               \
  template Point<dim>  SceneReader::get_point<dim>(const std::string &) const; \
  template std::string repeat_value<dim>(const std::string &);
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
