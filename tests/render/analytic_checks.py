#!/usr/bin/env python3
"""End-to-end checks of `gonio render` against answers known without any earlier render:
coverage of analytic shapes, camera mappings, crop windows, depth, exposure, the box filter,
Sides, determinism and seeds, output files, and the exit codes.

    analytic_checks.py --gonio build/bin/gonio [--group analytic|exit|shading] [--known-bugs] [NAME ...]

Images are read with `oiiotool --dumpdata` so the checks need nothing beyond openimageio-tools.
Checks of known renderer bugs run only with --known-bugs (see README.md)."""

import argparse
import concurrent.futures
import math
import os
import re
import subprocess
import sys
import tempfile
import traceback

CHECKS = {}


# Groups whose checks share one batch render, and the --group they belong to. The "shading"
# checks live in shading_checks.py, which imports this module and runs them.
BATCH_GROUPS = {"batch": "analytic", "shading": "shading"}


def check(group, known_bug=None):
    """Registers a check; `known_bug` names the bug that makes it fail today."""
    def register(function):
        CHECKS[function.__name__] = (group, known_bug, function)
        return function
    return register


class CheckFailed(Exception):
    pass


def expect(condition, message):
    if not condition:
        raise CheckFailed(message)


class Image:
    def __init__(self, width, height, channels, data_format, pixels, origin):
        self.width, self.height, self.channels = width, height, channels
        self.format = data_format  # "uint8", "uint16", "half", "float"
        self.pixels = pixels  # {(x, y): [values]} with integer data normalised to [0, 1]
        self.origin = origin  # (x, y) of the data window

    def channel(self, c):
        return [p[c] for p in self.pixels.values()]

    def mean(self, c):
        values = self.channel(c)
        return sum(values) / len(values)


HEADER = re.compile(r"^(\S.*) :\s+(\d+) x\s+(\d+), (\d+) channel, (\w+) ")
PIXEL = re.compile(r"^\s+Pixel \((-?\d+), (-?\d+)\): ([^(]*)(?:\((.*)\))?$")


def read_images(*paths):
    """Reads images with one oiiotool call (each oiiotool start costs most of a second)."""
    proc = subprocess.run(["oiiotool", "--dumpdata", "--info", *paths], capture_output=True,
                          text=True)
    expect(proc.returncode == 0, f"oiiotool could not read {paths}: {proc.stderr}")
    images, current = [], None
    for line in proc.stdout.splitlines():
        if m := HEADER.match(line):
            current = Image(int(m[2]), int(m[3]), int(m[4]), m[5], {}, None)
            images.append(current)
        elif m := PIXEL.match(line):
            values = m[4] if m[4] is not None else m[3]
            xy = (int(m[1]), int(m[2]))
            current.pixels[xy] = [float(v) for v in values.split()]
            if current.origin is None:
                current.origin = xy
    expect(len(images) == len(paths), f"oiiotool read {len(images)} of {len(paths)} images")
    return images


class Workspace:
    """A temporary folder in which scenes are written and rendered."""

    def __init__(self, gonio, root):
        self.gonio = gonio
        self.dir = tempfile.mkdtemp(dir=root)

    def path(self, name):
        return os.path.join(self.dir, name)

    def render(self, rib, name="scene", args=(), expect_code=0):
        scene = self.path(name + ".rib")
        with open(scene, "w") as f:
            f.write(rib)
        return self.run(["render", scene, *args], expect_code)

    def run(self, args, expect_code=0):
        proc = subprocess.run([self.gonio, *args], cwd=self.dir, capture_output=True, text=True)
        if expect_code is not None:
            expect(proc.returncode == expect_code,
                   f"gonio {' '.join(args)} exited with {proc.returncode}, expected "
                   f"{expect_code}:\n{proc.stderr}")
        return proc


class Batch:
    """Collects the frames of every analytic check into one RIB file, so that one `gonio render`
    and one `oiiotool` serve them all (each process start costs most of a second). A check is a
    generator: it adds its frames, yields, then reads its images and asserts."""

    def __init__(self):
        self.frames, self.images = [], {}

    def frame(self, check, name, options, world):
        """Adds a frame whose Display is the float RGBA TIFF `check`_`name`, or the display that
        `options` names when it contains the word Display."""
        display = "" if "Display" in options else float_tiff(f"{check}_{name}.tif")
        self.frames.append(f"FrameBegin {len(self.frames) + 1}\n{display}{options}"
                           f"WorldBegin\n{world}\nWorldEnd\nFrameEnd\n")

    def image(self, check, name):
        return self.images[f"{check}_{name}"]  # the file name without its extension


def float_tiff(name):
    """A float RGBA TIFF display: no quantization, so values are exact."""
    return f'Quantize "rgba" 0 0 0 0\nDisplay "{name}" "tiff" "rgba"\n'


