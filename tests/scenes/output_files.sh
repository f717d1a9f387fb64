#!/usr/bin/env bash
# The files a user opens: particles.pvd over .pvtu/.vtu with the named fields,
# grid.pvd, statistics.csv with its columns, the particle CSV, the progress
# line and the timing table. The grid at t = 0 already holds the particles'
# mass (summing to their total) and velocity, as one 3-component vector.
here=$(cd "$(dirname "$0")" && pwd)
source "$here/check_lib.sh"
export PYTHONPATH="$here"

"$dealmpm" "$scene" -s "Output/Directory=out" -s "Time/End time=0.1" -s "Output/Interval=0.05" \
  -s "Output/Write grid=true" -s "Output/Particle CSV=true" -s "Output/Progress interval=1e-9" \
  > log.txt 2> err.txt || fail "exit code $?"
for f in particles.pvd grid.pvd steps/particles_00000.pvtu steps/particles_00002.pvtu steps/particles_00002.0.vtu \
         steps/grid_00002.pvtu steps/grid_00002.0.vtu statistics.csv steps/particles_00002.csv run.prm run.log; do
  [ -s "out/$f" ] || fail "missing out/$f"
done
[ "$(grep -c 'DataSet' out/particles.pvd)" = 3 ] || fail "particles.pvd should list 3 outputs"
for field in id body material velocity displacement stress J volume mass stress_work; do
  grep -q "Name=\"$field\"" out/steps/particles_00002.0.vtu || fail "particle field $field missing"
done
for field in nodal_mass nodal_velocity level mpi_rank; do
  grep -q "Name=\"$field\"" out/steps/grid_00002.0.vtu || fail "grid field $field missing"
done
python3 - <<'PY' || fail "grid at t = 0"
import csv, sys
from vtk_files import read_vtu
grid = read_vtu("out/steps/grid_00000.0.vtu")
a = grid["arrays"]
problems = []
if a.get("nodal_velocity", (0, 0))[1] != 3:
    problems.append("nodal_velocity should be one 3-component vector")
# deal.II writes each cell's corners: count every node once.
mass, speed = {}, {}
for i, m in enumerate(a["nodal_mass"][2]):
    key = tuple(round(x, 9) for x in grid["points"][3 * i:3 * i + 3])
    mass[key] = m
    if "nodal_velocity" in a and a["nodal_velocity"][1] == 3:
        speed[key] = tuple(a["nodal_velocity"][2][3 * i:3 * i + 3])
total = float(next(csv.DictReader(open("out/statistics.csv")))["mass"])
if abs(sum(mass.values()) - total) > 1e-5 * total:
    problems.append("nodal mass sums to %g, the particles' to %g" % (sum(mass.values()), total))
# Nodes inside a disk move with it: (0.1, 0.1, 0) and (-0.1, -0.1, 0).
if speed and max(abs(v[0]) for v in speed.values()) < 0.1 * (1 - 1e-5):
    problems.append("nodal velocity at t = 0 should reach 0.1")
for p in problems:
    print("FAIL:", p)
sys.exit(1 if problems else 0)
PY
header="step,time,dt,n_particles,mass,momentum_x,momentum_y,kinetic_energy,strain_energy,gravitational_energy,total_energy,external_work,energy_drift,momentum_drift,mass_loss,min_J,max_cfl,lost_particles,wall_time,particles_per_rank_min,particles_per_rank_max,particles_per_rank_mean"
[ "$(head -1 out/statistics.csv)" = "$header" ] || fail "statistics header: $(head -1 out/statistics.csv)"
[ "$(wc -l < out/statistics.csv)" = 4 ] || fail "statistics.csv should have 3 rows"
[ "$(head -1 out/steps/particles_00002.csv)" = "id,x,y,vx,vy,ux,uy,J,body" ] || fail "particle CSV header"
[ "$(wc -l < out/steps/particles_00002.csv)" = 417 ] || fail "particle CSV should have 416 rows"
grep -Eq "^step +[0-9]+ +t = .* dt = .*% +ETA [0-9]+:[0-9]{2}:[0-9]{2}" log.txt || fail "no progress line"
grep -q "| P2G " log.txt || fail "no timing table"
grep -q "M particle-steps/s" log.txt || fail "no speed line"

finish output
