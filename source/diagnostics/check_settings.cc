#include <dealmpm/diagnostics/check_settings.h>

namespace dealmpm
{
  void
  CheckSettings::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Checks");
    prm.declare_entry(
      "Energy growth limit",
      "0.1",
      Patterns::Double(),
      "Stop the run (exit code 3) when the total energy, less the work of "
      "external forces, has grown by more than this fraction of the energy "
      "put in (kinetic and strain energy at the start, work of external "
      "forces, potential energy released): energy a scheme creates. Checked "
      "at every output and every few steps; 0: off.");
    prm.declare_entry(
      "Mass loss limit",
      "0.01",
      Patterns::Double(),
      "Stop the run (exit code 3) when the particles that left the grid "
      "('MPM/Particles leaving the grid = remove') have carried away more "
      "than this fraction of the particles' initial mass; 0: off. Particles "
      "that erosion removes ('Damage') do not count.");
    prm.declare_entry(
      "Memory limit",
      "0",
      Patterns::Double(),
      "GB the run may use (all ranks together); 0: the memory available on "
      "the machines it runs on. A scene whose estimated memory (cells and "
      "particles, printed in the start line) exceeds it is refused before "
      "anything big is made.");
    prm.declare_entry(
      "CFL warning",
      "0.5",
      Patterns::Double(),
      "With a fixed time step: warn once when a particle's CFL number "
      "dt (c_p + |v_p|) / h passes this, in (0, 1]; past 1 the run stops "
      "(exit code 3) and says the largest stable step.");
    prm.leave_subsection();
  }

  CheckSettings
  CheckSettings::read(SceneReader &reader)
  {
    CheckSettings s;
    SectionScope  checks(reader, "Checks");
    s.energy_growth_limit = reader.get_nonnegative("Energy growth limit");
    s.cfl_warning         = reader.get_double("CFL warning");
    s.memory_limit        = reader.get_nonnegative("Memory limit") * 1e9;
    s.mass_loss_limit     = reader.get_nonnegative("Mass loss limit");
    if (s.mass_loss_limit > 1)
      reader.fail("Mass loss limit", "a fraction in [0, 1]");
    if (!(s.cfl_warning > 0 && s.cfl_warning <= 1))
      reader.fail("CFL warning", "a number in (0, 1]");
    return s;
  }
} // namespace dealmpm
