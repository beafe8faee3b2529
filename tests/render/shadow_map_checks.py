#!/usr/bin/env python3
"""End-to-end checks of shadow maps (issue 20; docs/shading-language.md, Shadow maps):

* `Display "depth.z" "zfile" "z"` writes Pixar's zfile whatever the extension, holding per
  pixel the smallest camera-space depth of its samples: exactly 5 on a plane 5 units away, and
  on a sphere between the analytic depths of the pixel's nearest and farthest points; its header
  holds the camera's world-to-camera and world-to-screen matrices; `Display "+x.sm" "shadow"
  "z"` writes the same depths as a shadow map, and MakeShadow of the zfile makes the same one;
* a two-pass RIB (frame 1 renders the depth from the light, MakeShadow makes the map, frame 2
  renders a plane under a sphere lit by shadowspot using it) shadows the same pixels as the
  ray-traced shadow of the same scene, but along the edge (within the filter's reach), and
  traces no shadow rays; the map written directly by a "shadow" display does the same;
* the default bias leaves a plane tilted 30° to the light unshadowed by itself (every pixel as
  without a map), where "bias" 0 shadows part of it (acne: the check can fail);
* a shadow map that does not exist warns once and falls back to traced shadows (the same image);
* shadowpoint's six maps (one per axis direction, made from the light's position) shadow a
  floor under four spheres as traced rays do, but along the edges, through four of the maps and
  across the seam of two, and trace no shadow rays;
* a Blobby's repelling plane (opcode 1003) is the surface of the depth map it names: a sphere
  cut by a stepped ground rendered into a zfile stays in front of the ground on each side of the
  step (and on both sides alike once a later frame has rendered the ground flat), and with a map
  that does not exist it warns (file:line) and is whole (the plane z = 0 is out of its reach).

    shadow_map_checks.py --gonio build/bin/gonio"""

import math
import os
import re
import struct
import subprocess
import sys

from analytic_checks import expect, read_images, run_checks, workspace_main

ZFILE_MAGIC = 0x2F0867AB


def read_zfile(path):
    """(width, height, worldtoscreen, worldtocamera, depths row by row) of an uncompressed zfile."""
    with open(path, "rb") as f:
        data = f.read()
    magic, width, height = struct.unpack_from("<ihh", data)
    expect(magic == ZFILE_MAGIC, f"{path}: magic {magic:#x}, not a zfile")
    screen = struct.unpack_from("<16f", data, 8)
    camera = struct.unpack_from("<16f", data, 72)
    depths = struct.unpack_from(f"<{width * height}f", data, 136)
    expect(len(data) == 136 + 4 * width * height, f"{path}: {len(data)} bytes")
    return width, height, screen, camera, depths


def transform(point, m):
    """A point times a row-major 4x4 matrix (row vectors), divided by w."""
    x, y, z = point
    out = [x * m[c] + y * m[4 + c] + z * m[8 + c] + m[12 + c] for c in range(4)]
    return [v / out[3] for v in out[:3]]


DEPTH_SCENE = """Format 64 64 1
PixelSamples 3 3
Projection "perspective" "fov" [90]
Translate 0 0 5
Display "depth.z" "zfile" "z"
Display "+depth.sm" "shadow" "z"
WorldBegin
AttributeBegin
Translate 0 0 -2
Sphere 1 -1 1 360
AttributeEnd
Polygon "P" [-20 -20 0  20 -20 0  20 20 0  -20 20 0]
WorldEnd
MakeShadow "depth.z" "made.sm"
"""


def sphere_depth(r2):
    """Camera-space depth of the unit sphere at depth 3 along the ray (x, y, 1), x² + y² = r2."""
    return (3 - math.sqrt(9 - 8 * (1 + r2))) / (1 + r2)


def pixel_r2_range(px, py, size):
    """The smallest and largest x² + y² over pixel (px, py) of a [-1, 1]² screen."""
    x0, x1 = -1 + 2 * px / size, -1 + 2 * (px + 1) / size
    y0, y1 = 1 - 2 * (py + 1) / size, 1 - 2 * py / size
    nearest = lambda a, b: 0 if a <= 0 <= b else min(a * a, b * b)
    return (nearest(x0, x1) + nearest(y0, y1), max(x0 * x0, x1 * x1) + max(y0 * y0, y1 * y1))