# Shades every camera sample (at up to 4x4 samples), so that a pixel is the mean of the shading
# at its samples, which is what the analytic checks compute; at the default ShadingRate 1 a
# pixel shows the shading of one point near its centre (docs/user-guide.md, "Shading rate").
EVERY_SAMPLE_SHADED = "ShadingRate 0.0625\n"


def ortho(fmt="128 128", window="-2 2 -2 2", extra=""):
    """Options of an orthographic camera 5 units in front of the world origin, box filter,
    every sample shaded."""
    return (f"Format {fmt} 1\nPixelSamples 4 4\nPixelFilter \"box\" 1 1\n{EVERY_SAMPLE_SHADED}"
            f"Projection \"orthographic\"\nScreenWindow {window}\n{extra}Translate 0 0 5\n")


def expect_close(value, target, relative, what):
    expect(abs(value - target) <= relative * abs(target),
           f"{what}: {value:.6f}, expected {target:.6f} within {relative * 100:g}%")


def expect_values(values, want, tolerance, what):
    expect(len(values) == len(want) and all(abs(a - b) <= tolerance for a, b in zip(values, want)),
           f"{what}: {values}, expected {want}")


# ---- coverage and camera (batched: one render for all) ---------------------------------------

@check("batch")
def sphere_covers_pi_over_16(b, me):
    """An orthographic unit sphere in ScreenWindow [-2,2]² covers π/16 of the frame."""
    b.frame(me, "a", ortho(), "Sphere 1 -1 1 360")
    yield
    expect_close(b.image(me, "a").mean(3), math.pi / 16, 0.01, "mean alpha of the sphere")


@check("batch")
def partial_sweeps_cover_their_fraction(b, me):
    """Disk 0 1 90 covers a quarter of the unit disk; Sphere r -r r 180 seen along z half."""
    world = ("AttributeBegin\nTranslate -1 0 0\nDisk 0 1 90\nAttributeEnd\n"
             "Translate 1 0 0\nRotate 90 0 0 1\nSphere 0.9 -0.9 0.9 180\n")
    b.frame(me, "a", ortho(fmt="256 128", window="-2 2 -1 1"), world)
    yield
    image = b.image(me, "a")
    left = [p[3] for (x, y), p in image.pixels.items() if x < 128]
    right = [p[3] for (x, y), p in image.pixels.items() if x >= 128]
    # Each half of the frame is 2x2 units.
    expect_close(sum(left) / len(left), math.pi / 4 / 4, 0.01, "quarter disk coverage")
    expect_close(sum(right) / len(right), math.pi * 0.81 / 2 / 4, 0.01, "half sphere coverage")


@check("batch")
def perspective_fov90_maps_unit_half_width_to_full_width(b, me):
    """With fov 90 on a square frame, x = ±1 at depth 1 falls exactly on the frame's edges."""
    for half in ("1", "0.97"):
        b.frame(me, half, "Format 64 64 1\nPixelSamples 2 2\nPixelFilter \"box\" 1 1\n"
                "Projection \"perspective\" \"fov\" [90]\n",
                f"Polygon \"P\" [-{half} -0.5 1  {half} -0.5 1  {half} 0.5 1  -{half} 0.5 1]")
    yield
    # Rows 16..47 span y in [-0.5, 0.5]: every pixel there is covered, none outside.
    for (x, y), p in b.image(me, "1").pixels.items():
        inside = 16 <= y < 48
        expect(p[3] == (1.0 if inside else 0.0),
               f"half-width 1: alpha {p[3]} at pixel ({x},{y}), expected {float(inside)}")
    # 0.97 leaves 0.03 of the 0.03125-wide edge columns uncovered: alpha about 0.04 there.
    narrow = b.image(me, "0.97")
    for x in (0, 63):
        expect(narrow.pixels[(x, 32)][3] < 0.2,
               f"half-width 0.97: edge column {x} has alpha {narrow.pixels[(x, 32)][3]}")


@check("batch")
def crop_window_is_exactly_a_part_of_the_frame(b, me):
    """CropWindow 0 .5 0 .5 (and .5 1 .5 1) give exactly the matching quarter of the frame,
    with a gaussian filter whose footprint crosses the crop border."""
    world = "Rotate 30 0 0 1\nSphere 1.2 -1.2 1.2 300\nTorus 1.5 0.2 0 360 360"
    for name, crop in (("full", ""), ("tl", "CropWindow 0 0.5 0 0.5\n"),
                       ("br", "CropWindow 0.5 1 0.5 1\n")):
        b.frame(me, name, ortho(fmt="64 48", window="-2 2 -1.5 1.5",
                                extra=f"PixelFilter \"gaussian\" 2 2\n{crop}"), world)
    yield
    full = b.image(me, "full")
    for name, origin in (("tl", (0, 0)), ("br", (32, 24))):
        crop = b.image(me, name)
        expect((crop.width, crop.height) == (32, 24), f"crop is {crop.width}x{crop.height}")
        expect(crop.origin == origin, f"crop data window starts at {crop.origin}, not {origin}")
        for xy, values in crop.pixels.items():
            expect(values == full.pixels[xy],
                   f"cropped pixel {xy} is {values}, the full frame has {full.pixels[xy]}")


