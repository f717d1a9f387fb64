#!/usr/bin/env bash
# Bad input: one line on stderr naming the file/entry and what was expected,
# exit code 2 (1 for a bad command line), and nothing written.
source "$(dirname "$0")/check_lib.sh"

expect() { # expected_code regex args...
  local code=$1 regex=$2; shift 2
  "$dealmpm" "$@" > out.txt 2> err.txt
  local got=$?
  local lines; lines=$(wc -l < err.txt)
  if [ "$got" != "$code" ] || ! grep -Eq "$regex" err.txt || { [ "$code" = 2 ] && [ "$lines" != 1 ]; } || [ -e output ]; then
    echo "FAIL: dealmpm $* -> exit $got (expected $code), stderr:"; cat err.txt
    [ -e output ] && echo "  and it wrote output/"
    failures=$((failures + 1))
  else
    echo "ok: $(head -c 200 err.txt | head -1)"
  fi
  rm -rf output
}

s=(-s "Output/Directory=output")
expect 2 "cannot open the scene file" missing.prm
printf 'set Dimension = 2\nset Frobnicate = 3\n' > unknown.prm
expect 2 "unknown.prm.*Frobnicate" unknown.prm
printf 'set Dimension = 2\nsubsection Time\n  set End time = soon\nend\n' > malformed.prm
expect 2 "malformed.prm.*Time/End time.*expected a number" malformed.prm
expect 2 "Material 1/Density.*expected a positive number" "$scene" "${s[@]}" -s "Material 1/Density=-1000"
expect 2 "Poisson's ratio.*strictly between -1 and 0.5" "$scene" "${s[@]}" -s "Material 1/linear elastic/Poisson's ratio=0.5"
expect 2 "Time/Time step.*expected a positive number" "$scene" "${s[@]}" -s "Time/Time step=0"
expect 2 "Time/Time step.*expected a positive number" "$scene" "${s[@]}" -s "Time/Time step=-1e-3"
expect 2 "Grid/Cells.*expected positive integers" "$scene" "${s[@]}" -s "Grid/Cells=0, 20"
expect 2 "Grid/Cells.*expected 2 positive integers" "$scene" "${s[@]}" -s "Grid/Cells=20"
# The override that moved the body is named, not only the file's Shape.
expect 2 "Body 1/Shape' = 'ball' \(with the command line's -s 'Body 1/Center=3, 3'\): expected a body inside the grid" "$scene" "${s[@]}" -s "Body 1/Center=3, 3"
expect 2 "Grid/Mesh file.*readable Gmsh" "$scene" "${s[@]}" -s "Grid/Type=mesh file" -s "Grid/Mesh file=nowhere.msh"
expect 2 "Body 1/Material.*material number from 1 to" "$scene" "${s[@]}" -s "Body 1/Material=3"
expect 2 "Effects.*comma-separated list of" "$scene" "${s[@]}" -s "Effects=gravity, antigravity"
expect 2 "command line: -s 'Grid/Colour=red'" "$scene" "${s[@]}" -s "Grid/Colour=red"
expect 1 "unknown option" "$scene" --frobnicate
# Modified Cam-Clay's compression line must be steeper than its swelling
# lines, and a soil cannot be less than normally consolidated.
expect 2 "Material 1/Modified Cam-Clay/Compression index.*a number > the Swelling index" "$scene" "${s[@]}" \
  -s "Material 1/Model=Modified Cam-Clay" -s "Material 1/Modified Cam-Clay/Compression index=0.01"
expect 2 "Material 1/Mohr-Coulomb/Residual cohesion.*at most the Cohesion" "$scene" "${s[@]}" \
  -s "Material 1/Model=Mohr-Coulomb" -s "Material 1/Mohr-Coulomb/Softening strain=0.1" \
  -s "Material 1/Mohr-Coulomb/Residual cohesion=1e9"
mc=(-s "Material 1/Model=Mohr-Coulomb" -s "Material 1/Mohr-Coulomb/Regularisation length=0.01")
expect 2 "Material 1/Mohr-Coulomb/Regularisation length.*0 without a Softening strain" "$scene" "${s[@]}" "${mc[@]}"
expect 2 "Material 1/Mohr-Coulomb/Regularisation length.*0 with adaptivity" "$scene" "${s[@]}" "${mc[@]}" \
  -s "Material 1/Mohr-Coulomb/Softening strain=0.1" -s "Material 1/Mohr-Coulomb/Residual friction angle=20" \
  -s "Adaptivity/Criteria=particles"