def zfile_holds_analytic_depths(ws):
    ws.render(DEPTH_SCENE, "depth")
    width, height, screen, camera, depths = read_zfile(ws.path("depth.z"))
    expect((width, height) == (64, 64), f"zfile is {width} x {height}")
    want = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 5, 1]
    expect(all(abs(a - b) < 1e-6 for a, b in zip(camera, want)), f"world-to-camera {camera}")
    projected = transform((1, 2, 0), screen)
    expect(abs(projected[0] - 0.2) < 1e-6 and abs(projected[1] - 0.4) < 1e-6,
           f"world (1, 2, 0) goes to screen {projected}, expected (0.2, 0.4)")
    limit = 1 / 8  # the sphere's silhouette: x² + y² <= 1/8
    sphere = plane = 0
    for py in range(height):
        for px in range(width):
            z = depths[py * width + px]
            r2min, r2max = pixel_r2_range(px, py, width)
            if r2min > limit:
                expect(abs(z - 5) < 1e-5, f"plane pixel ({px},{py}) has depth {z}, expected 5")
                plane += 1
            elif r2max < limit:
                low, high = sphere_depth(r2min), sphere_depth(r2max)
                expect(low - 1e-4 <= z <= high + 1e-4,
                       f"sphere pixel ({px},{py}) has depth {z}, outside [{low}, {high}]")
                sphere += 1
            else:
                expect(sphere_depth(r2min) - 1e-4 <= z <= 5 + 1e-5, f"edge pixel ({px},{py}): {z}")
    expect(sphere > 200 and plane > 2000, f"{sphere} sphere and {plane} plane pixels")
    direct, made = read_images(ws.path("depth.sm"), ws.path("made.sm"))
    for image, name in ((direct, "the shadow display"), (made, "MakeShadow")):
        expect(image.channels == 1 and image.format == "float",
               f"{name}: {image.channels} channels of {image.format}")
        for (x, y), (z,) in image.pixels.items():
            expect(abs(z - depths[y * width + x]) <= 1e-6 * abs(z), f"{name} ({x},{y}): {z}, zfile {depths[y * width + x]}")
    info = subprocess.run(["oiiotool", "--info", "-v", ws.path("made.sm")], capture_output=True,
                          text=True).stdout
    expect('textureformat: "Shadow"' in info and "worldtocamera" in info,
           f"made.sm is not tagged as a shadow map:\n{info}")


# The light looks along +z from the origin; a sphere of radius 0.7 at depth 3 shadows a plane at
# depth 6. The viewer stands 2.5 to the side and sees both.
GEOMETRY = """Surface "matte"
AttributeBegin
Translate 0 0 3
Sphere 0.7 -0.7 0.7 360
AttributeEnd
Polygon "P" [-8 -8 6  8 -8 6  8 8 6  -8 8 6]
"""
LIGHT_FRAME = """FrameBegin {n}
Format 256 256 1
PixelSamples 2 2
Projection "perspective" "fov" [80]
Display "light.z" "zfile" "z"
Display "+direct.sm" "shadow" "z"
WorldBegin
{geometry}WorldEnd
FrameEnd
MakeShadow "light.z" "light.sm"
"""
VIEW_FRAME = """FrameBegin {n}
Format 128 128 1
PixelSamples 2 2
Projection "perspective" "fov" [60]
Translate -2.5 0 0
Display "{name}.exr" "openexr" "rgb"
Display "+{name}_z.exr" "openexr" "z"
WorldBegin
{light}LightSource "shadowspot" 1 "intensity" 36 "coneangle" [0.698] "string shadowname" "{map}" {more}
{geometry}WorldEnd
FrameEnd
"""


def view(n, name, map_name, light="", more="", geometry=GEOMETRY):
    return VIEW_FRAME.format(n=n, name=name, map=map_name, light=light, more=more,
                             geometry=geometry)