@check("batch")
def depth_output_reads_the_plane_depth(b, me):
    """Display mode z: a plane facing the camera at depth 3.25 reads 3.25; misses read +inf."""
    for projection in ("perspective", "orthographic"):
        b.frame(me, projection, f"Format 32 32 1\nDisplay \"{me}_{projection}.exr\" \"openexr\" "
                f"\"z\"\nProjection \"{projection}\"\nTranslate 0 0 3.25\n",
                "Polygon \"P\" [-5 -5 0  0 -5 0  0 5 0  -5 5 0]")
    yield
    for projection in ("perspective", "orthographic"):
        image = b.image(me, projection)
        expect(image.channels == 1, f"z image has {image.channels} channels")
        for (x, y), (z,) in image.pixels.items():
            if x < 15:
                expect(abs(z - 3.25) < 1e-5, f"{projection}: depth {z} at ({x},{y})")
            elif x > 16:
                expect(math.isinf(z), f"{projection}: depth {z} where nothing was hit")


@check("batch")
def exposure_gain_and_gamma(b, me):
    """Exposure 2 1 doubles a value; Exposure 1 2 takes its square root; alpha is untouched."""
    world = "Color [0.25 0.125 0.0625]\nPolygon \"P\" [-3 -3 0  3 -3 0  3 3 0  -3 3 0]"
    for name, exposure in (("one", "1 1"), ("gain", "2 1"), ("gamma", "1 2")):
        b.frame(me, name, ortho(fmt="8 8", extra=f"Exposure {exposure}\n"), world)
    yield
    one, gain, gamma = (b.image(me, n) for n in ("one", "gain", "gamma"))
    for xy, base in one.pixels.items():
        expect_values(base, [0.25, 0.125, 0.0625, 1], 1e-6, f"unexposed pixel {xy}")
        expect_values(gain.pixels[xy], [2 * v for v in base[:3]] + [1], 1e-6, f"gain 2 at {xy}")
        expect_values(gamma.pixels[xy], [math.sqrt(v) for v in base[:3]] + [1], 1e-6,
                      f"gamma 2 at {xy}")


