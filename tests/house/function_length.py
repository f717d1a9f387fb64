#!/usr/bin/env python3
"""A house rule on size, checked: no function longer than MAX_FUNCTION_LINES
lines (one screen), no file in source/ longer than MAX_FILE_LINES.
Prints the longest functions (lines, file:line, name), then every function
and file over its limit, and exits 1 when there is one.

    function_length.py [project root]

The code is clang-formatted in deal.II's style (.clang-format), which this
reads instead of parsing C++ (CI has no ctags): a definition's name and
arguments start a line (its return type on the line before), the body's '{'
stands alone at the name's indentation (a control statement's '{' is
indented further: IndentBraces), and the first '}' back at that indentation
closes it. So lambdas count as part of the function around them, and member
functions defined in a class body count on their own. A function's length
runs from the line with its name to its closing brace, as ctags' line and
end fields do.
"""
import pathlib
import re
import sys

MAX_FUNCTION_LINES = 80
MAX_FILE_LINES = 700
N_LONGEST = 10

# Lines that open a block at their own indentation without being a
# function: types, namespaces, statements.
NOT_A_FUNCTION = re.compile(
    r"^(class|struct|union|enum|namespace|extern|if|else|for|while|do|"
    r"switch|case|default|try|catch|return|template\b|using|typedef)\b")
# The name a definition's line starts with: an operator or a (qualified,
# possibly templated) identifier, followed by its argument list.
NAME = re.compile(r"^(?:explicit\s+|~)?((?:[\w:<>,~ ]*?)"
                  r"(?:operator\s*(?:\(\)|[^\s(]+)|[\w~]+))\s*\(")


def indentation(line):
    return len(line) - len(line.lstrip(" "))


def name_line(lines, brace):
    """The line of the definition whose body's '{' is lines[brace], or None
    if that brace opens something else."""
    indent = indentation(lines[brace])
    before = lines[brace - 1].rstrip() if brace > 0 else ""
    # A bare block after a statement, or a brace after a comment.
    if not before.strip() or before.endswith((";", "{", "}")) or \
       before.lstrip().startswith(("//", "*", "/*", "#")):
        return None
    i = brace - 1
    # The arguments, qualifiers and constructor initialisers are indented
    # further than the name.
    while i >= 0 and lines[i].strip() and indentation(lines[i]) > indent:
        i -= 1
    if i < 0 or not lines[i].strip() or indentation(lines[i]) != indent:
        return None
    text = lines[i].strip()
    # clang-format indents a name further after a macro it misreads as
    # the return type's end (DEAL_II_ALWAYS_INLINE Tensor<2, dim>).
    if "(" not in text and i + 1 < brace and NAME.match(
            lines[i + 1].strip()):
        i += 1
        text = lines[i].strip()
    if NOT_A_FUNCTION.match(text) or text.startswith(("//", "/*", "*", "#")):
        return None
    match = NAME.match(text)
    if match is None:
        return None
    return i, match.group(1).strip()


def closing_line(lines, brace):
    """The line of the '}' that closes the '{' alone on lines[brace]."""
    if lines[brace].strip() == "{}":
        return brace
    indent = indentation(lines[brace])
    for j in range(brace + 1, len(lines)):
        if indentation(lines[j]) == indent and lines[j].lstrip().startswith(
                "}"):
            return j
    return None


def functions(path, root):
    """(lines, file:line, name) of each function defined in path."""
    lines = path.read_text(encoding="utf-8").split("\n")
    found = []
    for brace, line in enumerate(lines):
        if line.strip() not in ("{", "{}"):
            continue
        start = name_line(lines, brace)
        if start is None:
            continue
        end = closing_line(lines, brace)
        if end is None:
            continue
        first, name = start
        found.append((end - first + 1,
                      f"{path.relative_to(root)}:{first + 1}", name))
    return found


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else
                        pathlib.Path(__file__).resolve().parents[2])
    files = [p for d in ("source", "include/dealmpm")
             for p in sorted((root / d).rglob("*"))
             if p.suffix in (".h", ".cc")]
    found = [f for path in files for f in functions(path, root)]
    found.sort(key=lambda f: (-f[0], f[1]))

    print(f"The {N_LONGEST} longest functions (lines, place, name):")
    for length, place, name in found[:N_LONGEST]:
        print(f"  {length:4d}  {place}  {name}")

    failed = False
    too_long = [f for f in found if f[0] > MAX_FUNCTION_LINES]
    if too_long:
        failed = True
        print(f"\nFunctions over {MAX_FUNCTION_LINES} lines: split them.")
        for length, place, name in too_long:
            print(f"  {length:4d}  {place}  {name}")

    big_files = []
    for path in files:
        if path.relative_to(root).parts[0] != "source":
            continue
        n = len(path.read_text(encoding="utf-8").splitlines())
        if n > MAX_FILE_LINES:
            big_files.append((n, path.relative_to(root)))
    if big_files:
        failed = True
        print(f"\nFiles in source/ over {MAX_FILE_LINES} lines: split them.")
        for n, path in sorted(big_files, reverse=True):
            print(f"  {n:4d}  {path}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