expect 2 "Material 2/Mohr-Coulomb/Regularisation length.*0 in a material an FEM region uses \('FEM region 1'" \
  "$(dirname "$scene")/projectile_fem_plate.prm" "${s[@]}" -s "Material 2/Model=Mohr-Coulomb" \
  -s "Material 2/Mohr-Coulomb/Regularisation length=0.01" -s "Material 2/Mohr-Coulomb/Softening strain=0.1" \
  -s "Material 2/Mohr-Coulomb/Residual friction angle=20"
expect 2 "Material 1/Modified Cam-Clay/Overconsolidation ratio.*a number >= 1" "$scene" "${s[@]}" \
  -s "Material 1/Model=Modified Cam-Clay" -s "Material 1/Modified Cam-Clay/Overconsolidation ratio=0.5"
# A model only the example registers: plain dealmpm names the entry and the models it knows.
expect 2 "custom_material.prm: entry 'Material 1/Model' = 'Saint Venant-Kirchhoff': expected one of .*'linear elastic', 'neo-Hookean'$" \
  "$(dirname "$scene")/../examples/custom_material.prm"

data="$(dirname "$scene")/../tests/data"
expect 2 "Grid/Mesh file.*quadrilaterals \(2D\) or hexahedra \(3D\), not triangles" "$scene" "${s[@]}" \
  -s "Grid/Type=mesh file" -s "Grid/Mesh file=$data/triangles.msh"
# A known motion's body force is computed for its own neo-Hookean constants:
# a scene whose material differs would report wrong errors, so it is refused.
ms="$(dirname "$scene")/manufactured_solution_2d.prm"
expect 2 "Manufactured solution/Young's modulus.*Material 1's Young's modulus \(20000\)" "$ms" "${s[@]}" \
  -s "Material 1/neo-Hookean/Young's modulus=2e4"
expect 2 "Manufactured solution/Young's modulus.*neo-Hookean \(Material 1 is 'linear elastic'\)" "$ms" "${s[@]}" \
  -s "Material 1/Model=linear elastic"
# Kernels that need a kind of grid say which, and what to use instead.
expect 2 "MPM/Shape function.*B-spline needs a grid without hanging nodes" "$scene" "${s[@]}" \
  -s "MPM/Shape function=quadratic B-spline" -s "Grid/Local refinement/Levels=1" \
  -s "Grid/Local refinement/Lower corner=-0.25, -0.5" -s "Grid/Local refinement/Upper corner=0.25, 0.5"
expect 2 "MPM/Shape function.*GIMP needs cells that are axis-aligned boxes" "$scene" "${s[@]}" \
  -s "MPM/Shape function=cpGIMP" -s "Grid/Type=mesh file" -s "Grid/Mesh file=$data/distorted_square.msh"
expect 2 "MPM/Shape function.*B-spline needs cells that are axis-aligned boxes" "$scene" "${s[@]}" \
  -s "MPM/Shape function=quadratic B-spline" -s "Grid/Type=mesh file" -s "Grid/Mesh file=$data/kinked_square.msh"
expect 2 "Body 1/Vertices.*three or more corners" "$scene" "${s[@]}" -s "Body 1/Shape=polygon" -s "Body 1/Vertices=0.1, 0.1; 0.5, 0.5"
expect 2 "Body 1/Vertices.*edge 1 meets edge 3" "$scene" "${s[@]}" -s "Body 1/Shape=polygon" \
  -s "Body 1/Vertices=0.1, 0.1; 0.5, 0.5; 0.5, 0.1; 0.1, 0.5"
expect 2 "Body 1/Mesh file.*quadrilaterals" "$scene" "${s[@]}" -s "Body 1/Shape=mesh" -s "Body 1/Mesh file=$data/triangles.msh"
expect 2 "Grid/Boundary conditions.*boundary ids the grid has \(0, 1, 2, 3\), not 4" "$scene" "${s[@]}" \
  -s "Grid/Boundary conditions=0: slip, 4: no-slip"
