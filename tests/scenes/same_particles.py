"""same_particles.py a.csv b.csv tolerance: two particle CSV files
(Output/Particle CSV) hold the same particles (by id, in any order) with
every value equal within the tolerance, relative to the largest magnitude
in its column's group (the position's components together, the
velocity's, the displacement's; others alone), so that a component that
is zero up to round-off is measured against the vector it belongs to. Prints the first difference and exits 1 otherwise."""

import csv
import sys


def read(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    return rows[0], {row[0]: [float(v) for v in row[1:]] for row in rows[1:]}


header_a, a = read(sys.argv[1])
header_b, b = read(sys.argv[2])
tolerance = float(sys.argv[3])
if header_a != header_b or a.keys() != b.keys():
    sys.exit("different particles: %d vs %d (ids or columns differ)" % (len(a), len(b)))
names = header_a[1:]
group = [n[:-1] if n[-1:] in "xyz" else n for n in names]
largest = {}
for c, g in enumerate(group):
    largest[g] = max([largest.get(g, 1e-300)] + [abs(r[c]) for r in a.values()])
scale = [largest[g] for g in group]
for pid, values in a.items():
    for c, (x, y) in enumerate(zip(values, b[pid])):
        if abs(x - y) > tolerance * scale[c]:
            sys.exit("particle %s, %s: %r vs %r" % (pid, header_a[c + 1], x, y))
print("same %d particles (tolerance %g)" % (len(a), tolerance))
