#!/usr/bin/env python3
"""Writes the grass micro geometry of thesis section 5.3.2 as RIB.

Blades are rectangles (width x height) standing on a square piece of ground, one per cell of an
n x n grid (thesis: 20 x 20 on 0.5 x 0.5), placed at the cell centres. Each blade is turned about
the vertical axis through its centre by alpha (its base line runs along (cos a, sin a, 0)) and
bent about its base line by beta away from the vertical, leaning towards (-sin a, cos a, 0)
(thesis fig. 5.13). alpha and beta are uniform in the given ranges, from a seeded generator, so a
run always writes the same file.

Presets (--model):
  v1      the first try (fig. 5.12): 0.01 x 0.06 blades, alpha 0..360, beta 0..20 degrees
  grass   the improved model (fig. 5.15): 0.008 x 0.03 blades, alpha 0..360, beta 0..85
  mowed   the improved model with alpha in -10..10: all blades lean towards +y (fig. 5.20)
Blades get a normalised-Phong micro BRDF (--kd, --ks, --exponent; default 0.5, 0.5, 10, the
plastic shader's defaults) and a green colour; the ground is matte soil (Kd 0.3). With --leaf
they get the leaf optics of docs/brdflight.md instead (a GGX cuticle of index 1.45, roughness
0.3, over diffuse reflection and transmission: the green blade of that page, whose diffuse
reflection plus transmission, 0.11 0.26 0.06, is about the Phong blade's kd * Cs).

The isotropic models ask for "averageazimuth": the light comes from every azimuth and photons
are stored relative to it, so the map is the isotropic BRDF of the patch rather than one azimuth
of the few blades under the sampling area.

With --periodic the ground covers the tile, a blade crossing a tile edge is repeated on the
opposite side, and the RIB asks for periodic tracing with the sampling area equal to the tile.

    python3 ribs/generators/grass.py --model grass > ribs/grass.rib
"""

import argparse
import math
import random
import sys

PRESETS = {
    "v1": dict(width=0.01, height=0.06, alpha=(0.0, 360.0), beta=(0.0, 20.0), iso=1),
    "grass": dict(width=0.008, height=0.03, alpha=(0.0, 360.0), beta=(0.0, 85.0), iso=1),
    "mowed": dict(width=0.008, height=0.03, alpha=(-10.0, 10.0), beta=(0.0, 85.0), iso=0),
}
BLADE_COLOUR = (0.25, 0.55, 0.15)
SOIL_COLOUR = (0.35, 0.25, 0.15)
LEAF_REFLECTANCE = (0.06, 0.14, 0.04)
LEAF_TRANSMITTANCE = (0.05, 0.12, 0.02)


def blade(x, y, alpha, beta, width, height):
    """The four corners of one blade, counter-clockwise seen from its leaning side."""
    a, b = math.radians(alpha), math.radians(beta)
    along = (math.cos(a) * width / 2, math.sin(a) * width / 2, 0.0)
    up = (-math.sin(a) * math.sin(b) * height, math.cos(a) * math.sin(b) * height,
          math.cos(b) * height)
    base0 = (x - along[0], y - along[1], 0.0)
    base1 = (x + along[0], y + along[1], 0.0)
    top1 = tuple(base1[i] + up[i] for i in range(3))
    top0 = tuple(base0[i] + up[i] for i in range(3))
    return [base0, base1, top1, top0]


def blade_optics(args):
    """The blades' BRDFLight attribute: normalised Phong, or with --leaf the leaf optics."""
    if args.leaf:
        return ('  Attribute "brdflight" "string model" "leaf" "float eta" 1.45 '
                '"float roughness" 0.3\n    "color reflectance" [%g %g %g] '
                '"color transmittance" [%g %g %g]\n' % (*LEAF_REFLECTANCE, *LEAF_TRANSMITTANCE))
    return ('  Attribute "brdflight" "float kd" %g "float ks" %g "float exponent" %g\n'
            % (args.kd, args.ks, args.exponent))


