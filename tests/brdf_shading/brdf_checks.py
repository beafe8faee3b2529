#!/usr/bin/env python3
"""Exact checks of the brdf() shading builtin (issue 6), end to end: a micro model is photon
traced with BRDFLight, optimised with `gonio brdf iopt`/`opt`, and the .grd is used by
shaders/brdfsurface.sl in a render that is compared with the analytic BRDF the micro model
stands for.

    brdf_checks.py --gonio build/bin/gonio [--keep] [NAME ...]

* lambert: the Lambert plane (ribs/lambert_plane.rib, baked table) renders within 2% of
  kd/π·(N·L) under the same two lights, pixel by pixel (relative to each pixel).
* phong: the Phong plane (ribs/phong_plane.rib, grid without a baked table: a table of 32 θ
  nodes is too coarse for an exponent-25 lobe) renders within 2% of the analytic normalised
  Phong, pixel by pixel, relative to the highlight's peak (the splat estimator blurs the lobe;
  away from the lobe the values are small and their relative error large).
* rotation: turning D by 90° about N turns the image of an anisotropic BRDF (brushed metal,
  seen and lit straight from above) by 90°, while the image itself is not symmetric under that
  turn; the isotropic Lambert grid gives the same image for any D.
* missing: a missing .grd is one error, with the shader's file and line; the frame is not
  written and the render exits 1.

The photon counts restrict the incidence to a band around the lights (BRDFLight's thetamin and
thetamax) so that a few seconds of tracing give the estimator enough photons there."""

import argparse
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "tests", "render"))
# One oiiotool call reads every image; checks fail by raising CheckFailed.
from analytic_checks import (CheckFailed, EVERY_SAMPLE_SHADED, Workspace, expect,  # noqa: E402
                             read_images)


def measured_grid(ws, model, rays, theta_range, optimiser, out):
    """Photon-traces ribs/`model`.rib with `rays` paths in the incidence band `theta_range`
    (degrees) and optimises the map with `optimiser` (the opt/iopt arguments before the files)
    into grids/`out`."""
    with open(os.path.join(ROOT, "ribs", model + ".rib")) as f:
        rib = f.read()
    rib, count = re.subn(r'"integer rays" \d+',
                         f'"integer rays" {rays} "float thetamin" {theta_range[0]} '
                         f'"float thetamax" {theta_range[1]}', rib)
    expect(count == 1, f"ribs/{model}.rib has no \"integer rays\" to override")
    ws.render(rib, model, ["-o", model + ".pm"])
    os.makedirs(ws.path("grids"), exist_ok=True)
    ws.run(["brdf", *optimiser, model + ".pm", os.path.join("grids", out)])
    os.remove(ws.path(model + ".pm"))


def look_at(eye, target, up=(0.0, 1.0, 0.0)):
    """The RIB camera transform (world to RenderMan's left-handed camera space) of a camera at
    `eye` looking at `target`."""
    def sub(a, b):
        return [x - y for x, y in zip(a, b)]

    def unit(a):
        n = math.sqrt(sum(x * x for x in a))
        return [x / n for x in a]

    def cross(a, b):
        return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]

    def dot(a, b):
        return sum(x * y for x, y in zip(a, b))

    forward = unit(sub(target, eye))
    right = unit(cross(forward, up))
    upward = cross(right, forward)
    axes = [right, upward, forward]
    # Row vectors: p_camera = p_world · M, so M's columns are the camera axes in world space.
    m = [[axes[c][r] for c in range(3)] + [0.0] for r in range(3)]
    m.append([-dot(axes[c], eye) for c in range(3)] + [1.0])
    return "Transform [" + " ".join(f"{v:.9g}" for row in m for v in row) + "]\n"


def distant(theta, phi, intensity=1.0):
    """A distantlight whose light arrives from the direction (θ, φ) in degrees."""
    t, p = math.radians(theta), math.radians(phi)
    frm = (math.sin(t) * math.cos(p), math.sin(t) * math.sin(p), math.cos(t))
    return (f'LightSource "distantlight" {{}} "intensity" {intensity} '
            f'"from" [{frm[0]:.9g} {frm[1]:.9g} {frm[2]:.9g}] "to" [0 0 0]\n')


