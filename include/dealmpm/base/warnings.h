#pragma once

#include <string>

namespace dealmpm
{
  /**
   * The run's warnings, on standard error: the first of each kind as one
   * line "dealmpm: warning: <text>", the later ones of that kind only
   * counted, so that a disk leaving the grid over 16 steps says so once.
   * summarize_warnings() at the end of a run says how many more each kind
   * had. Rank 0 prints: call it on every rank with the same text (or on
   * rank 0 alone).
   */
  void
  warn(const std::string &kind, const std::string &text);

  /** One line per kind that repeated: "dealmpm: warning: N more '<kind>'
   * warnings after the first (above)"; then forget every kind. */
  void
  summarize_warnings();
} // namespace dealmpm