TRACED = 'Attribute "light" "shadows" "on"\n'


def frame_shadow_rays(stderr):
    """The shadow rays of each frame's --stats line, in frame order."""
    counts = []
    for line in stderr.splitlines():
        if m := re.search(r"(\d+) camera rays, (\d+) rays traced(?: \(([^)]*)\))?", line):
            m2 = re.search(r"(\d+) shadow", m.group(3) or "")
            counts.append(int(m2.group(1)) if m2 else 0)
    return counts


# Where the edge can move, on the plane (world units): the light's view and the viewer's both
# meet the plane square on, at depth 6. A map texel's width there, the viewer pixel's, and the
# reach of a mapped shadow's edge from the true one: a min-depth texel dilates the sphere's
# silhouette by up to a texel, the filter region reaches half its width (a viewer pixel's
# footprint, at least a texel), and a pixel is judged by its centre, up to half a diagonal
# from where its area meets the edge.
TEXEL = 2 * 6 * math.tan(math.radians(40)) / 256
PIXEL = 2 * 6 * math.tan(math.radians(30)) / 128
REACH = TEXEL + max(TEXEL, PIXEL) / 2 + PIXEL * math.sqrt(0.5)
EDGE = 6 * math.tan(math.asin(0.7 / 3))  # the radius of the sphere's shadow on the plane


def plane_radius(px, py):
    """The distance from the light's axis of the plane point that pixel (px, py) sees."""
    x = 2.5 + (-1 + (px + 0.5) / 64) * PIXEL * 64
    y = (1 - (py + 0.5) / 64) * PIXEL * 64
    return math.hypot(x, y)


def compare_shadows(mapped, traced, depth, what):
    """Checks that `mapped` shadows the plane where `traced` does, but within the filter's reach
    of the shadow's edge."""
    # Plane pixels inside the spot's cone (40° less its 5° soft edge): the rest is dark anyway.
    plane = {p for p, (z,) in depth.pixels.items()
             if abs(z - 6) < 1e-3 and plane_radius(*p) < 6 * math.tan(math.radians(35))}
    brightest = max(traced.pixels[p][0] for p in plane)
    dark = [p for p in plane if traced.pixels[p][0] <= 1e-6]
    expect(len(dark) > 300, f"the traced shadow covers only {len(dark)} pixels")
    expect(all(plane_radius(*p) < EDGE + PIXEL for p in dark), "the traced shadow is misplaced")
    mismatched = [p for p in plane
                  if abs(mapped.pixels[p][0] - traced.pixels[p][0]) > 0.1 * brightest]
    expect(len(mismatched) < 0.02 * len(plane),
           f"{what}: {len(mismatched)} of {len(plane)} plane pixels differ from the traced shadow")
    far = [p for p in mismatched if abs(plane_radius(*p) - EDGE) > REACH]
    expect(not far, f"{what}: pixels {far[:5]} differ from the traced shadow further than "
                    f"{REACH:.3f} from its edge")


def two_pass_map_shadows_like_rays(ws):
    rib = (LIGHT_FRAME.format(n=1, geometry=GEOMETRY) + view(2, "mapped", "light.sm") +
           view(3, "traced", "", light=TRACED) + view(4, "direct", "direct.sm"))
    proc = ws.render(rib, "twopass", args=["--stats"])
    expect("warning" not in proc.stderr, f"the render warned:\n{proc.stderr}")
    mapped, traced, direct, depth = read_images(*(ws.path(f + ".exr") for f in
                                                  ("mapped", "traced", "direct", "traced_z")))
    compare_shadows(mapped, traced, depth, "MakeShadow's map")
    compare_shadows(direct, traced, depth, "the shadow display's map")
    rays = frame_shadow_rays(proc.stderr)
    expect(len(rays) == 4 and rays[1] == 0 and rays[3] == 0 and rays[2] > 1000,
           f"shadow rays per frame {rays}: the mapped frames should trace none")


