#include "unused_sections.h"

#include <deal.II/base/utilities.h>

#include <dealmpm/base/scene_reader.h>
#include <dealmpm/base/warnings.h>
#include <dealmpm/effects/effect.h>
#include <dealmpm/materials/material.h>

#include <algorithm>
#include <fstream>

#include "../base/parameter_text.h"
#include "run_log.h"

namespace dealmpm
{
  namespace
  {
    /** An entry a scene sets, "Section/Entry", and where: "file: line N"
     * or "command line: -s '...'". */
    struct SetEntry
    {
      std::string path;
      std::string where;
    };

    std::vector<SetEntry>
    entries_set(const std::string              &file,
                const std::vector<std::string> &overrides)
    {
      std::vector<SetEntry> set;
      std::ifstream         in(file);
      std::string           first;
      // A scene as it ran (run.prm) sets every entry on purpose; the run
      // that wrote it warned about those that mattered.
      if (std::getline(in, first) && first.rfind(scene_as_run_mark, 0) == 0)
        in.setstate(std::ios::eofbit);
      else
        in.seekg(0);
      walk_parameter_text(in, true, [&](const ParameterLine &line) {
        if (line.kind == ParameterLine::entry)
          set.push_back({line.section + line.name,
                         file + ": line " + std::to_string(line.number)});
      });
      for (const std::string &item : overrides)
        set.push_back({override_path(item),
                       "command line: -s '" + quote_value(item) + "'"});
      return set;
    }
  } // namespace

  template <int dim>
  void
  warn_unused_sections(const ParameterHandler         &prm,
                       const std::string              &file,
                       const std::vector<std::string> &overrides,
                       const unsigned int              n_materials)
  {
    const std::vector<SetEntry> set        = entries_set(file, overrides);
    const auto                  warn_under = [&](const std::string &section,
                                const std::string &why) {
      for (const SetEntry &entry : set)
        if (entry.path.rfind(section + "/", 0) == 0)
          warn("unused section '" + section + "'",
               entry.where + ": '" + entry.path + "' is set, but " + why);
    };
    const std::vector<std::string> listed =
      Utilities::split_string_list(prm.get("Effects"), ',');
    for (const std::string &name : effect_registry<dim>().names())
      if (std::find(listed.begin(), listed.end(), name) == listed.end())
        warn_under(section_title(name),
                   "'" + name +
                     "' is not in 'Effects': add it there, or the entry "
                     "does nothing");
    for (unsigned int m = 1; m <= n_materials; ++m)
      {
        const std::string material = "Material " + std::to_string(m);
        const std::string model    = prm.get({material}, "Model");
        for (const std::string &name : material_registry<dim>().names())
          if (name != model)
            warn_under(material + "/" + name,
                       "'" + material + "/Model' is '" + model +
                         "': the entry does nothing");
      }
  }

  template void
  warn_unused_sections<2>(const ParameterHandler &,
                          const std::string &,
                          const std::vector<std::string> &,
                          unsigned int);
  template void
  warn_unused_sections<3>(const ParameterHandler &,
                          const std::string &,
                          const std::vector<std::string> &,
                          unsigned int);
} // namespace dealmpm