@check("batch")
def box_filter_reproduces_pixel_values(b, me):
    """A checkerboard of 4x4-pixel cells: box 1 1 gives each pixel exactly its cell's colour
    (for any sample count), while gaussian 2 2 blends colours across cell borders."""
    points, verts = [], []
    for cy in range(8):
        for cx in range(8):
            if (cx + cy) % 2 == 0:
                x0, y0 = 4 * cx, -4 * cy  # ScreenWindow 0 32 -32 0: one unit per pixel
                verts += range(len(points), len(points) + 4)
                points += [(x0, y0), (x0 + 4, y0), (x0 + 4, y0 - 4), (x0, y0 - 4)]
    world = (f"Color [0.8 0.4 0.2]\nPointsPolygons [{' '.join(['4'] * (len(verts) // 4))}] "
             f"[{' '.join(map(str, verts))}] "
             f"\"P\" [{'  '.join(f'{x} {y} 0' for x, y in points)}]")
    for name, filt, samples in (("box1", "\"box\" 1 1", "1 1"), ("box3", "\"box\" 1 1", "3 3"),
                                ("gauss", "\"gaussian\" 2 2", "3 3")):
        b.frame(me, name, ortho(fmt="32 32", window="0 32 -32 0",
                                extra=f"PixelFilter {filt}\nPixelSamples {samples}\n"), world)
    yield
    for name in ("box1", "box3"):
        for (x, y), values in b.image(me, name).pixels.items():
            lit = ((x // 4) + (y // 4)) % 2 == 0
            want = [0.8, 0.4, 0.2, 1.0] if lit else [0.0, 0.0, 0.0, 0.0]
            expect_values(values, want, 1e-6, f"{name}: pixel ({x},{y})")
    blended = sum(1 for v in b.image(me, "gauss").channel(3) if 0.01 < v < 0.99)
    expect(blended > 100, f"gaussian 2 2 blended only {blended} pixels across cell borders")


@check("batch")
def sides_one_removes_back_faces(b, me):
    """The far hemisphere seen from inside: visible with Sides 2, gone with Sides 1, back again
    with Sides 1 and ReverseOrientation."""
    for name, attributes in (("two", ""), ("one", "Sides 1\n"),
                             ("reversed", "Sides 1\nReverseOrientation\n")):
        b.frame(me, name, ortho(), f"{attributes}Sphere 1 0 1 360")
    yield
    expect_close(b.image(me, "two").mean(3), math.pi / 16, 0.01, "Sides 2 coverage")
    one = b.image(me, "one").channel(3)
    expect(max(one) == 0, f"Sides 1 left alpha up to {max(one)}")
    expect_close(b.image(me, "reversed").mean(3), math.pi / 16, 0.01,
                 "Sides 1 + ReverseOrientation coverage")


@check("batch")
def quantize_sets_the_data_type(b, me):
    """Quantize one = 255, 65535 and 0 give 8-bit, 16-bit and float TIFF files."""
    for name, one in (("8", "255 0 255 0.5"), ("16", "65535 0 65535 0.5"), ("float", "0 0 0 0")):
        b.frame(me, name, f"Format 4 4 1\nQuantize \"rgba\" {one}\n"
                f"Display \"{me}_{name}.tif\" \"tiff\" \"rgba\"\n", "")
    yield
    formats = [b.image(me, n).format for n in ("8", "16", "float")]
    expect(formats == ["uint8", "uint16", "float"], f"data types {formats}")


@check("batch")
def matte_object_has_zero_alpha(b, me):
    """RISpec §4.2 RiMatte: where a matte object is visible the image is transparent (alpha 0)
    and the matte hides what lies behind it."""
    world = ("AttributeBegin\nTranslate 0 0 1\nPolygon \"P\" [-3 -3 0  3 -3 0  3 3 0  -3 3 0]\n"
             "AttributeEnd\nMatte 1\nSphere 1 -1 1 360")
    b.frame(me, "a", ortho(fmt="32 32"), world)
    yield
    image = b.image(me, "a")
    expect_values(image.pixels[(16, 16)], [0, 0, 0, 0], 0, "pixel under the matte sphere")
    expect(image.pixels[(1, 1)][3] == 1, "the card around the matte sphere is not opaque")


@check("batch")
def object_instance_inherits_current_attributes(b, me):
    """RISpec §5.6 RiObjectInstance: 'The object inherits the current set of attributes defined
    in the graphics state.' A sphere defined without a colour, instanced after Color [1 0 0],
    is red."""
    world = "ObjectBegin 1\nSphere 1 -1 1 360\nObjectEnd\nColor [1 0 0]\nObjectInstance 1"
    b.frame(me, "a", ortho(fmt="32 32"), world)
    yield
    centre = b.image(me, "a").pixels[(16, 16)]
    expect(centre[0] > 0.5 and centre[1] == 0 and centre[2] == 0,
           f"instance after Color [1 0 0] has colour {centre[:3]}")


@check("batch")
def facevarying_cs_on_a_subdivision_mesh(b, me):
    """RISpec §4.2: facevarying values are interpolated like varying ones, but each face by its
    own corner values. A flat 3x3 SubdivisionMesh (interpolateboundary) whose middle face has
    red bottom corners and blue top ones, every other face green: the middle face's centre is
    the mean of its corners, (0.5, 0, 0.5) by symmetry; above it blue grows, below red; a side
    face is green."""
    grid = " ".join(f"{x} {y} 0" for y in (-3, -1, 1, 3) for x in (-3, -1, 1, 3))
    faces = [(i, j) for j in range(3) for i in range(3)]
    indices = " ".join(f"{4 * j + i} {4 * j + i + 1} {4 * j + i + 5} {4 * j + i + 4}"
                       for i, j in faces)
    red, blue, green = "1 0 0", "0 0 1", "0 1 0"
    colours = " ".join(f"{red} {red} {blue} {blue}" if (i, j) == (1, 1) else f"{green} " * 4
                       for i, j in faces)
    world = (f'SubdivisionMesh "catmull-clark" [{"4 " * 9}] [{indices}] '
             f'["interpolateboundary"] [0 0] [] [] "P" [{grid}] "facevarying color Cs" [{colours}]')
    b.frame(me, "a", ortho(fmt="65 65"), world)
    yield
    image = b.image(me, "a")
    expect_values(image.pixels[(32, 32)][:3], [0.5, 0, 0.5], 0.02, "middle face centre")
    above, below = image.pixels[(32, 24)], image.pixels[(32, 40)]
    expect(above[2] > 0.55 > 0.45 > above[0] and below[0] > 0.55 > 0.45 > below[2],
           f"middle face above/below its centre: {above[:3]} / {below[:3]}")
    expect_values(image.pixels[(58, 32)][:3], [0, 1, 0], 1e-5, "the right face")


TEAPOT_DATA = os.path.join(os.path.dirname(__file__), "..", "..", "data", "teapot.txt")


def teapot_patches():
    """The control points of data/teapot.txt's patches, read here without the renderer."""
    lines = [l.split() for l in open(TEAPOT_DATA) if l.strip() and not l.startswith("#")]
    count = int(lines[0][1])
    vertices = [tuple(map(float, l)) for l in lines[1:1 + count]]
    return [[vertices[int(i)] for i in l[1:]] for l in lines[2 + count:]]


def bezier_point(points, u, v):
    """A bicubic Bézier patch (16 points, u fastest) at (u, v)."""
    bu = [(1 - u) ** 3, 3 * u * (1 - u) ** 2, 3 * u * u * (1 - u), u ** 3]
    bv = [(1 - v) ** 3, 3 * v * (1 - v) ** 2, 3 * v * v * (1 - v), v ** 3]
    return [sum(bu[i] * bv[j] * points[4 * j + i][c] for i in range(4) for j in range(4))
            for c in range(3)]


@check("batch")
def teapot_side_view_covers_its_silhouette(b, me):
    """Geometry "teapot" seen from the side (orthographic, 64×48 pixels of 1/8 unit) covers the
    pixels that its Bézier patches, sampled densely here, fall in; lit from the eye, every pixel
    inside the silhouette is finite and not black (the degenerate lid and bottom patches)."""
    options = ("Format 64 48 1\nPixelSamples 4 4\nPixelFilter \"box\" 1 1\n"
               "Projection \"orthographic\"\nScreenWindow -4 4 -3 3\n"
               "Translate 0 0 5\nRotate -90 1 0 0\nTranslate -0.25 0 -1.575\n")
    world = ("LightSource \"distantlight\" 1 \"from\" [0 1 0] \"to\" [0 0 0]\n"
             "Surface \"matte\"\nGeometry \"teapot\"\n")
    b.frame(me, "a", options, world)
    yield
    image = b.image(me, "a")
    expected = set()
    steps = 48
    for patch in teapot_patches():
        for i in range(steps + 1):
            for j in range(steps + 1):
                x, _, z = bezier_point(patch, i / steps, j / steps)
                expected.add((int((x - 0.25 + 4) * 8), int((3 - (z - 1.575)) * 8)))
    # A pixel the patches touch may be missed by all 16 samples: a few more expected than seen.
    covered = {xy for xy, p in image.pixels.items() if p[3] > 0}
    differ = len(covered ^ expected)
    expect(differ <= 0.04 * len(expected),
           f"{differ} pixels differ from the {len(expected)} the patches cover")
    expect_close(len(covered) / (64 * 48), len(expected) / (64 * 48), 0.05, "covered fraction")
    inside = [xy for xy, p in image.pixels.items() if p[3] == 1]
    for xy in inside:
        value = image.pixels[xy]
        expect(all(math.isfinite(c) for c in value), f"pixel {xy} is {value}")
        expect(max(value[:3]) > 0.02, f"pixel {xy} inside the silhouette is black: {value}")


def blob_field(s):
    """Application Note #31's field of one Blobby leaf at squared blob-space distance s."""
    return (1 - s) ** 3 if s < 1 else 0.0


BLOB_RADIUS = math.sqrt(1 - 0.5 ** (1 / 3))  # a lone unit leaf's surface: (1 - r²)³ = 0.5


@check("batch")
def blobby_ellipsoid_is_the_threshold_sphere(b, me):
    """Blobby 1 [1001 0] with a matrix that scales by 2 is the sphere of radius 2·√(1 − 0.5^⅓)
    ≈ 0.9084 (RISpec 3.2 §5.6: field (1 − r²)³, surface at 0.5): seen orthographically it covers
    πR²/16 of ScreenWindow [-2,2]², and matte lit from the eye shows cos θ = √(1 − ρ²/R²) at
    distance ρ from its centre, so its shading normals are the sphere's."""
    world = ('LightSource "distantlight" 1 "from" [0 0 0] "to" [0 0 1]\nSurface "matte"\n'
             'Blobby 1 [1001 0] [2 0 0 0  0 2 0 0  0 0 2 0  0 0 0 1] [""]\n')
    b.frame(me, "a", ortho(), world)
    yield
    image, radius = b.image(me, "a"), 2 * BLOB_RADIUS
    expect_close(image.mean(3), math.pi * radius * radius / 16, 0.01, "mean alpha of the blob")
    for x, y in ((64, 64), (80, 64), (64, 44), (76, 76), (50, 70)):
        rho = math.hypot((x + 0.5) / 32 - 2, 2 - (y + 0.5) / 32)
        expect(abs(image.pixels[(x, y)][0] - math.sqrt(1 - (rho / radius) ** 2)) < 0.01,
               f"pixel {(x, y)} at ρ = {rho:.3f}: {image.pixels[(x, y)][0]:.4f}, expected "
               f"cos θ = {math.sqrt(1 - (rho / radius) ** 2):.4f}")


@check("batch")
def blobby_two_leaves_blend_shape_and_colour(b, me):
    """Two unit leaves at x = ±0.4 added (opcode 0), red and blue per leaf ("vertex color Cs"),
    Surface "constant". The silhouette is where the summed field in the plane z = 0 reaches 0.5
    (each leaf's field is largest there along a line of sight); the colour of a pixel is the
    leaves' colours weighted by their fields at the visible surface point, found here by
    bisection along the ray."""
    d = 0.4
    world = ('Surface "constant"\nBlobby 2 [1001 0 1001 16 0 2 0 1]\n'
             f'[1 0 0 0  0 1 0 0  0 0 1 0  {-d} 0 0 1  1 0 0 0  0 1 0 0  0 0 1 0  {d} 0 0 1] [""]\n'
             '"vertex color Cs" [1 0 0  0 0 1]\n')
    b.frame(me, "a", ortho(window="-1 1 -1 1"), world)
    yield
    image = b.image(me, "a")

    def fields(x, y, z):
        return (blob_field((x + d) ** 2 + y * y + z * z), blob_field((x - d) ** 2 + y * y + z * z))

    def centre(px, py):
        return (px + 0.5) / 64 - 1, 1 - (py + 0.5) / 64

    inside = {xy for xy in image.pixels if sum(fields(*centre(*xy), 0)) >= 0.5}
    covered = {xy for xy, p in image.pixels.items() if p[3] >= 0.5}
    expect(len(inside ^ covered) <= 0.02 * len(inside),
           f"{len(inside ^ covered)} pixels differ from the {len(inside)} inside the silhouette")
    checked = 0
    for xy in sorted(inside):
        if image.pixels[xy][3] < 1 or xy[0] % 7 or xy[1] % 7:
            continue
        x, y = centre(*xy)
        near, far = 0.0, 1.0  # the front surface point: the field falls with |z|
        for _ in range(40):
            mid = (near + far) / 2
            near, far = (mid, far) if sum(fields(x, y, mid)) >= 0.5 else (near, mid)
        a, c = fields(x, y, near)
        want = [a / (a + c), 0.0, c / (a + c)]
        expect_values([round(v, 3) for v in image.pixels[xy][:3]], [round(v, 3) for v in want],
                      0.011, f"colour at pixel {xy}")
        checked += 1
    expect(checked > 30, f"only {checked} pixels checked")


@check("batch")
def colour_samples_convert_to_rgb(b, me):
    """RISpec §4.1.3 ColorSamples: colours have n components, converted to RGB by nRGB (n rows
    of 3). Components 0.2 0.2 0.2 0.1 0.1 0.1 whose rows map 1,4 to red, 2,5 to green and 3,6 to
    blue give RGB 0.3 0.3 0.3."""
    matrix = ("[1 0 0  0 1 0  0 0 1  1 0 0  0 1 0  0 0 1] "
              "[1 0 0 0 0 0  0 1 0 0 0 0  0 0 1 0 0 0]")
    b.frame(me, "a", ortho(fmt="8 8", extra=f"ColorSamples {matrix}\n"),
            "Color [0.2 0.2 0.2 0.1 0.1 0.1]\nPolygon \"P\" [-3 -3 0  3 -3 0  3 3 0  -3 3 0]")
    yield
    expect_values(b.image(me, "a").pixels[(4, 4)], [0.3, 0.3, 0.3, 1], 1e-6, "pixel")


# ---- determinism, seeds, outputs (their own command lines) -----------------------------------

SCENES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "scenes")


@check("analytic")
def thread_count_does_not_change_the_file(ws):
    """The same render with --threads 1 and --threads 2 writes identical pixels (not identical
    bytes: a TIFF records the second it was written); --seed changes the sample pattern and so
    the noise, not the picture."""
    scene = os.path.join(SCENES, "depth_of_field.rib")
    ws.run(["render", scene, "--threads", "1", "-o", "t1.tif"])
    ws.run(["render", scene, "--threads", "2", "-o", "t2.tif"])
    ws.run(["render", scene, "--threads", "2", "--seed", "7", "-o", "s7.tif"])
    t1, t2, s7 = read_images(ws.path("t1.tif"), ws.path("t2.tif"), ws.path("s7.tif"))
    expect(t1.pixels == t2.pixels, "--threads 1 and --threads 2 wrote different pixels")
    changed = sum(1 for xy in t1.pixels if t1.pixels[xy] != s7.pixels[xy])
    expect(changed > 0.05 * len(t1.pixels), f"--seed 7 changed only {changed} pixels")
    expect(abs(t1.mean(1) - s7.mean(1)) < 0.004, "--seed changed the mean of the picture")


@check("analytic")
def default_display_and_output_numbering(ws):
    """Without Display and Format: <scene>.tif in the working folder, 640x480 RGBA. With -o and
    several frames, # in the name becomes the frame number."""
    ws.render("WorldBegin\nTranslate 0 0 5\nSphere 1 -1 1 360\nWorldEnd\n", "nodisplay")
    ws.run(["render", os.path.join(SCENES, "frames.rib"), "-o", "out_#.png"])
    proc = subprocess.run(["oiiotool", "--info", ws.path("nodisplay.tif"), ws.path("out_1.png"),
                           ws.path("out_2.png")], capture_output=True, text=True)
    sizes = [m.groups()[1:4] for m in map(HEADER.match, proc.stdout.splitlines()) if m]
    expect(sizes == [("640", "480", "4"), ("48", "48", "4"), ("64", "48", "4")],
           f"default display, out_1.png, out_2.png: {sizes} {proc.stderr}")


# ---- exit codes ------------------------------------------------------------------------------

GOOD_SCENE = "Format 8 8 1\nDisplay \"good.tif\" \"tiff\" \"rgba\"\nWorldBegin\n" \
             "Translate 0 0 5\nSphere 1 -1 1 360\nWorldEnd\n"
BAD_SCENE = "Format 8 8 1\nDisplay \"bad.tif\" \"tiff\" \"rgba\"\nWorldBegin\n" \
            "Translate 0 0 5\nSphere 1 -1 1 360 \"varying color Cs\" [1 0 0]\nWorldEnd\n"


@check("exit")
def exit_0_on_success(ws):
    ws.render(GOOD_SCENE, expect_code=0)
    expect(os.path.exists(ws.path("good.tif")), "no image after a successful render")


@check("exit")
def exit_1_on_scene_errors_but_the_rest_renders(ws):
    """By default (ErrorHandler "print") a bad request is reported and skipped."""
    proc = ws.render(BAD_SCENE, "bad", expect_code=1)
    expect("bad.rib:5:1: error: Sphere: varying variable \"Cs\" needs 4 values, got 1"
           in proc.stderr, f"unexpected message:\n{proc.stderr}")
    expect(os.path.exists(ws.path("bad.tif")), "the frame was not rendered")


@check("exit")
def exit_1_and_no_image_with_strict_or_abort(ws):
    ws.render(BAD_SCENE, "bad", ["--strict"], expect_code=1)
    expect(not os.path.exists(ws.path("bad.tif")), "--strict still rendered the frame")
    ws.render("ErrorHandler \"abort\"\n" + BAD_SCENE, "bad", expect_code=1)
    expect(not os.path.exists(ws.path("bad.tif")), "ErrorHandler abort still rendered")


@check("exit")
def exit_1_on_a_missing_archive(ws):
    proc = ws.render("WorldBegin\nReadArchive \"missing.rib\"\nWorldEnd\n", "arch",
                     ["-o", "arch.tif"], expect_code=1)
    expect("arch.rib:2:" in proc.stderr and "missing.rib" in proc.stderr,
           f"the error does not name the file, line and archive:\n{proc.stderr}")


@check("exit")
def exit_2_on_an_unreadable_scene(ws):
    proc = ws.run(["render", ws.path("no_such.rib")], expect_code=2)
    expect("cannot open scene file" in proc.stderr, f"unexpected message:\n{proc.stderr}")


@check("exit")
def exit_2_on_an_unwritable_output_without_leaving_a_file(ws):
    scene = ws.path("good.rib")
    with open(scene, "w") as f:
        f.write(GOOD_SCENE)
    ws.run(["render", scene, "-o", ws.path("no_such_folder/out.tif")], expect_code=2)
    # The target is a folder: the temporary file can be written, the rename cannot.
    os.mkdir(ws.path("taken.tif"))
    before = set(os.listdir(ws.dir))
    proc = ws.run(["render", scene, "-o", "taken.tif"], expect_code=2)
    expect("taken.tif" in proc.stderr, f"the error does not name the file:\n{proc.stderr}")
    left = set(os.listdir(ws.dir)) - before
    expect(not left, f"a failed write left {sorted(left)} behind")


@check("exit")
def exit_2_on_bad_usage(ws):
    ws.run(["render"], expect_code=2)
    ws.run(["render", "x.rib", "--threads", "-1"], expect_code=2)


def render_in_folder(gonio, folder, shaders, scene, args=()):
    """Writes the shaders (file name -> source) and `scene` as scene.rib into folder and renders
    it there (with the further command-line `args`). Returns None, or a message saying how gonio
    failed or that it warned."""
    for name, text in shaders.items():
        with open(os.path.join(folder, name), "w") as f:
            f.write(text)
    path = os.path.join(folder, "scene.rib")
    with open(path, "w") as f:
        f.write(scene)
    proc = subprocess.run([gonio, "render", path, *args], cwd=folder, capture_output=True,
                          text=True)
    if proc.returncode != 0 or re.search(r"warning|error", proc.stderr):
        return f"gonio render failed or warned (exit {proc.returncode}):\n{proc.stderr}"
    return None


def frames_main(description, prefix, shaders, scene, images, checks, prepare=None):
    """The command line of a checks script that renders one scene (`--gonio PATH`): in a
    temporary folder, `prepare(folder)` (may be None), the shaders and scene.rib written and
    rendered, the image files `images` (name: file) read, and the checks run on
    {name: Image}; returns the exit status."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--gonio", required=True)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix=prefix) as folder:
        if prepare:
            prepare(folder)
        failure = render_in_folder(os.path.abspath(args.gonio), folder, shaders, scene)
        if failure:
            print(failure)
            return 1
        read = read_images(*(os.path.join(folder, file) for file in images.values()))
        return run_checks(checks, dict(zip(images, read)))


def workspace_main(description, checks, prefix, shaders=None):
    """The command line of a checks script run on one Workspace (`--gonio PATH`): writes the
    shaders (name: source) into it and runs the checks; returns the exit status."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--gonio", required=True)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix=prefix) as root:
        ws = Workspace(os.path.abspath(args.gonio), root)
        for name, source in (shaders or {}).items():
            with open(ws.path(name), "w") as f:
                f.write(source + "\n")
        return run_checks(checks, ws)