# A plane at 30° to the light's view axis, alone: nothing shadows it but itself.
TILTED = """Surface "matte"
AttributeBegin
Translate 0 0 5
Rotate 30 0 1 0
Polygon "P" [-6 -6 0  6 -6 0  6 6 0  -6 6 0]
AttributeEnd
"""
TILT_LIGHT_FRAME = """FrameBegin 1
Format 128 128 1
Projection "perspective" "fov" [50]
Display "tilt.z" "zfile" "z"
WorldBegin
{geometry}WorldEnd
FrameEnd
MakeShadow "tilt.z" "tilt.sm"
"""


def default_bias_leaves_a_lit_plane_unshadowed(ws):
    rib = (TILT_LIGHT_FRAME.format(geometry=TILTED) +
           view(2, "biased", "tilt.sm", geometry=TILTED) +
           view(3, "unshadowed", "", geometry=TILTED) +
           view(4, "unbiased", "tilt.sm", more='"float bias" [0]', geometry=TILTED))
    ws.render(rib, "tilt")
    biased, unshadowed, unbiased = read_images(*(ws.path(f + ".exr") for f in
                                                 ("biased", "unshadowed", "unbiased")))
    lit = [p for p, (r, g, b) in unshadowed.pixels.items() if r > 1e-3]
    expect(len(lit) > 2000, f"only {len(lit)} lit pixels")
    acne = [p for p in lit if biased.pixels[p][0] < unshadowed.pixels[p][0] * 0.999]
    expect(not acne, f"{len(acne)} of {len(lit)} pixels of the plane shadow themselves, "
                     f"e.g. {acne[:5]}")
    zero_bias = [p for p in lit if unbiased.pixels[p][0] < unshadowed.pixels[p][0] * 0.999]
    expect(len(zero_bias) > 0.05 * len(lit),
           f"with bias 0 only {len(zero_bias)} of {len(lit)} pixels shadow themselves")


def missing_map_falls_back_to_traced_shadows(ws):
    rib = view(1, "fallback", "nothere.sm") + view(2, "traced", "", light=TRACED)
    proc = ws.render(rib, "fallback")
    warnings = re.findall(r"warning: .*", proc.stderr)
    expect(len(warnings) == 1 and 'shadow("nothere.sm")' in warnings[0] and
           "shadowed by traced rays instead" in warnings[0],
           f"expected one warning about the missing map, got:\n{proc.stderr}")
    fallback, traced = read_images(ws.path("fallback.exr"), ws.path("traced.exr"))
    expect(fallback.pixels == traced.pixels, "the fallback differs from the traced shadows")


# shadowpoint: a point light 3 above a floor (y = 0) and four spheres whose shadows fall on the
# floor where the light sees it through four of its six maps: straight down (ny), along +x (px)
# and -z (nz), and one across the seam of the nx and ny faces. The maps' fov is a little over
# 90°, so that a lookup's filter region near a face's edge stays inside its map. The shadows
# are compared where the floor is within 60° of facing the light: the default bias is made for
# up to 63° (docs/shading-language.md, Shadow maps), and beyond that the floor shadows itself.
POINT_LIGHT = (0, 3, 0)
SPHERES = [((0, 1.5, 0), 0.5), ((2, 1.6, 0.3), 0.5), ((-0.3, 1.6, -2), 0.5),
           ((-1.5, 1.5, 0.2), 0.5)]
FACES = {"px": (1, 0, 0), "nx": (-1, 0, 0), "py": (0, 1, 0), "ny": (0, -1, 0),
         "pz": (0, 0, 1), "nz": (0, 0, -1)}
# The camera rotation that turns each axis into the camera's +z (its view direction).
FACE_ROTATIONS = {"px": "Rotate -90 0 1 0", "nx": "Rotate 90 0 1 0", "py": "Rotate 90 1 0 0",
                  "ny": "Rotate -90 1 0 0", "pz": "", "nz": "Rotate 180 0 1 0"}
CUBE_FOV, CUBE_SIZE = 95, 256
FLOOR_GEOMETRY = 'Surface "matte"\n' + "".join(
    f"AttributeBegin\nTranslate {x} {y} {z}\nSphere {r} {-r} {r} 360\nAttributeEnd\n"
    for (x, y, z), r in SPHERES) + 'Polygon "P" [-12 0 -12  -12 0 12  12 0 12  12 0 -12]\n'
