#!/usr/bin/env python3
"""End-to-end checks of trace() and of derivatives in `gonio render`, against answers known from
the scenes' geometry:

* a mirror plane at 45 degrees shows a constant-coloured square exactly (bit for bit in a float
  image) at the pixels where the reflected rays meet it, and black elsewhere;
* camera rays and trace() rays both see a white plane through 20 black planes of opacity 0.1
  as 0.9^20 (one layer policy for both; trace() used to stop after 16);
* two facing mirrors that each add 0.1 and reflect half stop at Option "trace" "maxdepth":
  0.1 * (1 + 0.5 + ... + 0.5^maxdepth), for maxdepth 0, 1, 3 and the default 6;
* on a plane seen by an orthographic camera, area(P) is the pixel's world-space area (also on a
  tilted plane: 1/cos), Du(s) = Dv(t) = 1, Dv(s) = Du(t) = 0, du and dv are the pixel's extent
  in u and v (also with the parametrisation turned in the plane), Deriv(s, u) = 1;
* calculatenormal(P) equals N on a sphere (within the forward difference's error);
* bumpy with a ramp texture tilts the normal of a plane by the analytic angle;
* texture() filters over the pixel's footprint: a checkerboard of texels far smaller than a
  pixel comes out grey, not aliased;
* the renders are identical with 1 and 2 threads;
* `--stats` counts the trace() rays of a mirror, the shadow rays of a lit plane and the rays of
  occlusion() exactly, and the same with 1 and 2 threads.

    trace_checks.py --gonio build/bin/gonio [NAME ...]

All frames go into one RIB file and one `gonio render`; images are read with one
`oiiotool --dumpdata` (each OIIO process takes most of a second to start)."""

import argparse
import math
import os
import re
import struct
import subprocess
import sys
import tempfile

from analytic_checks import expect, read_images, render_in_folder, run_checks

SHADERS = {
    "mirror.sl": """
surface mirror(float Kr = 1, Ke = 0) {
    Ci = Ke + Kr * trace(P, reflect(I, normalize(N)));
    Oi = 1;
}
""",
    "derivs.sl": """
surface derivs(float mode = 0) {
    if (mode == 0) Ci = color(area(P) * 256, Du(s), Dv(t));
    else if (mode == 1) Ci = color(Dv(s), Du(t), Deriv(s, u));
    else if (mode == 2) Ci = color(du * 48, dv * 48, 0);
    else Ci = color(normalize(calculatenormal(P)) . normalize(N), 0, 0);
    Oi = 1;
}
""",
    # bumpy and paintedplastic with s and t named: texture(name) without coordinates finds no
    # s and t in a shader that never names them (a shaderlang limitation, see README.md).
    "bump.sl": """
displacement bump(float Km = 1; string texturename = "") {
    P += Km * float texture(texturename, s, t) * normalize(N);
    N = calculatenormal(P);
}
""",
    "showtexture.sl": """
surface showtexture(string texturename = "") {
    Ci = float texture(texturename, s, t);
    Oi = 1;
}
""",
    "occluded.sl": """
surface occluded() {
    Ci = occlusion(P, normalize(N), 16);
    Oi = 1;
}
""",
    "shownormal.sl": """
surface shownormal() {
    normal n = normalize(N);
    Ci = color(xcomp(n), ycomp(n), zcomp(n));
    Oi = 1;
}
""",
}

# 64x64 pixels over [-2, 2]^2 (0.0625 world units a pixel), orthographic, one sample a pixel
# and a box filter, so that each pixel is the value at one point of it.
CAMERA = """Format 64 64 1
Projection "orthographic"
ScreenWindow -2 2 -2 2
PixelSamples 1 1
PixelFilter "box" 1 1
Quantize "rgba" 0 0 0 0
"""
PIXEL = 4 / 64
# A bilinear patch 3 units wide at depth 5: u and s run along x, v and t along y.
PATCH = 'Patch "bilinear" "P" [-1.5 -1.5 0  1.5 -1.5 0  -1.5 1.5 0  1.5 1.5 0]'