expect 2 "Grid/Global refinements.*at most 2e9" "$scene" "${s[@]}" -s "Grid/Cells=1000, 1000" -s "Grid/Global refinements=12"
# Counts without a common power of two make every cell a coarse cell.
expect 2 "Grid/Cells.*share a power of two.*400040001 coarse cells \(at most 2e8\)" "$scene" "${s[@]}" -s "Grid/Cells=20001, 20001"
expect 2 "Grid/Most coarse cells.*'auto' or a number >= 1" "$scene" "${s[@]}" -s "Grid/Most coarse cells=many"
expect 2 "Grid/Most coarse cells.*'auto' or a number >= 1" "$scene" "${s[@]}" -s "Grid/Most coarse cells=0.5"
expect 2 "command line: -s '=1': expected 'Section/Entry=value'" "$scene" -s "=1"
expect 2 "command line: -s 'Grid/=1'" "$scene" -s "Grid/=1"
# A scene that sets nothing would run a built-in default: refused.
: > empty.prm
expect 2 "empty.prm: the scene sets nothing" empty.prm
printf '# only a comment\n\n   # and another\n' > comments.prm
expect 2 "comments.prm: the scene sets nothing" comments.prm
# More Body sections than 'Number of bodies': the extra section by name.
sed 's/^set Number of bodies *= 2/set Number of bodies = 1/' "$scene" > extra_body.prm
expect 2 "extra_body.prm: line [0-9]+: section 'Body 2' but 'Number of bodies' = 1" extra_body.prm
# A bad value given with -s is blamed on the command line, not the file.
expect 2 "^dealmpm: error: command line: -s 'Time/End time=-1': expected a positive number" \
  "$scene" "${s[@]}" -s "Time/End time=-1"
# Long values are cut in the message (a 1 MB value was echoed in full).
long=$(head -c 3000 /dev/zero | tr '\0' x)
expect 2 "Time/End time=x+\.\.\. \(3014 characters\)': expected a number" \
  "$scene" "${s[@]}" -s "Time/End time=$long"
[ "$(wc -c < err.txt)" -lt 600 ] || fail "a long -s value is echoed at length ($(wc -c < err.txt) bytes)"
sed "s/set End time *= 3.5/set End time = $long/" "$scene" > long.prm
expect 2 "long.prm: entry 'Time/End time' = 'x{200}\.\.\. \(3000 characters\)'" long.prm "${s[@]}"
expect 2 "Time/Time step method=x+\.\.\. \(3022 characters\)': expected one of 'CFL', 'fixed'$" "$scene" "${s[@]}" \
  -s "Time/Time step method=$long"
# Overlapping bodies would be filled twice.
expect 2 "Body 2/Allow overlap.*does not overlap 'Body 1'" "$scene" "${s[@]}" -s "Body 2/Center=-0.2, -0.2"
# A scene too big for the machine is refused before the grid is made.
expect 2 "the scene needs about [0-9.]+ GB \(1e\+08 cells, .* particles\), more than the" \
  "$scene" "${s[@]}" -s "Grid/Cells=10000, 10000"
expect 2 "more than the 0.1 GB of 'Checks/Memory limit'" "$scene" "${s[@]}" -s "Grid/Cells=400, 400" \
  -s "Checks/Memory limit=0.1"
# Adaptivity refines where the bodies are before the first step and fills
# them there: 4^6 times the particles (the estimate counted the Cells'
# particles only before 2026-11-30, 0.15 GB, and let this run start).
expect 2 "needs about [0-9.]+ GB \([0-9.e+]+ cells, [0-9.]+e\+06 particles\), more than the 0.5 GB" \
  "$scene" "${s[@]}" -s "Adaptivity/Criteria=particles" -s "Adaptivity/Maximum level=6" \
  -s "Checks/Memory limit=0.5" -s "Time/Maximum number of steps=1"
expect 2 "Checks/Energy growth limit.*expected a number >= 0" "$scene" "${s[@]}" -s "Checks/Energy growth limit=-1"
expect 2 "Checks/CFL warning.*expected a number in \(0, 1\]" "$scene" "${s[@]}" -s "Checks/CFL warning=2"
# Total Lagrangian cannot follow what separates, flows or meets.
expect 2 "MPM/Formulation.total Lagrangian.: expected 'updated Lagrangian' for bodies that start apart: bodies 1 and 2 share no grid node" \
  "$scene" "${s[@]}" -s "MPM/Formulation=total Lagrangian"
