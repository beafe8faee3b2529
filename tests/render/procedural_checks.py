#!/usr/bin/env python3
"""End-to-end checks of Procedural and TrimCurve in `gonio render`: a RunProgram sphere lands
where the program put it and is told its bound's raster area; a DelayedReadArchive outside the
viewing frustum is never read (a broken archive gives no error) and inside it is; procedurals
nest and leave the graphics state as they found it; a hanging program is killed after
Option "limits" "proceduraltimeout"; a NuPatch square trimmed by a circle covers the disc's
analytic area, and with an outer loop the square minus the disc.

    procedural_checks.py --gonio build/bin/gonio"""

import math
import os
import sys
import time

from analytic_checks import expect, expect_close, float_tiff, ortho, read_images, workspace_main

PIXELS_PER_UNIT = 32  # ortho(): 128 pixels over ScreenWindow -2 2
SPHERE_AREA = math.pi * 0.25  # a sphere of radius 0.5 seen along z

# A RunProgram program (RISpec App. C.3): for each request "detail data" it writes RIB placing a
# sphere of radius r at x, then 0377; it records the detail it was told.
GENERATOR = r"""#!/usr/bin/env python3
import sys
for line in sys.stdin:
    detail, data = line.rstrip("\n").split(" ", 1)
    x, r = data.split()
    with open("detail.txt", "w") as f:
        f.write(detail)
    sys.stdout.write(f"Translate {x} 0 0\nSphere {r} -{r} {r} 360\n")
    sys.stdout.flush()
    sys.stdout.buffer.write(b"\xff")
    sys.stdout.buffer.flush()
"""

RUN_SPHERE = 'Procedural "RunProgram" ["gen.py" "1 0.5"] [0.5 1.5 -0.5 0.5 -0.5 0.5]\n'


def write(ws, name, text, executable=False):
    with open(ws.path(name), "w") as f:
        f.write(text)
    if executable:
        os.chmod(ws.path(name), 0o755)


def frame(image, world, options=""):
    return f"{float_tiff(image)}{ortho(extra=options)}WorldBegin\n{world}WorldEnd\n"


def coverage_and_centroid(image):
    """The mean alpha and the alpha-weighted centre (x, y) in pixels."""
    total = sum(p[3] for p in image.pixels.values())
    cx = sum((x + 0.5) * p[3] for (x, _), p in image.pixels.items()) / total
    cy = sum((y + 0.5) * p[3] for (_, y), p in image.pixels.items()) / total
    return total / len(image.pixels), cx, cy


def expect_two_spheres(ws, image_name):
    """The program's sphere at x = 1 and the scene's own at the origin: had the program's
    Translate leaked out of the procedural, the second would cover the first."""
    image, = read_images(ws.path(image_name))
    coverage, cx, cy = coverage_and_centroid(image)
    expect_close(coverage, 2 * SPHERE_AREA / 16, 0.02, "coverage of the two spheres")
    # Centres at 96 and 64 pixels from the left.
    expect(abs(cx - 80) < 0.5 and abs(cy - 64) < 0.5, f"centroid ({cx:.2f}, {cy:.2f}), "
           "expected (80, 64)")


def check_run_program_places_its_sphere(ws):
    write(ws, "gen.py", GENERATOR, executable=True)
    ws.render(frame("run.tif", RUN_SPHERE + "Sphere 0.5 -0.5 0.5 360\n"), "run")
    expect_two_spheres(ws, "run.tif")
    # The bound spans 1 x 1 units: 32 x 32 raster pixels.
    with open(ws.path("detail.txt")) as f:
        detail = float(f.read())
    expect_close(detail, PIXELS_PER_UNIT ** 2, 1e-3, "detail the program was told")


def check_nested_procedurals(ws):
    """A DelayedReadArchive whose archive holds the RunProgram procedural."""
    write(ws, "gen.py", GENERATOR, executable=True)
    write(ws, "outer.rib", "Color 1 0 0\n" + RUN_SPHERE)
    ws.render(frame("nested.tif", 'Procedural "DelayedReadArchive" ["outer.rib"] '
                    "[-2 2 -2 2 -2 2]\nSphere 0.5 -0.5 0.5 360\n"), "nested")
    expect_two_spheres(ws, "nested.tif")


def check_archive_outside_the_frustum_is_not_read(ws):
    write(ws, "broken.rib", "Sphere 1 -1\nBogus 3\n")
    outside = ("Procedural \"DelayedReadArchive\" [\"broken.rib\"] [10 11 -0.5 0.5 -0.5 0.5]\n"
               # behind the camera, which looks down +z from z = -5
               "Procedural \"DelayedReadArchive\" [\"broken.rib\"] [-1 1 -1 1 -10 -9]\n")
    proc = ws.render(frame("out.tif", outside), "outside")
    expect("broken.rib" not in proc.stderr, f"an archive out of view was read:\n{proc.stderr}")
    inside = "Procedural \"DelayedReadArchive\" [\"broken.rib\"] [1.5 2.5 -0.5 0.5 -0.5 0.5]\n"
    proc = ws.render(frame("in.tif", inside), "inside", expect_code=1)
    expect("broken.rib:1:1: error: Sphere expects" in proc.stderr and
           "broken.rib:2:1: error: unknown request 'Bogus'" in proc.stderr,
           f"the archive in view was not read, or its errors are not located:\n{proc.stderr}")