def camera_xy(x, y):
    """The camera-space point at the centre of pixel (x, y)."""
    return -2 + (x + 0.5) * PIXEL, 2 - (y + 0.5) * PIXEL


def write_pfm(path, width, height, value):
    """A one-channel float image (PFM, rows bottom to top) with value(x, y) at each texel."""
    with open(path, "wb") as f:
        f.write(b"Pf\n%d %d\n-1.0\n" % (width, height))
        for y in range(height):
            f.write(struct.pack("<%df" % width, *(value(x, y) for x in range(width))))


def make_textures(folder):
    """ramp.tx: texel i holds (i + 0.5) / 256, so that bilinear lookups (and every mip level,
    a box average of a ramp) give exactly s. checker.tx: one-texel black and white squares."""
    write_pfm(os.path.join(folder, "ramp.pfm"), 256, 256, lambda x, y: (x + 0.5) / 256)
    write_pfm(os.path.join(folder, "checker.pfm"), 256, 256, lambda x, y: float((x + y) % 2))
    for name in ("ramp", "checker"):
        subprocess.run(["oiiotool", os.path.join(folder, name + ".pfm"), "-otex",
                        os.path.join(folder, name + ".tx")], check=True, capture_output=True)


# Each frame: (image name, options, world body).
FRAMES = {}


def frame(name, world, options=""):
    FRAMES[name] = (options, world)


# A mirror z = 5 - y, at 45 degrees: it turns the camera rays (+z) to -y.
MIRROR = """Translate 0 0 5
AttributeBegin
  Surface "mirror"
  Polygon "P" [-3 -3 3  3 -3 3  3 3 -3  -3 3 -3]
AttributeEnd
"""
frame("mirror", MIRROR + """AttributeBegin
  Color [0.2 0.6 0.9]
  Surface "constant"
  Polygon "P" [-0.5 -3 0.25  0.5 -3 0.25  0.5 -3 1  -0.5 -3 1]
AttributeEnd""")

# Twenty black planes of opacity 0.1 in front of a white one: what is left of the white is
# 0.9^20, for camera rays (planes across z) and for trace() rays off the mirror above (planes
# across y, parallel to the camera rays), which cross transparent surfaces by one policy.
LAYERS = 20
TRANSPARENT = 'Surface "constant"\nColor [0 0 0]\nOpacity [0.1 0.1 0.1]\n'
frame("camera_layers", "Translate 0 0 5\n" + TRANSPARENT + "".join(
    f'Polygon "P" [-3 -3 {z}  3 -3 {z}  3 3 {z}  -3 3 {z}]\n'
    for z in (0.05 * k for k in range(LAYERS))) +
    'Opacity [1 1 1]\nColor [1 1 1]\nPolygon "P" [-3 -3 2  3 -3 2  3 3 2  -3 3 2]')
frame("trace_layers", MIRROR + "AttributeBegin\n" + TRANSPARENT + "".join(
    f'  Polygon "P" [-3 {y} -3  3 {y} -3  3 {y} 12  -3 {y} 12]\n'
    for y in (-1.05 - 0.05 * k for k in range(LAYERS))) + """  Opacity [1 1 1]
  Color [1 1 1]
  Polygon "P" [-3 -3.5 -3  3 -3.5 -3  3 -3.5 12  -3 -3.5 12]
AttributeEnd""")

FACING_MIRRORS = """Surface "mirror" "uniform float Kr" 0.5 "uniform float Ke" 0.1
Polygon "P" [-30 -30 5  30 -30 5  30 30 5  -30 30 5]
Polygon "P" [-30 -30 -1  -30 30 -1  30 30 -1  30 -30 -1]"""
for depth in (0, 1, 3):
    frame(f"mirrors{depth}", FACING_MIRRORS, f'Option "trace" "maxdepth" [{depth}]')
