#!/usr/bin/env python3
"""No input may crash the program: mangled versions of shipped scenes (cut
lines, huge, non-ASCII and binary values, deep nesting) and mangled -s
overrides end in exit 0 (the mangling left a valid scene) or in a non-zero
exit below 128 with one line on standard error; never a signal, a hang or
a wall of text.

    mangled_input.py DEALMPM SCENE.prm [SCENE.prm ...]

Every run is cut to one step (-s "Time/Maximum number of steps=1") and
writes into a scratch folder. Deterministic: the same variants every time.
"""
import os
import random
import re
import subprocess
import sys
import tempfile

ONE_STEP = "Time/Maximum number of steps=1"
LONG = 10000  # the longest line the program reads (parameter_file.cc)


def set_lines(lines):
    return [i for i, l in enumerate(lines)
            if re.match(rb"\s*set\s+[^=]+=", l)]


def with_value(lines, i, value):
    head = lines[i][:lines[i].index(b"=") + 1]
    out = list(lines)
    out[i] = head + b" " + value + b"\n"
    return out


def variants(text, rng):
    """(name, file bytes, extra overrides) of one scene."""
    lines = text.splitlines(keepends=True)
    sets = set_lines(lines)
    for share in (0.2, 0.5, 0.8):  # cut in the middle of a line
        cut = int(len(text) * share)
        yield f"cut at {cut} of {len(text)} bytes", text[:cut], []
    picks = [sets[0], sets[-1]]  # the top level and the last section
    values = {
        "100k characters": b"x" * 100000,
        "just below the longest line": b"x" * (LONG - 60),
        "a huge number": b"9" * 400,
        "1e999": b"1e999",
        "a list of 2,000 numbers": b", ".join([b"1"] * 2000),
        "non-ASCII": "\u00e9\u2192\u221e \u6f22\u5b57".encode(),
        "invalid UTF-8": b"\xff\xfe\xc3(",
        "control characters": b"\x01\x02\x1b[31m\x7f",
        "a NUL byte": b"1\x002",
        "unbalanced quotes and brackets": b"'\"<<[[{(",
    }
    for i in picks:
        for name, value in values.items():
            yield f"line {i + 1}: {name}", b"".join(with_value(lines, i,
                                                                value)), []
    middle = len(text) // 2
    noise = bytes(rng.randrange(256) for _ in range(64))
    yield "64 random bytes inside", text[:middle] + noise + text[middle:], []
    yield "all NUL", b"\x00" * 100000, []
    yield "empty", b"", []
    yield "10,000 subsections never closed", \
        text + b"subsection Deep\n" * 10000, []
    yield "10,000 subsections closed", \
        text + b"subsection Deep\n" * 10000 + b"end\n" * 10000, []
    yield "10,000 extra ends", text + b"end\n" * 10000, []
    yield "a line of 1 MB", text + b"#" + b"y" * 1000000 + b"\n", []
    overrides = {
        "100k-character override": ["Time/End time=" + "x" * 100000],
        "override just below the limit": ["Time/End time=" + "x" * (LONG - 30)],
        "override of a long path": ["/".join(["A"] * 3000) + "=1"],
        "non-ASCII override": ["Time/End tim\u00e9=1"],
        "override without '='": ["Time/End time"],
        "override of an empty path": ["=1"],
    }
    for name, extra in overrides.items():
        yield name, text, extra


def run(program, scene, extra, folder):
    command = [program, scene, "-s", ONE_STEP,
               "-s", "Output/Directory=" + os.path.join(folder, "out")]
    command += [a for e in extra for a in ("-s", e)]
    try:
        r = subprocess.run(command, cwd=folder, timeout=120,
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    except subprocess.TimeoutExpired:
        return "hung (no exit within 120 s)"
    err = r.stderr.decode(errors="replace").strip().splitlines()
    if r.returncode < 0 or r.returncode >= 128:
        return f"exit {r.returncode} (a signal): {' '.join(err[-3:])[:300]}"
    if r.returncode != 0 and len(err) != 1:
        return (f"exit {r.returncode} with {len(err)} lines on standard "
                f"error, expected one: {' | '.join(err[:4])[:300]}")
    if r.returncode != 0 and not err[0].startswith("dealmpm: error:"):
        return f"exit {r.returncode}, the line is not an error: {err[0][:200]}"
    return None


def main():
    program, scenes = sys.argv[1], sys.argv[2:]
    rng = random.Random(20261130)
    failures, count = [], 0
    with tempfile.TemporaryDirectory() as folder:
        for scene in scenes:
            with open(scene, "rb") as f:
                text = f.read()
            for name, content, extra in variants(text, rng):
                mangled = os.path.join(folder, "mangled.prm")
                with open(mangled, "wb") as f:
                    f.write(content)
                problem = run(program, mangled, extra, folder)
                count += 1
                label = f"{os.path.basename(scene)}: {name}"
                print(("FAIL " if problem else "ok   ") + label, flush=True)
                if problem:
                    failures.append(f"{label}: {problem}")
    print(f"{count} mangled inputs, {len(failures)} failures")
    for f in failures:
        print("FAIL: " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