def run_checks(checks, subject):
    """Runs each check on `subject` (a Workspace, or the images the checks read) in turn,
    printing ok or FAIL with the reason for each and a summary; returns the exit status (1 when
    any failed). A pixel the images lack (KeyError) fails its check like a failed expectation."""
    failures = 0
    for check in checks:
        try:
            check(subject)
            print(f"ok   {check.__name__}")
        except (CheckFailed, KeyError) as error:
            print(f"FAIL {check.__name__}\n     {error}")
            failures += 1
    print(f"{len(checks) - failures} of {len(checks)} checks passed")
    return 1 if failures else 0


def run_batch(gonio, root, checks):
    """Runs the batched checks: collect frames, one render, one read, then each check's asserts.
    Returns [(name, bug, error or None)]."""
    batch, generators, results = Batch(), [], []
    for name, bug, function in checks:
        generator = function(batch, name)
        next(generator)
        generators.append((name, bug, generator))
    ws = Workspace(gonio, root)
    try:
        ws.render("".join(batch.frames), "batch")
        names = sorted(f for f in os.listdir(ws.dir) if not f.endswith(".rib"))
        for name, image in zip(names, read_images(*(ws.path(n) for n in names))):
            batch.images[os.path.splitext(name)[0]] = image
    except CheckFailed as e:
        return [(name, bug, f"the batch render failed: {e}") for name, bug, _ in generators]
    for name, bug, generator in generators:
        try:
            next(generator, None)
            results.append((name, bug, None))
        except CheckFailed as e:
            results.append((name, bug, str(e)))
        except Exception:  # a crash of the check itself is a failure too
            results.append((name, bug, traceback.format_exc()))
    return results


