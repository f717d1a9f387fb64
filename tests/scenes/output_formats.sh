#!/usr/bin/env bash
# Output/Compression = zlib: particle .vtu files that ParaView reads as the
# same data as the raw ones, and smaller.
# Output/Format = hdf5: one .h5 file per output for all ranks (no file per
# rank), and .xdmf series that ParaView opens without a warning. Each scene
# runs twice on the same ranks, with vtu and with hdf5 output, and
# ParaView (pvpython) reads both series: every output must hold the same
# data, the particles entry by entry (matched by id, types kept: ids are
# Int64), the grid's and the FEM regions' nodal fields to their VTU
# rounding (deal.II's .vtu stores Float32). Scenes: the colliding disks
# with the grid adapted every step on 2 ranks, the dropped cube in 3D on 2
# ranks with a rank that holds no particle, the bonded bar (an FEM region)
# on 3 ranks; and
# a run resumed from a checkpoint.
here=$(cd "$(dirname "$0")" && pwd)
source "$here/check_lib.sh"
mpirun=$3 prm=$(dirname "$scene")
command -v pvpython > /dev/null || { echo "FAIL: pvpython missing (./build.sh test installs python3-paraview)"; exit 1; }

run() { # ranks scene folder format overrides...
  local ranks=$1 file=$2 out=$3 format=$4; shift 4
  timeout 600 "$mpirun" "${mpirun_flags[@]}" -np "$ranks" "$dealmpm" "$file" \
    -s "Output/Directory=$out" -s "Output/Format=$format" -s "Output/Progress interval=0" \
    "$@" > "$out.log" 2>&1 || fail "$out: exit code $? ($(tail -1 "$out.log"))"
}

compare() { # folder_vtu folder_hdf5 series...
  local vtu=$1 h5=$2; shift 2
  for s in "$@"; do
    [ -s "$h5/$s.xdmf" ] || fail "$h5/$s.xdmf missing"
  done
  if ls "$h5"/steps/*.vtu "$h5"/steps/*.pvtu > /dev/null 2>&1; then fail "$h5 has .vtu files"; fi
  local n_outputs; n_outputs=$(grep -c DataSet "$vtu/particles.pvd")
  [ "$(ls "$h5"/steps/particles_*.h5 | wc -l)" = "$n_outputs" ] || fail "$h5: not one particles .h5 per output"
  timeout 300 pvpython "$here/same_series.py" "$vtu" "$h5" "$@" > "$h5.compare" 2>&1 \
    || fail "$h5: $(cat "$h5.compare")"
  grep -qi "warning\|error" "$h5.compare" && fail "$h5: ParaView says: $(grep -i 'warning\|error' "$h5.compare" | head -3)"
  cat "$h5.compare"
}

short=(-s "Time/End time=0.02" -s "Output/Interval=0.01")
adaptive=(-s "Adaptivity/Criteria=particles" -s "Adaptivity/Steps between adaptations=1")
for format in vtu hdf5; do
  run 2 "$prm/colliding_disks.prm" "disks_$format" "$format" "${short[@]}" "${adaptive[@]}" -s "Output/Write grid=true"
  run 2 "$prm/cube_drop_3d.prm" "cube_$format" "$format" "${short[@]}" -s "Load balance/Enabled=false"
  run 3 "$prm/bonded_bar.prm" "bar_$format" "$format" "${short[@]}"
done
# The time an output takes, in the run's summary.
for f in vtu hdf5; do
  grep -Eq "^dealmpm: 3 output\(s\), [0-9.e+-]+ s each \(slowest rank\)" "disks_$f.log" \
    || fail "disks_$f: no line with the time per output"
done
grep -q "2 rank(s) (0 to" cube_hdf5.log || fail "expected a rank without particles: $(grep 'rank(s)' cube_hdf5.log)"
compare disks_vtu disks_hdf5 particles grid
compare cube_vtu cube_hdf5 particles
compare bar_vtu bar_hdf5 particles fem_region_1

run 2 "$prm/colliding_disks.prm" disks_zlib vtu "${short[@]}" "${adaptive[@]}" -s "Output/Compression=zlib"
timeout 300 pvpython "$here/same_series.py" disks_vtu disks_zlib particles > zlib.compare 2>&1 \
  || fail "zlib: $(cat zlib.compare)"
cat zlib.compare
grep -q 'compressor="vtkZLibDataCompressor"' disks_zlib/steps/particles_00002.1.vtu || fail "zlib: not compressed"
raw=$(du -b disks_vtu/steps/particles_00002.1.vtu | cut -f1) packed=$(du -b disks_zlib/steps/particles_00002.1.vtu | cut -f1)
[ "$packed" -lt "$raw" ] || fail "zlib: $packed bytes, not fewer than the raw $raw"

# A resumed run continues the .xdmf series: from a checkpoint before the
# last output, it removes what the interrupted run wrote after it and ends
# with the uninterrupted run's series.
resume=(-s "Time/End time=0.05" -s "Output/Interval=0.01" -s "Checkpoint/Steps between checkpoints=2")
run 1 "$prm/colliding_disks.prm" resumed hdf5 "${resume[@]}"
cp resumed/particles.xdmf uninterrupted.xdmf
# (The run saved its end too: resume from the older of the two kept.)
older=$(ls -d resumed/checkpoints/checkpoint-* | head -1)
run 1 "$prm/colliding_disks.prm" resumed hdf5 "${resume[@]}" --resume "$older"
grep -q "removed [1-9][0-9]* files the interrupted run wrote" resumed.log || fail "resume removed nothing: $(grep 'output in' resumed.log)"
cmp -s uninterrupted.xdmf resumed/particles.xdmf || fail "the resumed run's particles.xdmf differs"
[ "$(ls resumed/steps/particles_*.h5 | wc -l)" = "$(grep -c '<Time ' uninterrupted.xdmf)" ] || fail "resumed: not one .h5 per output"
# ... but not in the other format: its series could not go on.
if "$dealmpm" "$prm/colliding_disks.prm" -s "Output/Directory=resumed" -s "Output/Format=vtu" \
     "${resume[@]}" --resume > other_format.log 2>&1; then
  fail "a resume in the other format ran"
fi
grep -q "entry 'Output/Format' = 'vtu': the saved run wrote hdf5" other_format.log \
  || fail "a resume in the other format: $(tail -1 other_format.log)"

# A vtu run in the hdf5 run's folder removes its files and series.
run 1 "$prm/colliding_disks.prm" disks_hdf5 vtu -s "Time/End time=0.01" -s "Output/Interval=0.01"
if ls disks_hdf5/*.xdmf disks_hdf5/steps/*.h5 > /dev/null 2>&1; then fail "an earlier run's .h5/.xdmf files stayed"; fi
finish "output format"
