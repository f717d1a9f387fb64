#!/usr/bin/env python3
"""The one-way layers of doc/design.md, checked: a module may include
<dealmpm/X/...> only for X at its own floor or below. Prints every include
that runs up and exits 1 when there is one.

    layers.py [project root]
"""
import pathlib
import re
import sys

# Lowest first; doc/design.md ("Layers") explains each floor.
LAYERS = ["base", "grid", "particles", "materials", "transfer", "effects",
          "fem", "adaptivity", "schemes", "diagnostics", "io", "core",
          "study", "app"]
FLOOR = {name: i for i, name in enumerate(LAYERS)}
INCLUDE = re.compile(r'^\s*#\s*include\s*<dealmpm/([a-z_]+)/', re.M)


def module_of(path, root):
    """The module a file under source/ or include/dealmpm/ belongs to."""
    parts = path.relative_to(root).parts
    if parts[0] == "include":
        parts = parts[2:]
    else:
        parts = parts[1:]
    return parts[0] if len(parts) > 1 else None


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else
                        pathlib.Path(__file__).resolve().parents[2])
    files = [p for d in ("source", "include/dealmpm")
             for p in sorted((root / d).rglob("*"))
             if p.suffix in (".h", ".cc")]
    upward, unknown = [], set()
    for path in files:
        module = module_of(path, root)
        if module is None:
            continue
        if module not in FLOOR:
            unknown.add(module)
            continue
        text = path.read_text()
        for match in INCLUDE.finditer(text):
            target = match.group(1)
            if target not in FLOOR:
                unknown.add(target)
            elif FLOOR[target] > FLOOR[module]:
                line = text.count("\n", 0, match.start()) + 1
                upward.append(f"{path.relative_to(root)}:{line}: {module} "
                              f"includes {target}, a floor above it")
    for name in sorted(unknown):
        print(f"module '{name}' has no floor in tests/house/layers.py "
              "(add it there and to doc/design.md)")
    for line in upward:
        print(line)
    print(f"{len(files)} files, {len(upward)} upward includes, "
          f"{len(unknown)} modules without a floor")
    return 1 if upward or unknown else 0


if __name__ == "__main__":
    sys.exit(main())