expect 2 "MPM/Formulation.total Lagrangian.: expected 'updated Lagrangian' for a scene with a fluid \('Material 1' is a 'Tait fluid'" \
  "$(dirname "$scene")/hard-cases/dam_break.prm" "${s[@]}" -s "MPM/Formulation=total Lagrangian"
# Geostatic stress needs gravity, and K0 a number or 'elastic'.
expect 2 "Body 1/Initial stress.*expected 'none' in a scene without gravity" \
  "$scene" "${s[@]}" -s "Body 1/Initial stress=geostatic"
expect 2 "Body 1/K0.*expected 'elastic' or a number >= 0" "$scene" "${s[@]}" -s "Body 1/K0=-0.5"
expect 2 "Body 1/Initial stress.*expected 'none' under 'MPM/Formulation = total Lagrangian'" \
  "$(dirname "$scene")/elastic_column_2d.prm" "${s[@]}" -s "Body 1/Initial stress=geostatic" \
  -s "MPM/Formulation=total Lagrangian"
# Newmark needs MUSL and FLIP, and its parameters in their ranges.
n=(-s "MPM/Particle update=Newmark")
expect 2 "MPM/Stress update.*expected 'MUSL' with 'Particle update = Newmark'" \
  "$scene" "${s[@]}" "${n[@]}" -s "MPM/Stress update=USL"
expect 2 "MPM/Velocity update.*expected 'FLIP' with 'Particle update = Newmark'" \
  "$scene" "${s[@]}" "${n[@]}" -s "MPM/Velocity update=APIC"
expect 2 "MPM/Newmark gamma.*expected a number in \[0.5, 1\]" \
  "$scene" "${s[@]}" "${n[@]}" -s "MPM/Newmark gamma=0.4"
expect 2 "MPM/Newmark beta.*expected a number in \[0, 0.5\]" \
  "$scene" "${s[@]}" "${n[@]}" -s "MPM/Newmark beta=-0.1"
# Wall friction: ids the grid has, on slip walls, as 'id: mu' pairs; contact:
# pairs of existing bodies, and only with the updated-Lagrangian explicit
# update, which give each body its own nodal fields; a gravity ramp >= 0.
f=(-s "Effects=boundary friction")
expect 2 "Boundary friction/Coefficients.*expected boundary ids the grid has \(0, 1, 2, 3\), not 7" \
  "$scene" "${s[@]}" "${f[@]}" -s "Boundary friction/Coefficients=7: 0.3"
expect 2 "Boundary friction/Coefficients.*expected ids whose 'Grid/Boundary conditions' is 'slip' \(id 2 is 'free'\)" \
  "$scene" "${s[@]}" "${f[@]}" -s "Boundary friction/Coefficients=2: 0.3"
expect 2 "Boundary friction/Coefficients.*expected a list of 'id: value' pairs" \
  "$scene" "${s[@]}" "${f[@]}" -s "Boundary friction/Coefficients=2 0.3"
c=(-s "Effects=frictional contact")
expect 2 "Pair friction coefficients.*expected pairs of body numbers from 1 to 2 \('Number of bodies'\), not 3" \
  "$scene" "${s[@]}" "${c[@]}" -s "Frictional contact/Pair friction coefficients=1 3: 0.2"
expect 2 "Pair friction coefficients.*expected a list of 'b c: mu' items" \
  "$scene" "${s[@]}" "${c[@]}" -s "Frictional contact/Pair friction coefficients=1 2: -1"
expect 2 "MPM/Formulation.*expected 'updated Lagrangian' with 'frictional contact'" \
  "$scene" "${s[@]}" "${c[@]}" -s "MPM/Formulation=total Lagrangian"
expect 2 "MPM/Particle update.*expected 'explicit' with 'frictional contact'" \
  "$scene" "${s[@]}" "${c[@]}" -s "MPM/Particle update=Newmark"
expect 2 "Gravity/Ramp time.*expected a number >= 0" \
  "$scene" "${s[@]}" -s "Effects=gravity" -s "Gravity/Ramp time=-1"
