#!/usr/bin/env python3
"""The documentation cannot drift from the program: every command README.md,
the user guide (doc/guide/*.md) and the tutorials (doc/tutorials/*.md) give
in a ```sh block runs as written.

    doc_commands.py SOURCE_DIR BUILD_DIR [FILE.md ...]

Each line of a ```sh block is run from a scratch folder that looks like the
project's root (its folders linked, build/ the build), so the commands'
output folders land there and not in the source tree. Runs are shortened,
nothing else is changed:
- a scene run (build/dealmpm scene.prm ..., alone or under mpirun) gets
  -s "Time/Maximum number of steps=3" and -s "Checks/Energy growth
  limit=0": 3 steps check the command, not the physics (ctest
  scene_header.* runs the scenes whole), and where the energy comes in
  slowly (gravity ramped up, a centrifuge spinning up: tutorial 2) the
  guard's fraction of the little energy put in by step 3 means nothing
  (+41 % there, while the whole run closes to -1.4 %);
- a study (--study file) runs a copy of its study file with each axis cut
  to its first value and 3 steps a run;
- ./build.sh is what CI runs itself: only checked to exist;
- a script given the program (python3 benchmarks/hard_cases.py
  build/dealmpm --check CASE) runs whole: the program is run by it.
The lines after a run (a tutorial's pvpython picture, its plot of
statistics.csv) run unchanged on the shortened run's output.
Under root, mpirun gets Open MPI's root variables in its environment (what
the README tells root to set); nothing adds --oversubscribe, so an mpirun
line asking for more ranks than this machine's cores fails, as it would
for a user. README.md must also stay a front door: at most 250 lines.
"""
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile

README_MOST_LINES = 250
STEPS = "Time/Maximum number of steps=3"
NO_GUARD = "Checks/Energy growth limit=0"
STUDY_AXES = ("Refinements", "Formulations", "Adaptivity",
              "Particles per cell", "Shape functions", "Stress updates",
              "Velocity updates", "CFL numbers")


def sh_lines(path):
    """(line number, command) of every line of the file's ```sh blocks."""
    out, inside = [], False
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            fence = line.strip()
            if fence.startswith("```"):
                inside = (not inside) and fence[3:].strip() == "sh"
                continue
            if inside and line.strip() and not line.strip().startswith("#"):
                out.append((number, line.rstrip("\n")))
    return out


def markdown_files(folder):
    """The .md files of @p folder, sorted (none if it is missing)."""
    names = os.listdir(folder) if os.path.isdir(folder) else []
    return sorted(os.path.join(folder, f) for f in names if f.endswith(".md"))


def scratch_root(source, build):
    root = tempfile.mkdtemp(prefix="doc_commands.")
    for name in os.listdir(source):
        if name not in ("build", "output", ".git"):
            os.symlink(os.path.join(source, name), os.path.join(root, name))
    os.symlink(os.path.abspath(build), os.path.join(root, "build"))
    return root


def short_study(study, root):
    """A copy of @p study with one run of 3 steps, in @p root."""
    folder = os.path.dirname(os.path.abspath(study))
    lines = []
    with open(study, encoding="utf-8") as f:
        for line in f:
            m = re.match(r"(\s*set\s+)([^=]+?)(\s*=\s*)(.*)$", line.rstrip("\n"))
            if m:
                key, value = m.group(2), m.group(4)
                if key == "Base scene":
                    value = os.path.normpath(os.path.join(folder, value))
                elif key == "Output directory":
                    value = os.path.join(root, "study_output")
                elif key in STUDY_AXES:
                    value = value.split(",")[0].strip()
                elif key == "Settings":
                    value = (value + "; " if value.strip() else "") + STEPS
                line = m.group(1) + key + m.group(3) + value
            lines.append(line.rstrip("\n"))
    if not any(re.match(r"\s*set\s+Settings\s*=", l) for l in lines):
        end = max(i for i, l in enumerate(lines) if l.strip() == "end")
        lines.insert(end, "  set Settings = " + STEPS)
    copy = os.path.join(root, "short_" + os.path.basename(study))
    with open(copy, "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")
    return copy


def shortened(words, root):
    """The command to run for @p words (None: checked, not run)."""
    if words[0] == "./build.sh":
        if not os.access(os.path.join(root, "build.sh"), os.X_OK) or \
                words[1:] not in ([], ["run"], ["test"]):
            raise ValueError("./build.sh takes nothing, 'run' or 'test'")
        return None
    if words[0] not in ("build/dealmpm", "mpirun", "mpiexec") or \
            "build/dealmpm" not in words:
        return words
    words = list(words)
    if "--study" in words:
        i = words.index("--study") + 1
        words[i] = short_study(os.path.join(root, words[i]), root)
    elif not ({"-h", "--help", "--print-parameters", "--resume"} & set(words)):
        words += ["-s", STEPS, "-s", NO_GUARD]
    return words


def run_line(words, root, env):
    command = shortened(words, root)
    if command is None:
        return 0, "(checked, not run)"
    result = subprocess.run(command, cwd=root, env=env, timeout=600,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True, errors="replace")
    return result.returncode, result.stdout


def main():
    source, build = sys.argv[1], sys.argv[2]
    guide = os.path.join(source, "doc", "guide")
    failures = []
    if not os.path.isdir(guide):
        failures.append("doc/guide/ is missing: the user guide lives there")
    tutorials = os.path.join(source, "doc", "tutorials")
    files = sys.argv[3:] or ([os.path.join(source, "README.md")] +
                             markdown_files(guide) + markdown_files(tutorials))
    readme = os.path.join(source, "README.md")
    with open(readme, encoding="utf-8") as f:
        n = sum(1 for _ in f)
    if n > README_MOST_LINES:
        failures.append(f"README.md has {n} lines, more than "
                        f"{README_MOST_LINES}: move the rest to doc/guide/")
    env = dict(os.environ)
    if os.geteuid() == 0:
        env.update(OMPI_ALLOW_RUN_AS_ROOT="1",
                   OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    root = scratch_root(source, build)
    # $HOME in a command (an install prefix, say) is a scratch folder too.
    env["HOME"] = os.path.join(root, "home")
    os.mkdir(env["HOME"])
    os.environ["HOME"] = env["HOME"]
    count = 0
    for path in files:
        for number, line in sh_lines(path):
            where = f"{os.path.relpath(path, source)}:{number}"
            try:
                words = [os.path.expandvars(w)
                         for w in shlex.split(line, comments=True)]
                if not words:
                    continue
                code, output = run_line(words, root, env)
            except (ValueError, OSError, subprocess.TimeoutExpired) as e:
                code, output = -1, str(e)
            count += 1
            print(f"{where}: exit {code}: {line.strip()}", flush=True)
            if code != 0:
                tail = "\n".join(output.splitlines()[-15:])
                failures.append(f"{where}: '{line.strip()}' exits {code}:\n"
                                f"{tail}")
    print(f"{count} commands from {len(files)} files")
    if count == 0:
        failures.append("no ```sh block found: the files hold no command")
    for f in failures:
        print("FAIL: " + f)
    if not failures:
        shutil.rmtree(root, ignore_errors=True)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