CUBE_FRAME = """FrameBegin {n}
Format {size} {size} 1
PixelSamples 2 2
Projection "perspective" "fov" [{fov}]
{rotation}
Translate {tx} {ty} {tz}
Display "{face}.z" "zfile" "z"
WorldBegin
{geometry}WorldEnd
FrameEnd
MakeShadow "{face}.z" "{face}.sm"
"""
# The viewer looks straight down on the floor from 14 above the light's foot: pixel (px, py)
# sees the floor point (x, 0, z), x growing along the image's width and z up its height.
VIEW_HEIGHT, VIEW_SIZE, VIEW_FOV = 14, 128, 60
POINT_VIEW_FRAME = """FrameBegin {n}
Format {size} {size} 1
PixelSamples 2 2
PixelFilter "box" 1 1
Projection "perspective" "fov" [{fov}]
Rotate -90 1 0 0
Translate 0 {ty} 0
Display "{name}.exr" "openexr" "rgb"
Display "+{name}_z.exr" "openexr" "z"
Display "+{name}.z" "zfile" "z"
WorldBegin
{light}LightSource "shadowpoint" 1 "intensity" 36 "point from" [{lx} {ly} {lz}] {maps}
{geometry}WorldEnd
FrameEnd
"""


def cube_frames(first):
    lx, ly, lz = POINT_LIGHT
    return "".join(CUBE_FRAME.format(n=first + k, size=CUBE_SIZE, fov=CUBE_FOV, rotation=rotation,
                                     tx=-lx, ty=-ly, tz=-lz, face=face, geometry=FLOOR_GEOMETRY)
                   for k, (face, rotation) in enumerate(FACE_ROTATIONS.items()))


def point_view(n, name, maps="", light=""):
    lx, ly, lz = POINT_LIGHT
    return POINT_VIEW_FRAME.format(n=n, size=VIEW_SIZE, fov=VIEW_FOV, ty=-VIEW_HEIGHT, name=name,
                                   light=light, lx=lx, ly=ly, lz=lz, maps=maps,
                                   geometry=FLOOR_GEOMETRY)


def floor_point(px, py):
    half = VIEW_HEIGHT * math.tan(math.radians(VIEW_FOV / 2))
    return (half * (-1 + 2 * (px + 0.5) / VIEW_SIZE), 0, half * (1 - 2 * (py + 0.5) / VIEW_SIZE))


def dominant_face(d):
    axis = max(range(3), key=lambda k: abs(d[k]))
    return ("p" if d[axis] > 0 else "n") + "xyz"[axis]


def edge_margin(point):
    """The angle, seen from the light, between `point` and the nearest edge of a sphere's
    shadow (a sphere's silhouette cone), and whether the point lies inside some shadow."""
    d = [p - l for p, l in zip(point, POINT_LIGHT)]
    dist = math.sqrt(sum(v * v for v in d))
    margin, inside = math.pi, False
    for centre, r in SPHERES:
        c = [p - l for p, l in zip(centre, POINT_LIGHT)]
        cdist = math.sqrt(sum(v * v for v in c))
        angle = math.acos(max(-1, min(1, sum(a * b for a, b in zip(c, d)) / (cdist * dist))))
        margin = min(margin, abs(angle - math.asin(r / cdist)))
        inside = inside or angle < math.asin(r / cdist)
    return margin, inside, dist