expect 2 "Rotating frame/Angular velocity.*expected a rotation that is not zero" \
  "$scene" "${s[@]}" -s "Effects=rotating frame"
# Dashpots only on free faces, and not with contact (each body's own
# velocity would not see them); surface loads: bodies that exist, parsable
# expressions, a load curve with increasing times.
a=(-s "Absorbing boundary/Boundary ids=1" -s "Absorbing boundary/Density=1000" -s "Absorbing boundary/P-wave speed=100")
expect 2 "Absorbing boundary/Boundary ids.*expected ids without a velocity condition \(id 1 is 'slip'" \
  "$scene" "${s[@]}" "${a[@]}" -s "Effects=absorbing boundary" -s "Grid/Boundary conditions=1: slip"
expect 2 "Effects.*expected 'frictional contact' without 'absorbing boundary'" \
  "$scene" "${s[@]}" "${a[@]}" -s "Effects=frictional contact, absorbing boundary"
b=(-s "Effects=base shaking" -s "Base shaking/Boundary ids=2" -s "Base shaking/Load curve=0: 0, 1: 1")
expect 2 "Base shaking/Boundary ids.*expected ids without a velocity condition \(id 2 is 'slip'" \
  "$scene" "${s[@]}" "${b[@]}" -s "Grid/Boundary conditions=2: slip"
expect 2 "Base shaking/Density.*expected a positive number" \
  "$scene" "${s[@]}" "${b[@]}" -s "Base shaking/Base=compliant"
expect 2 "Base shaking/Load curve.*expected the record" \
  "$scene" "${s[@]}" -s "Effects=base shaking" -s "Base shaking/Boundary ids=2"
expect 2 "Base shaking/Boundary ids.*expected at least one boundary id, here or in an FEM region's 'Shaken boundaries'" \
  "$scene" "${s[@]}" -s "Effects=base shaking" -s "Base shaking/Load curve=0: 0, 1: 1"
expect 2 "Effects.*expected 'frictional contact' without 'base shaking'" \
  "$scene" "${s[@]}" "${b[@]}" -s "Effects=frictional contact, base shaking"
t=(-s "Effects=traction")
expect 2 "Traction/Bodies.*expected at least one body" "$scene" "${s[@]}" "${t[@]}"
expect 2 "Traction/Bodies.*expected body numbers from 1 to the scene's 'Number of bodies' \(2\), not 3" \
  "$scene" "${s[@]}" "${t[@]}" -s "Traction/Bodies=3"
expect 2 "Traction/Pressure.*expected an expression of x,y,t" \
  "$scene" "${s[@]}" "${t[@]}" -s "Traction/Bodies=1" -s "Traction/Pressure=1e4*(t"
expect 2 "Traction/Traction.*expected 2 expressions separated by ';'" \
  "$scene" "${s[@]}" "${t[@]}" -s "Traction/Bodies=1" -s "Traction/Traction=0; 0; 1"
expect 2 "Traction/Load curve.*expected a table 'time: factor" \
  "$scene" "${s[@]}" "${t[@]}" -s "Traction/Bodies=1" -s "Traction/Load curve=0: 0, 0: 1"
expect 2 "Traction/Face normal.*expected the outward normal of the loaded face.*faces facing -x \(.*\), \+x .*\+y" \
  "$scene" "${s[@]}" "${t[@]}" -s "Traction/Bodies=1" -s "Traction/Surface selection=y > -0.3"
expect 2 "Traction/Face normal.*expected a nonzero vector, 'all' or nothing" \
  "$scene" "${s[@]}" "${t[@]}" -s "Traction/Bodies=1" -s "Traction/Face normal=0, 0"
expect 2 "Traction/Face normal.*expected" \
  "$scene" "${s[@]}" "${t[@]}" -s "Traction/Bodies=1" -s "Traction/Face normal=0, 0, 1"
expect 2 "Traction/Face normal.*the 'Surface selection' holds no surface particle" \
  "$scene" "${s[@]}" "${t[@]}" -s "Traction/Bodies=1" -s "Traction/Surface selection=x > 100"