frame("mirrors_default", FACING_MIRRORS)

for mode in range(3):
    frame(f"patch{mode}", f'Translate 0 0 5\nSurface "derivs" "uniform float mode" {mode}\n{PATCH}')
    # Turned by 30 degrees in its plane, and tilted by 60 degrees out of it.
    frame(f"turned{mode}", f'Translate 0 0 5\nRotate 30 0 0 1\n'
          f'Surface "derivs" "uniform float mode" {mode}\n{PATCH}')
    frame(f"tilted{mode}", f'Translate 0 0 5\nRotate 60 1 0 0\n'
          f'Surface "derivs" "uniform float mode" {mode}\n{PATCH}')
frame("sphere", 'Translate 0 0 5\nSurface "derivs" "uniform float mode" 3\n'
      'Sphere 1.5 -1.5 1.5 360')
frame("bumpy", 'Translate 0 0 5\nDisplacement "bump" "uniform float Km" 1 '
      '"uniform string texturename" "ramp.tx"\nSurface "shownormal"\n' + PATCH)
frame("flat", 'Translate 0 0 5\nSurface "shownormal"\n' + PATCH)
frame("checker", 'Translate 0 0 5\nSurface "showtexture" "uniform string texturename" '
      '"checker.tx"\n' + PATCH)


def scene_text():
    parts = []
    for number, (name, (options, world)) in enumerate(FRAMES.items(), 1):
        parts.append(f'FrameBegin {number}\n{options}\n{CAMERA}'
                     f'Display "{name}.exr" "file" "rgba"\nWorldBegin\n{world}\nWorldEnd\n'
                     f'FrameEnd\n')
    return "".join(parts)


CHECKS = {}


def check(function):
    CHECKS[function.__name__] = function
    return function


class Renders(dict):
    """The pixels of each frame, {(x, y): [values]} by frame name, and where they were rendered,
    for the checks that render again."""

    def __init__(self, pixels, gonio, folder):
        super().__init__(pixels)
        self.gonio, self.folder = gonio, folder


def near(a, b, tol):
    return abs(a - b) <= tol


@check
def mirror_shows_the_reflected_square_exactly(images):
    # Mirror z = 5 - y (normal (0, -1, -1)/sqrt 2) turns the camera rays (+z) to -y; the ray
    # from camera (x, y) meets the plane y = -3 at z = 5 - y, so it sees the square
    # (|x| <= 0.5, 0.25 <= 5 - z <= 1) exactly when |x| <= 0.5 and -1 <= y <= -0.25.
    image, inside, outside = images["mirror"], 0, 0
    for (x, y), value in image.items():
        cx, cy = camera_xy(x, y)
        margin = PIXEL  # the sample lies anywhere in the pixel
        if abs(cx) <= 0.5 - margin and -1 + margin <= cy <= -0.25 - margin:
            expect(value[:3] == [0.2, 0.6, 0.9] or all(
                near(v, e, 1e-6) for v, e in zip(value, (0.2, 0.6, 0.9))),
                f"pixel {x},{y} sees the reflected square as {value[:3]}, not 0.2 0.6 0.9")
            inside += 1
        elif abs(cx) >= 0.5 + margin or cy >= -0.25 + margin or cy <= -1 - margin:
            expect(value[:3] == [0, 0, 0], f"pixel {x},{y} should reflect nothing: {value[:3]}")
            outside += 1
    expect(inside > 100 and outside > 3000, f"{inside} inside, {outside} outside pixels")


@check
def facing_mirrors_stop_at_the_trace_depth(images):
    for name, depth in (("mirrors0", 0), ("mirrors1", 1), ("mirrors3", 3),
                        ("mirrors_default", 6)):
        expected = 0.1 * (1 - 0.5 ** (depth + 1)) / 0.5
        for (x, y), value in images[name].items():
            expect(near(value[0], expected, 1e-6),
                   f"{name}: pixel {x},{y} is {value[0]}, not 0.1*(1+...+0.5^{depth}) = "
                   f"{expected}")