def six_maps_shadow_a_point_light_like_rays(ws):
    maps = " ".join(f'"string sf{face}" "{face}.sm"' for face in FACES)
    rib = (cube_frames(1) + point_view(7, "mapped", maps) + point_view(8, "traced", light=TRACED) +
           point_view(9, "unshadowed"))
    proc = ws.render(rib, "shadowpoint", args=["--stats"])
    expect("warning" not in proc.stderr, f"the render warned:\n{proc.stderr}")
    for face, axis in FACES.items():  # each map's camera looks along its axis from the light
        camera = read_zfile(ws.path(face + ".z"))[3]
        ahead = transform([l + a for l, a in zip(POINT_LIGHT, axis)], camera)
        expect(max(abs(ahead[0]), abs(ahead[1]), abs(ahead[2] - 1)) < 1e-5,
               f"map {face}: one unit along {axis} from the light is at camera {ahead}")
    _, _, screen, camera, _ = read_zfile(ws.path("mapped.z"))
    for px, py in ((0, 0), (100, 20)):  # floor_point is where the viewer's pixels look
        sx, sy, _ = transform(floor_point(px, py), screen)
        expect(abs(transform(floor_point(px, py), camera)[2] - VIEW_HEIGHT) < 1e-4 and
               abs(sx - (-1 + 2 * (px + 0.5) / VIEW_SIZE)) < 1e-4 and
               abs(sy - (1 - 2 * (py + 0.5) / VIEW_SIZE)) < 1e-4,
               f"pixel ({px},{py}) does not see floor point {floor_point(px, py)}")
    mapped, traced, unshadowed, depth = read_images(
        *(ws.path(f + ".exr") for f in ("mapped", "traced", "unshadowed", "traced_z")))
    # Angles seen from the light: a map texel is at most 2 tan(fov/2) / size wide (at its
    # centre), a viewer pixel's footprint on the floor at most pixel / distance. The mapped edge
    # may move by a texel, half the filter region and half a pixel's diagonal, as for the spot
    # light above; a traced edge pixel is judged by its centre, up to half its diagonal away.
    texel = 2 * math.tan(math.radians(CUBE_FOV / 2)) / CUBE_SIZE
    pixel = 2 * VIEW_HEIGHT * math.tan(math.radians(VIEW_FOV / 2)) / VIEW_SIZE
    floor = [p for p, (z,) in depth.pixels.items() if abs(z - VIEW_HEIGHT) < 1e-3]
    shadowed_by_face, mismatched, far, compared = {}, [], [], 0
    for p in floor:
        lit = unshadowed.pixels[p][0]
        expect(lit > 0, f"floor pixel {p} is unlit without shadows")
        traced_fraction = 1 - traced.pixels[p][0] / lit
        mapped_fraction = 1 - mapped.pixels[p][0] / lit
        point = floor_point(*p)
        margin, inside, dist = edge_margin(point)
        footprint = pixel / dist
        expect(abs(traced_fraction - (1 if inside else 0)) < 1e-4 or
               margin < footprint * math.sqrt(0.5),
               f"floor pixel {p}: traced shadow {traced_fraction:.3f}, the spheres say {inside}")
        if POINT_LIGHT[1] / dist < math.cos(math.radians(60)):
            continue
        compared += 1
        if traced_fraction > 0.999:
            face = dominant_face([a - b for a, b in zip(point, POINT_LIGHT)])
            shadowed_by_face[face] = shadowed_by_face.get(face, 0) + 1
        if abs(mapped_fraction - traced_fraction) > 0.1:
            mismatched.append(p)
            if margin > texel + max(texel, footprint) / 2 + footprint * math.sqrt(0.5):
                far.append(p)
    expect(all(shadowed_by_face.get(face, 0) > 50 for face in ("px", "nx", "ny", "nz")),
           f"shadowed floor pixels per map face: {shadowed_by_face}")
    expect(len(mismatched) < 0.02 * compared,
           f"{len(mismatched)} of {compared} floor pixels differ from the traced shadows")
    expect(not far, f"pixels {far[:5]} differ from the traced shadows away from their edges")
    rays = frame_shadow_rays(proc.stderr)
    expect(len(rays) == 9 and rays[6] == 0 and rays[7] > 1000,
           f"shadow rays per frame {rays}: the mapped frame should trace none")