def run_single(gonio, root, entry):
    name, bug, function = entry
    try:
        function(Workspace(gonio, root))
        return name, bug, None
    except CheckFailed as e:
        return name, bug, str(e)
    except Exception:  # a crash of the check itself is a failure too
        return name, bug, traceback.format_exc()


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--gonio", required=True)
    parser.add_argument("--group", choices=["analytic", "exit", "shading"],
                        help="analytic: the image checks; exit: the exit codes; shading: the "
                        "checks of shading_checks.py")
    parser.add_argument("--known-bugs", action="store_true",
                        help="also run the checks of known bugs (expected to fail)")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("names", nargs="*")
    args = parser.parse_args()
    gonio = os.path.abspath(args.gonio)
    selected = {name: (group, bug, fn) for name, (group, bug, fn) in CHECKS.items()
                if (not args.names or name in args.names)
                and (args.group is None or BATCH_GROUPS.get(group, group) == args.group)
                and (args.known_bugs or bug is None or name in args.names)}
    if args.names and len(selected) != len(args.names):
        sys.exit(f"analytic_checks: unknown check among {args.names}")
    batched = [(n, bug, fn) for n, (group, bug, fn) in selected.items()
               if group in BATCH_GROUPS]
    single = [(n, bug, fn) for n, (group, bug, fn) in selected.items()
              if group not in BATCH_GROUPS]

    with tempfile.TemporaryDirectory(prefix="gonio_checks_") as root:
        with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
            batch_results = pool.submit(run_batch, gonio, root, batched) if batched else None
            results = list(pool.map(lambda entry: run_single(gonio, root, entry), single))
            if batch_results:
                results = batch_results.result() + results
    failures = 0
    for name, bug, error in results:
        note = f"  [known bug: {bug}]" if bug else ""
        print(f"{'ok  ' if error is None else 'FAIL'} {name}{note}")
        if error:
            print("     " + error.replace("\n", "\n     "))
            failures += 1
    print(f"{len(results) - failures} of {len(results)} checks passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