def periodic_copies(corners, tile):
    """The blade and its copies shifted by a tile where it sticks out of [-tile/2, tile/2]^2."""
    half = tile / 2
    shifts_x, shifts_y = [0.0], [0.0]
    xs = [p[0] for p in corners]
    ys = [p[1] for p in corners]
    if min(xs) < -half:
        shifts_x.append(tile)
    if max(xs) > half:
        shifts_x.append(-tile)
    if min(ys) < -half:
        shifts_y.append(tile)
    if max(ys) > half:
        shifts_y.append(-tile)
    return [[(p[0] + dx, p[1] + dy, p[2]) for p in corners] for dx in shifts_x for dy in shifts_y]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--model", choices=sorted(PRESETS), default="grass")
    parser.add_argument("--blades", type=int, default=20, help="blades per side of the ground")
    parser.add_argument("--ground", type=float, default=0.5, help="side of the ground square")
    parser.add_argument("--kd", type=float, default=0.5)
    parser.add_argument("--ks", type=float, default=0.5)
    parser.add_argument("--exponent", type=float, default=10.0)
    parser.add_argument("--rays", type=int, default=100000)
    parser.add_argument("--area", type=float, default=0.1)
    parser.add_argument("--seed", type=int, default=1996)
    parser.add_argument("--periodic", action="store_true")
    parser.add_argument("--leaf", action="store_true", help="leaf optics instead of Phong blades")
    parser.add_argument("--texturename", default="grass.pm")
    parser.add_argument("--comment", default="", help="an extra comment line")
    args = parser.parse_args()
    preset = PRESETS[args.model]
    rng = random.Random(args.seed)
    area = args.ground if args.periodic else args.area

    out = sys.stdout
    out.write("# Grass (thesis section 5.3.2, model '%s'), written by ribs/generators/grass.py\n"
              % args.model)
    out.write("# %d x %d blades %g x %g, alpha %g..%g, beta %g..%g degrees, on a %g x %g ground;"
              " seed %d\n" % (args.blades, args.blades, preset["width"], preset["height"],
                              *preset["alpha"], *preset["beta"], args.ground, args.ground,
                              args.seed))
    if args.comment:
        out.write("# %s\n" % args.comment)
    out.write('Option "BRDFLight" "string texturename" "%s" "integer rays" %d "float area" %g '
              '"integer isotropic" %d "integer averageazimuth" %d "integer periodic" %d\n'
              % (args.texturename, args.rays, area, preset["iso"], preset["iso"],
                 int(args.periodic)))
    out.write("WorldBegin\n")
    half = args.ground / 2
    # A periodic tile's ground reaches a little past the tile walls, so that a ray reaching the
    # ground exactly at a wall cannot slip past the polygon's edge.
    ground_half = half * 1.02 if args.periodic else half
    out.write("AttributeBegin  # the ground\n")
    out.write('  Color [%g %g %g]\n  Surface "matte" "Kd" 0.3\n' % SOIL_COLOUR)
    out.write('  Polygon "P" [%g %g 0  %g %g 0  %g %g 0  %g %g 0]\n'
              % (-ground_half, -ground_half, ground_half, -ground_half, ground_half, ground_half,
                 -ground_half, ground_half))
    out.write("AttributeEnd\n")

    polygons = []
    step = args.ground / args.blades
    for j in range(args.blades):
        for i in range(args.blades):
            x = -half + (i + 0.5) * step
            y = -half + (j + 0.5) * step
            alpha = rng.uniform(*preset["alpha"])
            beta = rng.uniform(*preset["beta"])
            corners = blade(x, y, alpha, beta, preset["width"], preset["height"])
            polygons += periodic_copies(corners, args.ground) if args.periodic else [corners]

    out.write("AttributeBegin  # the blades\n")
    out.write('  Color [%g %g %g]\n' % BLADE_COLOUR)
    out.write('  Surface "plastic" "Kd" %g "Ks" %g\n' % (args.kd, args.ks))
    out.write(blade_optics(args))
    out.write("  PointsPolygons [%s]\n" % " ".join("4" for _ in polygons))
    out.write("    [%s]\n" % " ".join(str(k) for k in range(4 * len(polygons))))
    out.write('    "P" [\n')
    for corners in polygons:
        out.write("      %s\n" % "  ".join("%.6f %.6f %.6f" % p for p in corners))
    out.write("    ]\n")
    out.write("AttributeEnd\n")
    out.write("WorldEnd\n")


if __name__ == "__main__":
    main()
