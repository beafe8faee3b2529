#!/usr/bin/env python3
"""End-to-end checks of Procedural and TrimCurve in `gonio render`: a RunProgram sphere lands
where the program put it and is told its bound's raster area; a DelayedReadArchive outside the
viewing frustum is never read (a broken archive gives no error) and inside it is, unless a ray
reaches its bound: an archive seen only in a mirror, and archives nested in it, are read and
render as the same RIB inline does, whatever the number of threads, as does one out of view that
casts a shadow into it (reached by shadow rays only), while one behind the camera
that no ray reaches is never opened (a file that does not exist gives no error); procedurals
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


# A mirror facing the camera at 45°, in the plane x = −z: camera rays (along +z) leave it along
# −x, towards x = −6, far outside the view (|x| <= 2). What lies there is seen only in the mirror,
# as if at (−z, y, 6).
MIRROR = """Color 1 1 1
Surface "mattemirror" "Kd" 0 "Kr" 1
Polygon "P" [-1 -1 1  1 -1 -1  1 1 -1  -1 1 1]
Surface "constant"
"""
RED_BALL = "Color 1 0 0\nTranslate -6 0 -0.6\nSphere 0.5 -0.5 0.5 360\n"
GREEN_BALL = "Color 0 1 0\nTranslate -6 0 0.6\nSphere 0.4 -0.4 0.4 360\n"
INNER = 'Procedural "DelayedReadArchive" ["inner.rib"] [-6.5 -5.5 -0.5 0.5 0.1 1.1]\n'
OUTER = 'Procedural "DelayedReadArchive" ["outer.rib"] [-7 -5 -1 1 -1.2 1.2]\n'
# Behind the camera (at z = −5 looking along +z) and in no reflected ray's way.
UNREACHED = 'Procedural "DelayedReadArchive" ["nothere.rib"] [-1 1 -1 1 -10 -9]\n'


def mirrored_balls(image):
    """The red and green of the pixels nearest where the balls' reflections are centred."""
    # ortho(): 32 pixels a unit, x = 0 at column 64; the reflections centre on x = 0.6 and −0.6.
    red = image.pixels[(64 + 19, 64)]
    green = image.pixels[(64 - 19, 64)]
    return red[0], green[1]


def check_archives_seen_in_a_mirror_are_read(ws):
    write(ws, "outer.rib", f"AttributeBegin\n{RED_BALL}AttributeEnd\n{INNER}")
    write(ws, "inner.rib", GREEN_BALL)
    inline = (f"AttributeBegin\nAttributeBegin\n{RED_BALL}AttributeEnd\n"
              f"AttributeBegin\n{GREEN_BALL}AttributeEnd\nAttributeEnd\n")
    ws.render(frame("inline.tif", MIRROR + inline), "inline")
    for threads in ("1", "4"):
        proc = ws.render(frame(f"lazy{threads}.tif", MIRROR + OUTER + UNREACHED),
                         f"lazy{threads}", args=["--threads", threads])
        expect(proc.stderr == "", f"the lazy render said:\n{proc.stderr}")
    inline_image, lazy1, lazy4 = read_images(
        *(ws.path(f) for f in ("inline.tif", "lazy1.tif", "lazy4.tif")))
    red, green = mirrored_balls(inline_image)
    expect(red > 0.9 and green > 0.9, f"the inline balls' reflections are {red}, {green}")
    for image, what in ((lazy1, "1 thread"), (lazy4, "4 threads")):
        expect(image.pixels == inline_image.pixels,
               f"with {what} the lazy archives render otherwise than inline: reflections "
               f"{mirrored_balls(image)}")



# A plane in view lit by a point light out of view, with a ball between them that is out of view
# too: only a shadow ray reaches the ball's archive, and its shadow falls round the origin.
SHADOWED = """Attribute "light" "shadows" "on"
LightSource "pointlight" 1 "from" [-8 0 -4] "intensity" [60]
Surface "matte"
Polygon "P" [-2 -2 0  2 -2 0  2 2 0  -2 2 0]
"""
BALL = "Translate -4 0 -2\nSphere 0.5 -0.5 0.5 360\n"


def check_archive_casting_a_shadow_into_view_is_read(ws):
    write(ws, "ball.rib", BALL)
    ws.render(frame("inline_shadow.tif", f"{SHADOWED}AttributeBegin\n{BALL}AttributeEnd\n"),
              "inline_shadow")
    ws.render(frame("lazy_shadow.tif", SHADOWED +
                    'Procedural "DelayedReadArchive" ["ball.rib"] [-4.5 -3.5 -0.5 0.5 -2.5 -1.5]\n'),
              "lazy_shadow")
    inline_image, lazy = read_images(ws.path("inline_shadow.tif"), ws.path("lazy_shadow.tif"))
    centre, edge = inline_image.pixels[(64, 64)][0], inline_image.pixels[(64, 4)][0]
    expect(centre < 1e-6 < edge, f"the inline ball's shadow: centre {centre}, edge {edge}")
    expect(lazy.pixels == inline_image.pixels, "the lazy ball shadows otherwise than inline: "
           f"centre {lazy.pixels[(64, 64)][0]}")

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
          check_archive_outside_the_frustum_is_not_read, check_archives_seen_in_a_mirror_are_read,
          check_archive_casting_a_shadow_into_view_is_read, check_hanging_program_is_killed,
          check_trimmed_square_is_a_disc, check_bad_trim_curve_is_located]


def main():
    return workspace_main(__doc__.split("\n\n")[0], CHECKS, "gonio_procedural_")


if __name__ == "__main__":
    sys.exit(main())
