#include <dealmpm/schemes/time_stepping.h>

namespace dealmpm
{
  void
  TimeStepping::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time");
    prm.declare_entry("End time",
                      "1",
                      Patterns::Double(),
                      "Simulated time (s), > 0.");
    prm.declare_entry(
      "Time step method",
      "CFL",
      Patterns::Selection("CFL|fixed"),
      "'CFL': dt = CFL number x min over particles of h / (c_p + |v_p|), "
      "recomputed every step; 'fixed': Time step.");
    prm.declare_entry("Time step",
                      "1e-3",
                      Patterns::Double(),
                      "Fixed time step (s), > 0.");
    prm.declare_entry("CFL number",
                      "0.5",
                      Patterns::Double(),
                      "CFL number C, 0 < C <= 1; 0.5 with the default MUSL "
                      "and linear shape functions held every case of the "
                      "defaults study (benchmarks/README.md).");
    prm.declare_entry("Maximum number of steps",
                      "0",
                      Patterns::Integer(0),
                      "Stop after this many steps (0: no limit).");
    prm.leave_subsection();
  }

  TimeStepping
  TimeStepping::read(SceneReader &reader)
  {
    TimeStepping s;
    SectionScope time(reader, "Time");
    s.end_time        = reader.get_positive("End time");
    s.cfl_time_step   = reader.get("Time step method") == "CFL";
    s.fixed_time_step = reader.get_positive("Time step");
    s.cfl_number      = reader.get_double("CFL number");
    if (!(s.cfl_number > 0 && s.cfl_number <= 1))
      reader.fail("CFL number", "a number in (0, 1]");
    s.max_steps = reader.get_integer("Maximum number of steps");
    return s;
  }
} // namespace dealmpm