@check
def camera_and_trace_rays_cross_the_same_layers(images):
    expected = 0.9 ** LAYERS
    seen = 0
    for name in ("camera_layers", "trace_layers"):
        for (x, y), value in images[name].items():
            cx, cy = camera_xy(x, y)
            # trace_layers: rays reflected below y = -1 miss some of the planes.
            if name == "trace_layers" and not -0.9 <= cy <= 1.9:
                continue
            expect(near(value[0], expected, 1e-5),
                   f"{name}: pixel {x},{y} is {value[0]}, not 0.9^{LAYERS} = {expected}")
            seen += 1
    expect(seen > 64 * 64, f"only {seen} pixels checked")


def interior(image, margin_pixels=2, half_width=1.5):
    """Pixels of the patch at least margin_pixels inside its screen-space square."""
    for (x, y), value in image.items():
        cx, cy = camera_xy(x, y)
        if max(abs(cx), abs(cy)) < half_width - margin_pixels * PIXEL:
            yield (x, y), value


@check
def area_is_the_pixel_footprint(images):
    # area(P) * 256: the pixel's area 0.0625^2 = 1/256 facing the camera; 1/cos 60 = 2 tilted.
    for name, expected, half in (("patch0", 1, 1.5), ("turned0", 1, 1.0), ("tilted0", 2, 0.7)):
        count = 0
        for (x, y), value in interior(images[name], half_width=half):
            expect(near(value[0], expected, 1e-3 * expected),
                   f"{name}: area(P)*256 at pixel {x},{y} is {value[0]}, not {expected}")
            count += 1
        expect(count > 100, f"{name}: only {count} pixels checked")


@check
def du_dv_deriv_match_the_parametrisation(images):
    # s = u, t = v: Du(s) = Dv(t) = 1 and Dv(s) = Du(t) = 0 however the patch is turned or
    # tilted (the renderer solves for them from the pixel neighbours' steps in u and v).
    for name, half in (("patch", 1.5), ("turned", 1.0), ("tilted", 0.7)):
        for (x, y), value in interior(images[name + "0"], half_width=half):
            expect(near(value[1], 1, 1e-3) and near(value[2], 1, 1e-3),
                   f"{name}: Du(s), Dv(t) at pixel {x},{y} are {value[1:3]}, not 1")
        for (x, y), value in interior(images[name + "1"], half_width=half):
            expect(near(value[0], 0, 1e-3) and near(value[1], 0, 1e-3),
                   f"{name}: Dv(s), Du(t) at pixel {x},{y} are {value[:2]}, not 0")
            expect(near(value[2], 1, 1e-3), f"{name}: Deriv(s, u) at {x},{y} is {value[2]}")


@check
def du_dv_are_the_pixel_extent_in_u_and_v(images):
    # du * 48: one pixel is 1/48 of the patch's width 3. Turned by 30 degrees, the pixel's
    # square spans cos 30 + sin 30 of that in u and in v; tilted by 60 degrees about x, it
    # spans twice that in v.
    c, s = math.cos(math.radians(30)), math.sin(math.radians(30))
    for name, half, du, dv in (("patch2", 1.5, 1, 1), ("turned2", 1.0, c + s, c + s),
                               ("tilted2", 0.7, 1, 2)):
        for (x, y), value in interior(images[name], half_width=half):
            expect(near(value[0], du, 2e-3) and near(value[1], dv, 2e-3),
                   f"{name}: du*48, dv*48 at pixel {x},{y} are {value[:2]}, not {du}, {dv}")