r=(-s "Effects=rigid body")
expect 2 "Rigid body/Upper corner.*expected a point above 'Lower corner'" "$scene" "${s[@]}" "${r[@]}"
expect 2 "Rigid body/Normal.*expected a direction that is not zero" \
  "$scene" "${s[@]}" "${r[@]}" -s "Rigid body/Shape=half-space"
expect 2 "Rigid body/Velocity.*expected 2 expressions of t separated by ';'" \
  "$scene" "${s[@]}" "${r[@]}" -s "Rigid body/Shape=cylinder" -s "Rigid body/Radius=0.1" -s "Rigid body/Velocity=sin(t)"
d=(-s "Effects=damage")
expect 2 "Damage/Materials.*expected material numbers from 1 to the scene's 'Number of materials' \\(1\\), not 3" \
  "$scene" "${s[@]}" "${d[@]}" -s "Damage/Materials=3"
expect 2 "Damage/Failure.*expected a value >= 'Onset'" \
  "$scene" "${s[@]}" "${d[@]}" -s "Damage/Onset=0.2" -s "Damage/Failure=0.1"
expect 2 "Damage/Onset.*expected a strain > 0" \
  "$scene" "${s[@]}" "${d[@]}" -s "Damage/Onset=0"
adapt=(-s "Adaptivity/Criteria=particles")
expect 2 "Adaptivity/Criteria.*expected none with 'MPM/Shape function = quadratic B-spline'" \
  "$scene" "${s[@]}" "${adapt[@]}" -s "MPM/Shape function=quadratic B-spline"
expect 2 "Adaptivity/Criteria.*expected none under 'MPM/Formulation = total Lagrangian'" \
  "$scene" "${s[@]}" "${adapt[@]}" -s "MPM/Formulation=total Lagrangian"
expect 2 "Adaptivity/Split particles.*expected false with 'traction'" \
  "$scene" "${s[@]}" "${adapt[@]}" "${t[@]}" -s "Traction/Bodies=1"
expect 2 "Adaptivity/Maximum level.*expected a level at least 'Minimum level'" \
  "$scene" "${s[@]}" "${adapt[@]}" -s "Adaptivity/Minimum level=2" -s "Adaptivity/Maximum level=1"
expect 2 "Adaptivity/Velocity jump/Coarsen fraction.*expected a number below Refine fraction" \
  "$scene" "${s[@]}" -s "Adaptivity/Criteria=velocity jump" -s "Adaptivity/Velocity jump/Coarsen fraction=0.5"
expect 2 "Adaptivity/Criteria.*expected a comma-separated list of" "$scene" "${s[@]}" -s "Adaptivity/Criteria=particles, everywhere"
# FEM regions (issue 15): each mistake named by its entry.
fem="$(dirname "$scene")/bonded_bar.prm"
big=(-s "Grid/Upper corner=1.2, 1.2" -s "Grid/Cells=48, 48" -s "FEM region 1/Type=mesh file"
  -s "FEM region 1/Bonded boundaries=" -s "FEM region 1/Fixed boundaries=")
expect 2 "FEM region 1/Mesh file.*without inverted or twisted cells" "$fem" "${s[@]}" "${big[@]}" \
  -s "FEM region 1/Mesh file=$data/twisted_square.msh"
expect 2 "FEM region 1/Mesh file.*quadrilaterals \(2D\) or hexahedra \(3D\), not triangles" "$fem" "${s[@]}" \
  "${big[@]}" -s "FEM region 1/Mesh file=$data/triangles.msh"
expect 2 "FEM region 1/Upper corner.*inside the background grid" "$fem" "${s[@]}" \
  -s "FEM region 1/Upper corner=1.5, 0.025"
expect 2 "FEM region 1/Bonded boundaries.*boundary ids of the region's mesh \(0, 1, 2, 3\), not 7" "$fem" "${s[@]}" \
  -s "FEM region 1/Bonded boundaries=7: 1"
expect 2 "FEM region 1/Bonded boundaries.*bodies from 1 to 1" "$fem" "${s[@]}" \
  -s "FEM region 1/Bonded boundaries=1: 2"
expect 2 "FEM region 1/Bonded boundaries.*node spacing \(0.025 m here\) is at most the background cells' size" \
  "$fem" "${s[@]}" -s "Grid/Cells=48, 2"
