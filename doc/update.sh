#!/usr/bin/env bash
# Regenerate the parameter reference from the program (a test checks that the
# committed files are current):  doc/update.sh [path/to/dealmpm]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
dealmpm=${1:-$here/../build/dealmpm}
"$dealmpm" --print-parameters > "$here/parameters-2d.prm"
"$dealmpm" --print-parameters -s "Dimension=3" > "$here/parameters-3d.prm"
