#!/usr/bin/env python3
"""Numbers from the tables of `gonio brdf section` (first colour component of each curve).

    section_stats.py rms A.txt B.txt   # relative RMS between two runs of the same cuts
    section_stats.py ratios T.txt      # backscatter, side and forward values of each Δφ cut
    section_stats.py growth T.txt      # f at the lowest viewer over f at the highest, per light
    section_stats.py compare T.txt     # two grids' curves of the same cuts: level and shape

The tables are what `gonio brdf section --vary phi-out --from 0 --to 180` prints: a header line
naming each curve as "[grid cut]:component", then one row per sample. For two seeds of the same
cut, the relative RMS is sqrt(mean((a - b)^2)) / mean((a + b) / 2) over the samples: the
seed-to-seed spread as a fraction of the curve's level (one seed's error is that over sqrt 2).
`ratios` reads f at Δφ = 0 (back towards the light), 90 (the side) and 180 (forward); `growth`
divides, for each θ_in, the curve of the largest θ_out by that of the smallest at those Δφ (the
thesis's "higher reflectance at lower outgoing direction"). `compare` reads a table of two grids
with the same k cuts (the first grid's k curves, then the second's) and prints, per cut, the
ratio of the second's mean level to the first's, the range of their ratio over the samples, and
the largest relative difference of the two shapes (each curve divided by its mean level).
"""

import math
import re
import sys


def read_table(path):
    """The curve names and, per curve, its (x, f) samples of component 0."""
    with open(path) as table:
        lines = [line for line in table if line.strip()]
    header = re.findall(r"\[[^\]]*\]:\d+|\.\.\.:\d+", lines[0])
    names, columns, last = [], [], ""
    for column, title in enumerate(header):
        name, component = title.rsplit(":", 1)
        last = last if name == "..." else name
        if component == "0":
            names.append(last)
            columns.append(column + 1)
    rows = [[float(v) for v in line.split()] for line in lines[1:]]
    return names, [[(row[0], row[c]) for row in rows] for c in columns]


def cut_label(name):
    """"θi=60° θo=80°" from a curve name such as "[g.grd θi=60° φi=0° θo=80°]"."""
    angles = re.findall(r"(θ[io])=([-\d.]+)°", name)
    return " ".join("%s=%s" % (a, v) for a, v in angles)


def relative_rms(a, b):
    diff = [(fa - fb) ** 2 for (_, fa), (_, fb) in zip(a, b)]
    level = sum(fa + fb for (_, fa), (_, fb) in zip(a, b)) / (2 * len(a))
    return math.sqrt(sum(diff) / len(diff)) / level


def value_at(curve, x):
    return min(curve, key=lambda sample: abs(sample[0] - x))[1]


def angle(name, which):
    return float(re.search(which + r"=([-\d.]+)°", name).group(1))


def print_growth(names, curves):
    by_light = {}
    for name, curve in zip(names, curves):
        by_light.setdefault(angle(name, "θi"), []).append((angle(name, "θo"), curve))
    print("%-8s %-10s %9s %9s %9s" % ("θi", "θo", "Δφ=0", "Δφ=90", "Δφ=180"))
    for theta_in, cuts in sorted(by_light.items()):
        (low, top), (high, bottom) = min(cuts, key=lambda c: c[0]), max(cuts, key=lambda c: c[0])
        ratios = [value_at(bottom, x) / value_at(top, x) for x in (0, 90, 180)]
        print("%-8g %-10s %9.2f %9.2f %9.2f" % (theta_in, "%g/%g" % (high, low), *ratios))


def print_comparison(names, curves):
    k = len(curves) // 2
    print("%-16s %7s %13s %7s" % ("cut", "level", "ratio range", "shape"))
    for name, a, b in zip(names, curves[:k], curves[k:]):
        fa, fb = [f for _, f in a], [f for _, f in b]
        mean_a, mean_b = sum(fa) / len(fa), sum(fb) / len(fb)
        ratios = [y / x for x, y in zip(fa, fb)]
        shape = max(abs(y / mean_b - x / mean_a) / (x / mean_a) for x, y in zip(fa, fb))
        print("%-16s %7.3f %6.2f-%-6.2f %6.0f%%" % (cut_label(name), mean_b / mean_a, min(ratios),
                                                   max(ratios), 100 * shape))


def main():
    if len(sys.argv) == 4 and sys.argv[1] == "rms":
        names, a = read_table(sys.argv[2])
        _, b = read_table(sys.argv[3])
        for name, ca, cb in zip(names, a, b):
            print("%-16s %6.1f%%" % (cut_label(name), 100 * relative_rms(ca, cb)))
    elif len(sys.argv) == 3 and sys.argv[1] == "ratios":
        names, curves = read_table(sys.argv[2])
        print("%-16s %9s %9s %9s %9s %9s" % ("cut", "f(0)", "f(90)", "f(180)", "back/side",
                                            "fwd/side"))
        for name, curve in zip(names, curves):
            back, side, forward = (value_at(curve, x) for x in (0, 90, 180))
            print("%-16s %9.4f %9.4f %9.4f %9.2f %9.2f" % (cut_label(name), back, side, forward,
                                                         back / side, forward / side))
    elif len(sys.argv) == 3 and sys.argv[1] == "growth":
        print_growth(*read_table(sys.argv[2]))
    elif len(sys.argv) == 3 and sys.argv[1] == "compare":
        print_comparison(*read_table(sys.argv[2]))
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main()