def frames(surfaces, camera, lights, size=48, fov=30):
    """One RIB with a frame per (image name, Surface line): a large plane z = 0 that fills the
    view, float RGBA output."""
    light_lines = "".join(light.replace("{}", str(i + 1)) for i, light in enumerate(lights))
    out = ('Option "searchpath" "shader" ["' + os.path.join(HERE, "shaders") + ':@"]\n'
           'Option "searchpath" "texture" ["grids"]\n')
    for number, (name, surface) in enumerate(surfaces, start=1):
        out += (f"FrameBegin {number}\n"
                f'Display "{name}.tif" "tiff" "rgba"\nQuantize "rgba" 0 0 0 0\n'
                f'Format {size} {size} 1\nPixelSamples 2 2\nPixelFilter "box" 1 1\n'
                f"{EVERY_SAMPLE_SHADED}"
                f'Projection "perspective" "fov" {fov}\n{camera}'
                f"WorldBegin\n{light_lines}{surface}\n"
                'Polygon "P" [-20 -20 0  20 -20 0  20 20 0  -20 20 0]\n'
                "WorldEnd\nFrameEnd\n")
    return out


def compare(measured, reference, tolerance, relative_to_peak, what):
    peak = max(p[0] for p in reference.pixels.values())
    expect(peak > 0, f"{what}: the reference image is black")
    worst, where = 0.0, None
    for xy, want in reference.pixels.items():
        got = measured.pixels[xy]
        scale = peak if relative_to_peak else want[0]
        if scale <= 0:
            continue
        for c in range(3):
            error = abs(got[c] - want[c]) / scale
            if error > worst:
                worst, where = error, (xy, c, got[c], want[c])
    expect(worst <= tolerance,
           f"{what}: pixel {where[0]} channel {where[1]} is {where[2]:.5f}, analytic "
           f"{where[3]:.5f}: error {100 * worst:.2f}% > {100 * tolerance:.0f}%")
    return worst


def check_lambert(ws):
    measured_grid(ws, "lambert_plane", 400000, (15, 75),
                  ["iopt", "6", "24", "0.4", "0", "--bake", "16"], "lambert.grd")
    camera = look_at((0.0, 0.0, 4.0), (0.0, 0.0, 0.0))
    lights = [distant(45, 0), distant(40, 130, 0.6)]
    ws.render(frames(
        [("lambert_brdf", 'Surface "brdfsurface" "string grid" "lambert.grd"'),
         ("lambert_ref", 'Surface "lambertref" "float Kd" 1')], camera, lights))
    measured, reference = read_images(ws.path("lambert_brdf.tif"), ws.path("lambert_ref.tif"))
    worst = compare(measured, reference, 0.02, False, "Lambert plane")
    return f"worst pixel {100 * worst:.2f}% of its analytic value"


def check_phong(ws):
    measured_grid(ws, "phong_plane", 5000000, (42, 48),
                  ["iopt", "9", "96", "0.05", "0"], "phong.grd")
    # The viewer near the light's mirror direction (θ = 45°, φ = 180°), so the lobe fills the
    # view.
    camera = look_at((-3.0, 0.0, 3.0), (0.0, 0.0, 0.0), (0.0, 0.0, 1.0))
    ws.render(frames(
        [("phong_brdf", 'Surface "brdfsurface" "string grid" "phong.grd"'),
         ("phong_ref", 'Surface "phongref" "float Ks" 1 "float exponent" 25')], camera, [distant(45, 0)]))
    measured, reference = read_images(ws.path("phong_brdf.tif"), ws.path("phong_ref.tif"))
    worst = compare(measured, reference, 0.02, True, "Phong plane")
    return f"worst pixel {100 * worst:.2f}% of the peak"


def rotated90(image):
    """Pixel (x, y) of the image turned by 90° about its centre (square images)."""
    n = image.width
    return {(n - 1 - y, x): value for (x, y), value in image.pixels.items()}


