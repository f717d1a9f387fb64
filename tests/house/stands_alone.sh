#!/usr/bin/env bash
# The project stands alone (doc/design.md, "House rules"): no file in it
# cites the planning notes it grew from outside the project. Prints
# file:line for every citation and exits 1 when there is one.
#
#     stands_alone.sh PROJECT_ROOT
#
# The tracked files (git ls-files) when PROJECT_ROOT is a git checkout,
# else every file but build folders. This script names the patterns, so it
# is left out.
set -u
root=${1:?usage: stands_alone.sh PROJECT_ROOT}
cd "$root" || exit 2

# The patterns, written so that this file does not match them itself.
patterns=(-e "DESIGN[.]md" -e "RESEARCH[.]md" -e "VERIFICATION[.]md"
          -e "[.][.]/shared")
self=tests/house/stands_alone.sh

if [ -e .git ] && git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  list_files() { git ls-files -z; }
else
  list_files() {
    find . -type d \( -name .git -o -name 'build*' \) -prune -o -type f \
      -print0 | sed -z 's|^\./||'
  }
fi

found=$(list_files | grep -zv -x -F "$self" |
        xargs -0 -r grep -n -I -H -s "${patterns[@]}" --)
if [ -n "$found" ]; then
  echo "$found"
  echo "$(echo "$found" | wc -l) citations of files outside the project" \
       "(move what they cite into doc/ and cite that)"
  exit 1
fi
echo "no citation of files outside the project"
exit 0