expect 2 "FEM region 1/Bonded boundaries.*'MPM/Stress update = USL'" "$fem" "${s[@]}" -s "MPM/Stress update=MUSL"
expect 2 "FEM region 1/Material.*'Material N' section, 1 to 1" "$fem" "${s[@]}" -s "FEM region 1/Material=2"
expect 2 "FEM region 1/Traction.*items 'id: v, v' separated by ';'" "$fem" "${s[@]}" -s "FEM region 1/Traction=1: 0"
expect 2 "FEM region 1/Fixed boundaries.*not 9" "$fem" "${s[@]}" -s "FEM region 1/Fixed boundaries=9"
expect 2 "FEM region 1/Shaken boundaries.*expected ids only with the effect 'base shaking' listed" "$fem" "${s[@]}" \
  -s "FEM region 1/Shaken boundaries=2"
expect 2 "FEM region 1/Shaken boundaries.*expected ids without another condition \(id 0 is fixed" "$fem" "${s[@]}" \
  -s "Effects=base shaking" -s "Base shaking/Load curve=0: 0, 1: 1" -s "FEM region 1/Shaken boundaries=0"
expect 2 "section 'FEM region 1' but 'Number of FEM regions' = 0" "$fem" "${s[@]}" -s "Number of FEM regions=0"
# Resuming where no run saved itself.
expect 2 "checkpoints: no such folder of checkpoints" "$scene" "${s[@]}" --resume
# Names with typos: one line in the program's words, naming the file or the
# override, the section, and the nearest declared names.
sed 's/set End time/set End tme/' "$scene" > typo_entry.prm
expect 2 "typo_entry.prm: line [0-9]+: 'Time/End tme' is not an entry of this scene \(did you mean 'Time/End time'\?\)$" typo_entry.prm "${s[@]}"
sed 's/^subsection Time/subsection Tme/' "$scene" > typo_section.prm
expect 2 "typo_section.prm: line [0-9]+: 'subsection Tme' is not a section of this scene \(did you mean 'Time'\?\)$" typo_section.prm "${s[@]}"
sed 's/^subsection Material 1/subsection Materal 1/' "$scene" > typo_material.prm
expect 2 "typo_material.prm: line [0-9]+: 'subsection Materal 1' is not a section of this scene \(did you mean 'Material 1'\?\)$" typo_material.prm "${s[@]}"
sed "s/set Young's modulus/set Youngs modulus/" "$scene" > typo_nested.prm
expect 2 "typo_nested.prm: line [0-9]+: 'Material 1/linear elastic/Youngs modulus' is not an entry of this scene \(did you mean 'Material 1/linear elastic/Young's modulus'\?\)$" typo_nested.prm "${s[@]}"
sed 's/set Shape \( *\)= ball/set Shape = bal/' "$scene" > typo_choice.prm
expect 2 "typo_choice.prm: entry 'Body 1/Shape' = 'bal': expected one of 'box', 'ball', 'cylinder', 'polygon', 'mesh' \(did you mean 'ball'\?\)$" typo_choice.prm "${s[@]}"
expect 2 "command line: -s 'Time/End tme=1': 'Time/End tme' is not an entry of this scene \(did you mean 'Time/End time'\?\)$" "$scene" "${s[@]}" -s "Time/End tme=1"
expect 2 "command line: -s 'Tme/End time=1': 'Tme/End time' is not an entry of this scene \(did you mean 'Time/End time'\?\)$" "$scene" "${s[@]}" -s "Tme/End time=1"
expect 2 "command line: -s 'Body 1/Shape=bal': expected one of 'box', 'ball', 'cylinder', 'polygon', 'mesh' \(did you mean 'ball'\?\)$" "$scene" "${s[@]}" -s "Body 1/Shape=bal"
# Far from every name: no guess, also deep in a long path.
expect 2 "command line: -s 'Time/Frobnicate=1': 'Time/Frobnicate' is not an entry of this scene$" "$scene" "${s[@]}" -s "Time/Frobnicate=1"
expect 2 "command line: -s 'Material 1/linear elastic/Stiffness=1': 'Material 1/linear elastic/Stiffness' is not an entry of this scene$" "$scene" "${s[@]}" -s "Material 1/linear elastic/Stiffness=1"
touch afile
# Heat conduction's entries (issue 37).
heat=(-s "Effects=heat conduction" -s "Heat conduction/Specific heat=1")
expect 2 "Heat fluxes=0: abc'.*value a number" "$scene" "${s[@]}" "${heat[@]}" -s "Heat conduction/Heat fluxes=0: abc"
expect 2 "Thermal expansion=-1'.*numbers >= 0" "$scene" "${s[@]}" "${heat[@]}" -s "Heat conduction/Thermal expansion=-1"
expect 2 "Taylor-Quinney coefficient=2'.*from 0 to 1" "$scene" "${s[@]}" "${heat[@]}" -s "Heat conduction/Taylor-Quinney coefficient=2"
expect 2 "Convection=9: 1'.*boundary ids the grid has" "$scene" "${s[@]}" "${heat[@]}" -s "Heat conduction/Convection=9: 1"
expect 2 "Heat source=sin\('.*expression of x,y,t" "$scene" "${s[@]}" "${heat[@]}" -s "Heat conduction/Heat source=sin("
expect 2 "Flux curve=1: 2, 0: 1'.*increasing times" "$scene" "${s[@]}" "${heat[@]}" -s "Heat conduction/Flux curve=1: 2, 0: 1"
expect 2 "Temperature curve=1: 2, 0: 1'.*increasing times" "$scene" "${s[@]}" "${heat[@]}" -s "Heat conduction/Temperature curve=1: 2, 0: 1"
expect 2 "Ambient curve=x'.*expected a table" "$scene" "${s[@]}" "${heat[@]}" -s "Heat conduction/Ambient curve=x"
expect 2 "FEM region 1/Fixed temperatures.*no entries unless 'Effects' lists 'heat conduction'" "$fem" "${s[@]}" \
  -s "FEM region 1/Fixed temperatures=0: 300"