def image_difference(a_pixels, b_pixels):
    peak = max(v[0] for v in b_pixels.values())
    return max(abs(a_pixels[xy][0] - b_pixels[xy][0]) for xy in b_pixels) / peak


def check_rotation(ws):
    measured_grid(ws, "brushed_metal", 200000, (0, 35),
                  ["opt", "5", "5", "0.4", "0"], "brushed.grd")
    if not os.path.exists(ws.path("grids/lambert.grd")):
        check_lambert(ws)
    # Seen and lit from straight above, so a turn of D about N is a turn of the whole picture.
    camera = look_at((0.0, 0.0, 3.0), (0.0, 0.0, 0.0))
    lights = ['LightSource "pointlight" {} "intensity" 9 "from" [0 0 3]\n']

    def along(grid, x, y):
        return (f'Surface "brdfsurface" "string grid" "{grid}" "string orientation" "direction" '
                f'"vector direction" [{x} {y} 0]')

    ws.render(frames(
        [("brushed_x", along("brushed.grd", 1, 0)), ("brushed_y", along("brushed.grd", 0, 1)),
         ("lambert_x", along("lambert.grd", 1, 0)), ("lambert_y", along("lambert.grd", 0, 1))],
        camera, lights, fov=60))
    bx, by, lx, ly = read_images(*[ws.path(n + ".tif") for n in
                                   ("brushed_x", "brushed_y", "lambert_x", "lambert_y")])
    turned = rotated90(bx)
    asymmetry = image_difference(turned, bx.pixels)
    expect(asymmetry > 0.2,
           f"the brushed-metal image is nearly symmetric under a 90° turn ({asymmetry:.3f} of "
           "its peak): the check could not see a turn")
    # Which way the picture turns depends on the screen's handedness: accept either turn.
    other_way = {(x, y): v for (x, y), v in
                 {(bx.width - 1 - x, bx.width - 1 - y): v for (x, y), v in turned.items()}.items()}
    difference = min(image_difference(turned, by.pixels), image_difference(other_way, by.pixels))
    expect(difference < 0.05,
           f"turning D by 90° did not turn the brushed-metal image: it differs from the turned "
           f"image by {difference:.3f} of its peak")
    same = image_difference(lx.pixels, ly.pixels)
    expect(same < 1e-6, f"the isotropic Lambert grid depends on D ({same:.2e} of its peak)")
    return f"turned image within {100 * difference:.2f}% of the peak, asymmetry {asymmetry:.2f}"


def check_missing(ws):
    rib = frames([("missing", 'Surface "brdfsurface" "string grid" "no_such.grd"')],
                 look_at((0.0, 0.0, 4.0), (0.0, 0.0, 0.0)), [distant(30, 0)], size=16)
    proc = ws.render(rib, "missing", expect_code=1)
    lines = [line for line in proc.stderr.splitlines() if "no_such.grd" in line]
    expect(len(lines) == 1, f"expected one message about no_such.grd, got:\n{proc.stderr}")
    expect(re.search(r"brdf_lighting\.h:\d+: error: ", lines[0]) is not None,
           f"the error does not name the shader's file and line: {lines[0]}")
    expect(not os.path.exists(ws.path("missing.tif")),
           "a frame whose grid is missing was written (shaded black)")
    return "one error, no image: " + lines[0]


CHECKS = {"lambert": check_lambert, "phong": check_phong, "rotation": check_rotation,
          "missing": check_missing}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--gonio", required=True)
    parser.add_argument("--keep", action="store_true", help="keep the scratch folder")
    parser.add_argument("names", nargs="*", help="checks to run (default: all)")
    args = parser.parse_args()
    directory = tempfile.mkdtemp(prefix="brdf_checks_")
    ws = Workspace(os.path.abspath(args.gonio), directory)  # scenes in a folder below it
    failures = 0
    for name in args.names or CHECKS:
        try:
            print(f"PASS {name}: {CHECKS[name](ws)}", flush=True)
        except CheckFailed as e:
            failures += 1
            print(f"FAIL {name}: {e}", flush=True)
    if args.keep:
        print(f"scratch files kept in {directory}")
    else:
        shutil.rmtree(directory)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
