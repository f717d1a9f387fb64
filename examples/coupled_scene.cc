// A scene that couples an FEM region to an MPM body, built in C++ instead
// of a .prm file: the parameters are declared for a scene of this shape
// (one body, one material, one FEM region), set one by one, and the
// Simulation runs them. Here an FE bar on [0.1, 0.5] at +v0 meets an MPM
// bar on [0.5, 0.9] at -v0 (E = 100, rho = 1: c = 10, L = 0.4); the
// region's right edge is in frictionless contact with the MPM material.
// They stay in contact for 2 L / c = 0.08 s and part with their
// velocities reversed: the program checks that the region's momentum is
// -m v0 within 10 % at t = 0.12 and that the total stayed zero (exit code
// 1 otherwise). Run: coupled_scene (output in coupled_scene_output/).
#include <deal.II/base/mpi.h>

#include <dealmpm/core/simulation.h>

#include <cmath>
#include <iostream>

using namespace dealmpm;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  SceneShape                       shape;
  shape.dim           = 2;
  shape.n_fem_regions = 1;
  ParameterHandler prm;
  Simulation<2>::declare_parameters(prm, shape);

  const auto in =
    [&prm](const std::string                                      &section,
           const std::vector<std::pair<std::string, std::string>> &entries) {
      prm.enter_subsection(section);
      for (const auto &[entry, value] : entries)
        prm.set(entry, value);
      prm.leave_subsection();
    };
  prm.set("Number of FEM regions", "1");
  in("Grid",
     {{"Upper corner", "1, 0.025"},
      {"Cells", "40, 1"},
      {"Boundary conditions", "2: slip, 3: slip"}});
  in("Material 1", {{"Model", "linear elastic"}, {"Density", "1"}});
  prm.enter_subsection("Material 1");
  in("linear elastic", {{"Young's modulus", "100"}, {"Poisson's ratio", "0"}});
  prm.leave_subsection();
  in("Body 1",
     {{"Lower corner", "0.5, 0"},
      {"Upper corner", "0.9, 0.025"},
      {"Velocity", "-0.01, 0"}});
  in("FEM region 1",
     {{"Lower corner", "0.1, 0"},
      {"Upper corner", "0.5, 0.025"},
      {"Cells", "16, 1"},
      {"Initial velocity", "0.01, 0"},
      {"Contact boundaries", "1: 0"}});
  in("MPM", {{"Stress update", "USL"}});
  in("Time",
     {{"End time", "0.12"},
      {"Time step method", "fixed"},
      {"Time step", "0.001"}});
  in("Output",
     {{"Directory", "coupled_scene_output"},
      {"Interval", "0.01"},
      {"Progress interval", "0"}});

  try
    {
      Simulation<2> simulation(prm, "coupled_scene.cc", shape, MPI_COMM_WORLD);
      simulation.run();
      const double p0       = 0.4 * 0.025 * 0.01; // m v0 of each bar
      const double p_region = simulation.fem_regions()[0].solid->momentum()[0];
      const double p_total  = simulation.statistics().momentum[0];
      if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        std::cout << "coupled_scene: the region's momentum at t = 0.12 is "
                  << p_region / p0 << " m v0 (exact -1 after they part), the "
                  << "total " << p_total / p0 << " m v0 (exact 0)" << std::endl;
      return std::abs(p_region / p0 + 1) < 0.1 &&
                 std::abs(p_total) < 1e-12 * p0 ?
               0 :
               1;
    }
  catch (const std::exception &e)
    {
      std::cerr << "coupled_scene: " << e.what() << std::endl;
      return 1;
    }
}
