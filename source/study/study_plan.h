#pragma once

#include <dealmpm/study/study.h>

#include <string>
#include <vector>

namespace dealmpm
{
  /** The study file's settings and the runs they make. */
  struct StudyPlan
  {
    std::string  folder, base_scene;
    unsigned int jobs       = 1;
    double       time_limit = 0;
    unsigned int n_bodies   = 1;
    /** Entries set in every run. */
    std::vector<std::string> common;
    std::vector<StudyRun>    runs;
  };

  /** Every run of the plan, up to plan.jobs at once, each a process of
   * @p program; their results go into plan.runs. */
  void
  run_all(StudyPlan &plan, const std::string &program);

  /** The line of a run's stderr that says why it ended, without the
   * program's prefix. */
  std::string
  reason_in(const std::string &file);
} // namespace dealmpm