@check
def calculatenormal_is_the_normal_of_a_sphere(images):
    # A forward difference across a pixel turns the normal by half the pixel's arc: within
    # 3.3 degrees up to 1.2 of the radius 1.5; nowhere flipped or zero.
    worst_inner, covered = 1.0, 0
    for (x, y), value in images["sphere"].items():
        if value[3] == 0:
            continue
        covered += 1
        r = math.hypot(*camera_xy(x, y))
        expect(value[0] > 0.9, f"calculatenormal.N at pixel {x},{y} (r {r:.3f}) is {value[0]}")
        if r < 1.2:
            worst_inner = min(worst_inner, value[0])
    expect(worst_inner >= 0.998, f"calculatenormal.N is {worst_inner} within r < 1.2")
    expect(covered > 1500, f"the sphere covers only {covered} pixels")


@check
def bumpy_tilts_the_normal_of_a_plane(images):
    # P' = P + s*N with s = u: Du(P') = (3, 0, n), Dv(P') = (0, 3, 0) for N = (0, 0, n), so
    # N' = (-3, 0, 9 n) / sqrt(90); without the displacement N stays (0, 0, n).
    for (x, y), value in interior(images["bumpy"], margin_pixels=3):
        n = math.copysign(1, value[2])
        expected = (-3 / math.sqrt(90), 0, 9 * n / math.sqrt(90))
        expect(all(near(v, e, 2e-3) for v, e in zip(value, expected)),
               f"bumpy: N at pixel {x},{y} is {value[:3]}, not {expected}")
    for (x, y), value in interior(images["flat"]):
        expect(near(abs(value[2]), 1, 1e-6), f"flat: N at pixel {x},{y} is {value[:3]}")


@check
def texture_filters_over_the_pixel_footprint(images):
    # 256 one-texel checks over 48 pixels: 5.3 texels a pixel, so a filtered lookup is grey
    # (a point sample would be 0 or 1).
    values = [value[0] for _, value in interior(images["checker"], margin_pixels=3)]
    expect(values and min(values) > 0.35 and max(values) < 0.65,
           f"the filtered checkerboard ranges over [{min(values)}, {max(values)}], not ~0.5")


@check
def thread_counts_agree(renders):
    gonio, folder = renders.gonio, renders.folder
    outputs = []
    for threads in (1, 2):
        out = os.path.join(folder, f"threads{threads}.exr")
        scene = os.path.join(folder, f"threads{threads}.rib")
        with open(scene, "w") as f:
            f.write(f'Format 48 48 1\nPixelSamples 2 2\nProjection "perspective" "fov" 60\n'
                    f'Display "{out}" "file" "rgba"\nQuantize "rgba" 0 0 0 0\nWorldBegin\n'
                    f'{FRAMES["mirror"][1]}\nAttributeBegin\nSurface "derivs" '
                    f'"uniform float mode" 3\nTranslate 0.8 0.8 5\nSphere 0.5 -0.5 0.5 360\n'
                    f'AttributeEnd\nWorldEnd\n')
        proc = subprocess.run([gonio, "render", "--threads", str(threads), scene], cwd=folder,
                              capture_output=True, text=True)
        expect(proc.returncode == 0, f"gonio render --threads {threads}: {proc.stderr}")
        outputs.append(out)
    # The pixels, not the files: a file's header has the time it was written.
    one, two = (image.pixels for image in read_images(*outputs))
    differ = sum(1 for xy in one if one[xy] != two[xy])
    expect(differ == 0, f"renders with 1 and 2 threads differ in {differ} pixels")