expect 2 "FEM region 1/Fixed temperatures.*boundary ids of the region's mesh \(0, 1, 2, 3\), not 7" "$fem" "${s[@]}" \
  "${heat[@]}" -s "FEM region 1/Fixed temperatures=7: 300"
expect 2 "FEM region 1/Heat fluxes.*no entries unless 'Effects' lists 'heat conduction'" "$fem" "${s[@]}" \
  -s "FEM region 1/Heat fluxes=0: 300"
expect 2 "FEM region 1/Heat fluxes=0: x'.*value a number \(W/m\^2\)" "$fem" "${s[@]}" \
  "${heat[@]}" -s "FEM region 1/Heat fluxes=0: x"
expect 2 "FEM region 1/Convection=0: -1'.*value a number >= 0" "$fem" "${s[@]}" \
  "${heat[@]}" -s "FEM region 1/Convection=0: -1"
expect 2 "FEM region 1/Convection.*boundary ids of the region's mesh \(0, 1, 2, 3\), not 7" "$fem" "${s[@]}" \
  "${heat[@]}" -s "FEM region 1/Convection=7: 10"
three=(-s "Number of materials=3")
for m in 2 3; do
  three+=(-s "Material $m/Model=linear elastic" -s "Material $m/Density=1" -s "Material $m/linear elastic/Young's modulus=1")
done
expect 2 "FEM region 1/Material.*Conductivity and a Specific heat \(material 3 has none\)" "$fem" "${s[@]}" \
  "${heat[@]}" "${three[@]}" -s "Heat conduction/Specific heat=1, 2" -s "FEM region 1/Material=3"
expect 2 "Output/Directory.*expected a folder that can be created and written" "$scene" -s "Output/Directory=afile/sub"
# The same under MPI must not hang (only rank 0 makes folders).
if command -v mpirun > /dev/null; then
  flags=("${mpirun_flags[@]}")
  timeout 120 mpirun "${flags[@]}" -np 2 "$dealmpm" "$scene" -s "Output/Directory=afile/sub" > out.txt 2> err.txt
  code=$?
  if [ $code != 2 ] || ! grep -q "Output/Directory" err.txt; then
    echo "FAIL: unwritable output folder on 2 ranks -> exit $code"; cat err.txt; failures=$((failures + 1))
  else
    echo "ok: 2 ranks: $(head -1 err.txt)"
  fi
fi

finish bad-input
