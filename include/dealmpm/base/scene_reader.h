#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <map>
#include <string>
#include <vector>

namespace dealmpm
{
  using namespace dealii;

  /**
   * Reads typed, range-checked values out of a parsed ParameterHandler. Every
   * failure becomes an InputError of one line naming the scene file, the full
   * entry path and what was expected, so that bad input never gets past
   * set-up.
   */
  class SceneReader
  {
  public:
    /** @p overrides: the command line's "Section/Entry=value" items, so
     * that a bad value set there is blamed on the command line. */
    SceneReader(ParameterHandler               &prm,
                const std::string              &file_name,
                const std::vector<std::string> &overrides = {});

    /** Enter a subsection; pair with leave(). */
    void
    enter(const std::string &section);
    void
    leave();

    std::string
    get(const std::string &entry) const;
    bool
    get_bool(const std::string &entry) const;
    double
    get_double(const std::string &entry) const;
    double
    get_positive(const std::string &entry) const;
    double
    get_nonnegative(const std::string &entry) const;
    /** A value in the open interval (lower, upper). */
    double
    get_in_open_range(const std::string &entry,
                      const double       lower,
                      const double       upper) const;
    long
    get_integer(const std::string &entry) const;
    std::vector<double>
    get_doubles(const std::string &entry) const;

    /** The path of a file named by an entry, relative to the scene file's
     * folder unless absolute; fails unless the file can be opened. */
    std::string
    get_file(const std::string &entry, const std::string &expected) const;

    /** A list of 'id: value' pairs (boundary ids), each id once; @p
     * value_expected says what a value must be, for the message. */
    std::map<unsigned int, std::string>
    get_id_map(const std::string &entry,
               const std::string &value_expected) const;

    /** get_id_map() with values that are numbers >= 0. */
    std::map<unsigned int, double>
    get_id_nonnegatives(const std::string &entry) const;
    /** get_id_map() with values that are finite numbers (@p unit for
     * the message). */
    std::map<unsigned int, double>
    get_id_numbers(const std::string &entry, const std::string &unit) const;

    /** Exactly dim comma-separated numbers. */
    template <int dim>
    Point<dim>
    get_point(const std::string &entry) const;

    template <int dim>
    Tensor<1, dim>
    get_vector(const std::string &entry) const
    {
      return get_point<dim>(entry);
    }

    /** Throw an InputError about this entry. */
    [[noreturn]] void
    fail(const std::string &entry, const std::string &expected) const;

    /** Where this entry was given, as fail() names it: "file: entry
     * 'Section/entry' = 'value'" or "command line: -s '...'" (for an
     * error found after the scene is read). */
    std::string
    where(const std::string &entry) const;

    const std::string &
    file_name() const
    {
      return file;
    }

    ParameterHandler &
    handler() const
    {
      return prm;
    }

    /** "Section/Subsection/entry" for messages. */
    std::string
    path_of(const std::string &entry) const;

  private:
    /** get_id_map() with finite numbers (>= 0 if @p nonnegative). */
    std::map<unsigned int, double>
    id_values(const std::string &entry,
              const std::string &expected,
              const bool         nonnegative) const;

    ParameterHandler                  &prm;
    std::string                        file;
    std::vector<std::string>           sections;
    std::map<std::string, std::string> overridden; ///< path -> "-s" item
  };

  /** A value as quoted in a message: cut after 200 characters. */
  std::string
  quote_value(const std::string &value);

  /** "Section/Entry" of a "Section/Entry=value" override, spaces around
   * the parts trimmed ("" when it has no '='). */
  std::string
  override_path(const std::string &item);

  /** RAII guard for SceneReader::enter/leave. */
  class SectionScope
  {
  public:
    SectionScope(SceneReader &reader, const std::string &section)
      : reader(reader)
    {
      reader.enter(section);
    }
    ~SectionScope()
    {
      reader.leave();
    }

  private:
    SceneReader &reader;
  };

  /** "x, y" or "x, y, z" with dim entries, for default values. */
  template <int dim>
  std::string
  repeat_value(const std::string &value);
} // namespace dealmpm