def check_hanging_program_is_killed(ws):
    write(ws, "hang.sh", "#!/bin/sh\nread line\nsleep 60\n", executable=True)
    start = time.monotonic()
    proc = ws.render(frame("hang.tif", 'Procedural "RunProgram" ["hang.sh" ""] [-1 1 -1 1 -1 1]\n',
                           'Option "limits" "float proceduraltimeout" [0.5]\n'),
                     "hang", expect_code=1)
    seconds = time.monotonic() - start
    expect("hang.rib:12:1: error: Procedural RunProgram \"hang.sh\" did not finish within 0.5 s"
           in proc.stderr, f"unexpected message:\n{proc.stderr}")
    expect(seconds < 20, f"the render took {seconds:.1f} s")


# A bilinear NuPatch over object-space [-1,1]², (u, v) in [0,1]², in view.
SQUARE = ('NuPatch 2 2 [0 0 1 1] 0 1 2 2 [0 0 1 1] 0 1 '
          '"P" [-1 -1 0 1 -1 0 -1 1 0 1 1 0]\n')


def circle_curve(cx, cy, r):
    """The circle as a rational quadratic NURBS of 9 homogeneous points (u·w, v·w, w) over 4
    spans, the corners weighted √2/2 (The NURBS Book, §7.5)."""
    corners = [(1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1), (0, -1), (1, -1), (1, 0)]
    weights = [1, math.sqrt(0.5)] * 4 + [1]
    u = [(cx + r * px) * w for (px, _), w in zip(corners, weights)]
    v = [(cy + r * py) * w for (_, py), w in zip(corners, weights)]
    knots = [0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1]
    return 3, knots, 0, 1, 9, u, v, weights


def trim_curve(loops):
    """TrimCurve for loops of curves (order, knots, min, max, n, u, v, w)."""
    curves = [c for loop in loops for c in loop]
    def join(k):
        return " ".join(f"{x:.9g}" for c in curves for x in (c[k] if isinstance(c[k], list)
                                                              else [c[k]]))
    counts = " ".join(str(len(loop)) for loop in loops)
    return f"TrimCurve [{counts}] " + " ".join(f"[{join(k)}]" for k in range(8)) + "\n"


def check_trimmed_square_is_a_disc(ws):
    """A circle of radius 0.4 about (0.5, 0.5) in (u, v) is a disc of radius 0.8 on the
    square; the square with an outer loop and the circle as a hole is the rest of it."""
    circle = circle_curve(0.5, 0.5, 0.4)
    outer = (2, [0, 0, 1, 2, 3, 4, 4], 0, 4, 5, [0, 1, 1, 0, 0], [0, 0, 1, 1, 0], [1] * 5)
    disc = frame("disc.tif", trim_curve([[circle]]) + SQUARE)
    holed = frame("holed.tif", trim_curve([[outer], [circle]]) + SQUARE)
    # The trim curves are an attribute: a NuPatch after AttributeEnd is whole again.
    whole = frame("whole.tif", "AttributeBegin\n" + trim_curve([[circle]]) + "AttributeEnd\n" +
                  SQUARE)
    ws.render(disc + holed + whole, "trim")
    images = read_images(ws.path("disc.tif"), ws.path("holed.tif"), ws.path("whole.tif"))
    disc_area = math.pi * 0.8 ** 2
    wants = [disc_area / 16, (4 - disc_area) / 16, 4 / 16]
    # Edge tolerance: the disc's rim (2π·0.8 units, 161 pixels long) may be half a pixel off on
    # either side: 80 of 16384 pixels, 4% of the disc; the polyline loses 0.04% of its area.
    for image, want, what in zip(images, wants, ["disc", "square minus the disc", "square"]):
        coverage, cx, cy = coverage_and_centroid(image)
        expect_close(coverage, want, 0.01, f"coverage of the {what}")
        expect(abs(cx - 64) < 0.5 and abs(cy - 64) < 0.5, f"{what} centred at ({cx}, {cy})")


def check_bad_trim_curve_is_located(ws):
    proc = ws.render(frame("badtrim.tif", "TrimCurve [1] [3] [0 0 0 1 1 1] [0] [1] [3] [0 1] "
                           "[0 0 1] [1 1 1]\n" + SQUARE), "badtrim", expect_code=1)
    expect("badtrim.rib:11:1: error: TrimCurve: u, v and w need 3 values" in proc.stderr,
           f"unexpected message:\n{proc.stderr}")


CHECKS = [check_run_program_places_its_sphere, check_nested_procedurals,
          check_archive_outside_the_frustum_is_not_read, check_hanging_program_is_killed,
          check_trimmed_square_is_a_disc, check_bad_trim_curve_is_located]


def main():
    return workspace_main(__doc__.split("\n\n")[0], CHECKS, "gonio_procedural_")


if __name__ == "__main__":
    sys.exit(main())
