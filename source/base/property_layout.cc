#include <dealmpm/base/property_layout.h>

#include <stdexcept>

namespace dealmpm
{
  unsigned int
  PropertyLayout::add(const std::string &name, const unsigned int n_components)
  {
    if (has(name))
      throw std::logic_error("particle property '" + name +
                             "' is declared twice");
    field_list.push_back(Field{name, n_doubles, n_components});
    n_doubles += n_components;
    return field_list.back().offset;
  }

  unsigned int
  PropertyLayout::offset(const std::string &name) const
  {
    for (const auto &f : field_list)
      if (f.name == name)
        return f.offset;
    throw std::logic_error("particle property '" + name +
                           "' is not part of this scene's layout");
  }

  bool
  PropertyLayout::has(const std::string &name) const
  {
    for (const auto &f : field_list)
      if (f.name == name)
        return true;
    return false;
  }
} // namespace dealmpm
