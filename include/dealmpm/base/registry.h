#pragma once

#include <deal.II/base/parameter_handler.h>

#include <dealmpm/base/scene_reader.h>

#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace dealmpm
{
  /**
   * Name -> factory table for the things a scene selects by name (material
   * models, effects). Each entry declares its own parameters in a subsection
   * and builds itself from them, so user code can add models from outside the
   * library (see examples/) and the help text lists every registered name.
   * @p Signature: what create() takes (shape functions and boundary
   * conditions have no parameters and take nothing).
   */
  template <typename Product,
            typename Signature = std::unique_ptr<Product>(SceneReader &)>
  class Registry
  {
  public:
    using Declare = std::function<void(ParameterHandler &)>;
    using Create  = std::function<Signature>;

    struct Entry
    {
      std::string name;
      std::string description;
      Declare     declare;
      Create      create;
    };

    /** Register a name; a second registration of the same name replaces the
     * first, so that user code can override a built-in model. */
    void
    add(const std::string &name,
        const std::string &description,
        const Declare     &declare,
        const Create      &create)
    {
      entries[name] = Entry{name, description, declare, create};
    }

    /** Register a name whose product has no parameters. */
    void
    add(const std::string &name,
        const std::string &description,
        const Create      &create)
    {
      add(
        name, description, [](ParameterHandler &) {}, create);
    }

    bool
    has(const std::string &name) const
    {
      return entries.count(name) > 0;
    }

    const Entry &
    get(const std::string &name) const
    {
      const auto it = entries.find(name);
      if (it == entries.end())
        throw std::out_of_range("'" + name + "' is not registered");
      return it->second;
    }

    std::vector<std::string>
    names() const
    {
      std::vector<std::string> result;
      for (const auto &e : entries)
        result.push_back(e.first);
      return result;
    }

    /** "a|b|c", for Patterns::Selection and Patterns::MultipleSelection. */
    std::string
    pattern() const
    {
      std::string result;
      for (const auto &e : entries)
        result += (result.empty() ? "" : "|") + e.first;
      return result;
    }

    /** "a: what a is. b: what b is." for documentation strings. */
    std::string
    describe() const
    {
      std::string result;
      for (const auto &e : entries)
        result += "'" + e.first + "': " + e.second.description + " ";
      return result;
    }

  private:
    std::map<std::string, Entry> entries;
  };
} // namespace dealmpm
