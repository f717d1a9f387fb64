#pragma once

#include <string>
#include <vector>

namespace dealmpm
{
  /** A named per-particle field of n_components doubles. */
  struct FieldDescription
  {
    std::string  name;
    unsigned int n_components;
  };

  /**
   * The order of the doubles stored per particle in the particle handler's
   * property pool. Assembled once at start-up from the core fields, the
   * material models in use and the effects listed, so nothing that a scene
   * does not use takes memory. Output names come from the same list.
   */
  class PropertyLayout
  {
  public:
    /** Append a field and return its offset. */
    unsigned int
    add(const std::string &name, const unsigned int n_components);

    /** Offset of a field; throws if the field is not part of the layout. */
    unsigned int
    offset(const std::string &name) const;

    bool
    has(const std::string &name) const;

    /** Doubles per particle. */
    unsigned int
    size() const
    {
      return n_doubles;
    }

    struct Field
    {
      std::string  name;
      unsigned int offset;
      unsigned int n_components;
    };

    const std::vector<Field> &
    fields() const
    {
      return field_list;
    }

  private:
    std::vector<Field> field_list;
    unsigned int       n_doubles = 0;
  };
} // namespace dealmpm
