#!/usr/bin/env bash
# 'MPM/Anti-locking = automatic', the particles' default, says what it
# chose in the run's first lines: F-bar for a material that locks (here
# Drucker-Prager), none with the reason and the override for Johnson-Cook
# (its Taylor bars gain nothing from F-bar), and nothing where there was
# nothing to choose (an elastic solid at nu = 0.3, or 'none' asked for).
# One step of the colliding disks with each material.
# Arguments: dealmpm, the colliding disks.
here=$(cd "$(dirname "$0")" && pwd)
source "$here/check_lib.sh"
first_lines() { # overrides...: the run's first three lines
  "$dealmpm" "$scene" -s "Time/Maximum number of steps=1" -s "Output/Directory=out" \
    -s "Output/Progress interval=0" "$@" 2>&1 | head -3
}
lines=$(first_lines)
grep -q "anti-locking" <<< "$lines" && fail "elastic at nu = 0.3: says $lines"
lines=$(first_lines -s "Material 1/Model=Drucker-Prager")
grep -q "^dealmpm: anti-locking F-bar ('MPM/Anti-locking = automatic': Material 1 (Drucker-Prager) locks" \
  <<< "$lines" || fail "Drucker-Prager: $lines"
lines=$(first_lines -s "Material 1/Model=Drucker-Prager" -s "MPM/Anti-locking=none")
grep -q "anti-locking" <<< "$lines" && fail "Drucker-Prager with 'none': says $lines"
lines=$(first_lines -s "Material 1/Model=Johnson-Cook")
grep -q "^dealmpm: anti-locking none ('MPM/Anti-locking = automatic': Material 1 (Johnson-Cook) locks.*'MPM/Anti-locking = F-bar' applies it)" \
  <<< "$lines" || fail "Johnson-Cook: $lines"
finish "anti-locking choice"