# The depth map of a stepped ground seen along +z by an orthographic camera at the origin: depth
# 3 for x < 0, 2.85 for x > 0. A unit-matrix ellipsoid at (0, 0, 3) (surface radius 0.4542) plus
# a repelling plane (A = 1, B = 0.01, C = 1, D = 0) on that map is seen from behind, from
# z = 6, by an orthographic camera turned round (camera x = −world x, depth = 6 − z).
GROUND_FRAME = """FrameBegin 1
Format 64 64 1
Projection "orthographic"
Display "ground.z" "zfile" "z"
WorldBegin
Polygon "P" [-2 -2 3  0 -2 3  0 2 3  -2 2 3]
Polygon "P" [0 -2 2.85  2 -2 2.85  2 2 2.85  0 2 2.85]
WorldEnd
FrameEnd
"""
BLOB_FRAME = """FrameBegin {n}
Format 64 64 1
Projection "orthographic"
Rotate 180 0 1 0
Translate 0 0 -6
Display "{name}.exr" "openexr" "z"
WorldBegin
Blobby 2 [1001 0 1003 0 16 0 2 0 1] [1 0 0 0 0 1 0 0 0 0 1 0 0 0 3 1  1 0.01 1 0] ["{map}"]
WorldEnd
FrameEnd
"""


def nearest_blob_depths(image):
    """The smallest depth of the blob's pixels left (world x < −0.1) and right (x > 0.1)."""
    left, right = [], []
    for (px, _), (z,) in image.pixels.items():
        world_x = -(-1 + (px + 0.5) / 32)
        if z < 100:
            (left if world_x < -0.1 else right if world_x > 0.1 else []).append(z)
    expect(len(left) > 100 and len(right) > 100, f"{len(left)} and {len(right)} blob pixels")
    return min(left), min(right)


def blobby_plane_repels_from_the_depth_map(ws):
    # Frame 4 renders the ground again, flat at depth 3: frame 5's Blobby reads the new map.
    flat = GROUND_FRAME.replace("FrameBegin 1", "FrameBegin 4").replace("2.85", "3")
    rib = (GROUND_FRAME + BLOB_FRAME.format(n=2, name="cut", map="ground.z") +
           BLOB_FRAME.format(n=3, name="whole", map="nothere.z") + flat +
           BLOB_FRAME.format(n=5, name="flat", map="ground.z"))
    proc = ws.render(rib, "blobplane")
    warnings = re.findall(r".*warning: .*", proc.stderr)
    expect(len(warnings) == 1 and re.match(r".*blobplane\.rib:\d+(:\d+)?: warning", warnings[0])
           and '"nothere.z" is not used' in warnings[0],
           f"expected one located warning about the missing map, got:\n{proc.stderr}")
    cut, whole, flat_cut = read_images(*(ws.path(f + ".exr") for f in ("cut", "whole", "flat")))
    # From behind, the nearest blob points are the cut face, just in front of the ground (the
    # repulsion −B/h·(1 − ease(h/A)) brings the field under 0.5 within about 0.04 of it).
    left, right = nearest_blob_depths(cut)
    expect(6 - 3 < left < 6 - 3 + 0.06, f"left of the step the blob reaches depth {left}")
    expect(6 - 2.85 < right < 6 - 2.85 + 0.06, f"right of the step the blob reaches depth {right}")
    left, right = nearest_blob_depths(flat_cut)
    expect(abs(left - right) < 0.01 and 6 - 3 < right < 6 - 3 + 0.06,
           f"on the flat ground the blob reaches depths {left}, {right}")
    # Without its map the plane is z = 0, 3 units away: the sphere is whole, its back at 3.4542.
    left, right = nearest_blob_depths(whole)
    expect(abs(left - (6 - 3.4542)) < 0.03 and abs(right - (6 - 3.4542)) < 0.03,
           f"without the map the blob reaches depths {left}, {right}")


CHECKS = [zfile_holds_analytic_depths, two_pass_map_shadows_like_rays,
          default_bias_leaves_a_lit_plane_unshadowed, missing_map_falls_back_to_traced_shadows,
          six_maps_shadow_a_point_light_like_rays, blobby_plane_repels_from_the_depth_map]

if __name__ == "__main__":
    sys.exit(workspace_main(__doc__.splitlines()[0], CHECKS, "gonio-shadowmaps-"))
