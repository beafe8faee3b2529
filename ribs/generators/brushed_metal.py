#!/usr/bin/env python3
"""Writes the brushed-metal micro geometry of thesis §5.2 as RIB.

N parallel cylinders (default 50) lie along the y axis on the base plane z = 0 and overlap by 50%:
neighbouring axes are one radius apart, so cylinder n touches cylinder n + 2. The visible surface
is a row of circular arcs of +-30 degrees meeting in cusps. The micro BRDF is a perfectly
specular normalised Phong lobe (kd = 0, ks = 1, exponent 25) unless --kd/--ks/--exponent say
otherwise. The sampling area (default 0.1) covers the central cylinders; the cylinders are much
longer than the area is wide, and disks close their ends so that no photon is caught inside a
mirror tube.

    python3 ribs/generators/brushed_metal.py > ribs/brushed_metal.rib
"""

import argparse
import sys


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cylinders", type=int, default=50)
    parser.add_argument("--radius", type=float, default=0.01)
    parser.add_argument("--length", type=float, default=0.5, help="along the axes (y)")
    parser.add_argument("--kd", type=float, default=0.0)
    parser.add_argument("--ks", type=float, default=1.0)
    parser.add_argument("--exponent", type=float, default=25.0)
    parser.add_argument("--rays", type=int, default=300000)
    parser.add_argument("--area", type=float, default=0.1)
    parser.add_argument("--texturename", default="brushed_metal.pm")
    args = parser.parse_args()

    out = sys.stdout
    out.write("# Brushed metal (thesis section 5.2), written by ribs/generators/brushed_metal.py\n")
    out.write("# %d cylinders of radius %g along y, axes %g apart (50%% overlap), anisotropic.\n"
              % (args.cylinders, args.radius, args.radius))
    out.write('Option "BRDFLight" "string texturename" "%s" "integer rays" %d "float area" %g '
              '"integer isotropic" 0\n' % (args.texturename, args.rays, args.area))
    out.write("WorldBegin\n")
    out.write('Surface "metal" "Ks" %g\n' % args.ks)
    out.write('Attribute "brdflight" "float kd" %g "float ks" %g "float exponent" %g\n'
              % (args.kd, args.ks, args.exponent))
    half = args.length / 2
    first = -(args.cylinders - 1) / 2 * args.radius
    for n in range(args.cylinders):
        out.write("TransformBegin\n")
        out.write("  Translate %.6f 0 0\n" % (first + n * args.radius))
        out.write("  Rotate 90 1 0 0\n")
        out.write("  Cylinder %g %g %g 360\n" % (args.radius, -half, half))
        out.write("  Disk %g %g 360\n  Disk %g %g 360\n" % (-half, args.radius, half, args.radius))
        out.write("TransformEnd\n")
    out.write("WorldEnd\n")


if __name__ == "__main__":
    main()