def ray_stats(renders, name, world, options="", threads=1):
    """Renders `world` alone with --stats (on `threads` threads, CAMERA then `options`, every
    sample shaded) and returns its "frame" line's numbers: (camera rays, rays traced, {kind: rays})."""
    folder = renders.folder
    scene = os.path.join(folder, f"{name}.rib")
    with open(scene, "w") as f:
        f.write(f'{CAMERA}{options}\nDisplay "{name}.exr" "file" "rgba"\nWorldBegin\n'
                f'ShadingRate 0.0625\n{world}\nWorldEnd\n')
    proc = subprocess.run([renders.gonio, "render", "--stats", "--threads", str(threads), scene],
                          cwd=folder, capture_output=True, text=True)
    expect(proc.returncode == 0, f"gonio render --stats {name}: {proc.stderr}")
    match = re.search(r"(\d+) camera rays, (\d+) rays traced(?: \(([^)]*)\))?", proc.stderr)
    expect(match is not None, f"no ray statistics in: {proc.stderr}")
    kinds = {}
    for part in (match.group(3) or "").split(", "):
        if part:
            count, kind = part.split(" ")
            kinds[kind] = int(count)
    return int(match.group(1)), int(match.group(2)), kinds


@check
def stats_count_traced_and_shadow_rays(renders):
    # 64x64 pixels, one sample each (CAMERA), every camera ray hits the opaque mirror: one
    # camera ray and one trace() ray a pixel, whether the reflected ray meets the square or
    # escapes (an opaque hit ends it; no surface lies behind the mirror's rays).
    samples = 64 * 64
    cameras, total, kinds = ray_stats(renders, "stats_mirror", FRAMES["mirror"][1])
    expect(cameras == samples, f"{cameras} camera rays, not {samples}")
    expect(kinds == {"camera": samples, "trace": samples} and total == 2 * samples,
           f"the mirror traced {total} rays {kinds}, not {samples} camera + {samples} trace")
    # An opaque plane filling the frame, lit by one shadowed point light in front of it: with
    # 4x4 samples a pixel and ShadingRate 1/16 every sample is shaded, and each shaded point
    # sends one shadow ray (no shadow caster is partly transparent, so no ray goes further).
    samples = 64 * 64 * 16
    plane = ('Attribute "light" "shadows" "on"\nLightSource "pointlight" 1 "from" [0 0 2]\n'
             'Surface "matte"\nPolygon "P" [-3 -3 5  3 -3 5  3 3 5  -3 3 5]')
    cameras, total, kinds = ray_stats(renders, "stats_shadows", plane, "PixelSamples 4 4")
    expect(kinds == {"camera": samples, "shadow": samples} and total == 2 * samples,
           f"the lit plane traced {total} rays {kinds}, not {samples} camera + {samples} shadow")
    # Each worker counts its own rays; the sum must not depend on how tiles met threads.
    two = ray_stats(renders, "stats_shadows2", plane, "PixelSamples 4 4", threads=2)
    expect(two == (cameras, total, kinds), f"with 2 threads {two}, with 1 {kinds}")
    # occlusion() with 16 samples at every shaded point of the plane: 16 sampled rays each.
    samples = 64 * 64
    cameras, total, kinds = ray_stats(renders, "stats_occlusion",
                                      'Surface "occluded"\nPolygon "P" [-3 -3 5  3 -3 5  3 3 5  '
                                      '-3 3 5]')
    expect(kinds == {"camera": samples, "sampled": 16 * samples},
           f"occlusion() traced {kinds}, not {samples} camera + {16 * samples} sampled")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--gonio", required=True)
    parser.add_argument("names", nargs="*", help="checks to run (default: all)")
    args = parser.parse_args()
    unknown = [name for name in args.names if name not in CHECKS]
    if unknown:
        parser.error(f"unknown checks {unknown}; the checks are {list(CHECKS)}")
    gonio = os.path.abspath(args.gonio)
    with tempfile.TemporaryDirectory(prefix="gonio_trace_") as folder:
        make_textures(folder)
        failure = render_in_folder(gonio, folder, SHADERS, scene_text())
        if failure:
            print(failure)
            return 1
        paths = [os.path.join(folder, name + ".exr") for name in FRAMES]
        pixels = {name: image.pixels for name, image in zip(FRAMES, read_images(*paths))}
        checks = [CHECKS[name] for name in args.names or CHECKS]
        return run_checks(checks, Renders(pixels, gonio, folder))


if __name__ == "__main__":
    sys.exit(main())
