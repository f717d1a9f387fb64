#pragma once

#include <dealmpm/effects/effect.h>

#include <string>
#include <utility>
#include <vector>

namespace dealmpm
{
  /**
   * An effect whose forces do work without a potential, accumulated in
   * @p work: it counts in the energy balance, is the statistics column
   * @p column, and is saved with the run. Most effects are one of these.
   */
  template <int dim>
  class EffectWithWork : public Effect<dim>
  {
  public:
    explicit EffectWithWork(std::string column)
      : column(std::move(column))
    {}

    double
    work_done() const override
    {
      return work;
    }

    std::vector<std::pair<std::string, double>>
    statistics_columns() const override
    {
      return {{column, work}};
    }

    std::vector<double>
    saved_state() const override
    {
      return {work};
    }

    void
    restore_state(const std::vector<double> &state) override
    {
      work = state.at(0);
    }

  protected:
    /** Work done so far on this rank's particles. */
    double work = 0;

  private:
    std::string column;
  };
} // namespace dealmpm
