#!/usr/bin/env python3
"""Exact checks of the standard shaders against their definitions (issue 3), through `gonio
render`: matte under a distantlight gives Ci = Kd·(N·L) on a unit sphere; a pointlight falls
off as 1/d²; plastic's highlight lies at the mirror direction; shadows of a distantlight, a
pointlight and a spotlight land where projection says.

    shading_checks.py --gonio build/bin/gonio [--known-bugs] [NAME ...]

The checks use the machinery of analytic_checks.py (one batch render, one oiiotool read) and
are its group "shading". Every expected value is computed here from the shader's formula, per
pixel, as the mean over a grid of points inside the pixel (the renders use a box filter of one
pixel)."""

import math
import sys

import analytic_checks
from analytic_checks import check, expect, ortho

# Every scene: an orthographic camera looking along +z at the world origin from z = -5 (world
# and camera space differ by that translation only), so screen x, y are world x, y and the view
# direction is +z: V = (0, 0, -1). Float RGBA images, box filter, 4x4 samples.
SUBSAMPLES = 4  # per pixel side, for the expected pixel means


class Frame:
    """Pixel geometry of an orthographic square frame `size` pixels wide over [-half, half]²."""

    def __init__(self, size, half):
        self.size, self.half = size, half
        self.pixel = 2.0 * half / size

    def options(self, extra=""):
        return ortho(fmt=f"{self.size} {self.size}",
                     window=f"-{self.half} {self.half} -{self.half} {self.half}", extra=extra)

    def screen(self, px, py, fx=0.5, fy=0.5):
        """Screen (= world) x, y of the point (fx, fy) inside pixel (px, py); y is up."""
        return -self.half + (px + fx) * self.pixel, self.half - (py + fy) * self.pixel

    def subsamples(self, px, py):
        return [self.screen(px, py, (i + 0.5) / SUBSAMPLES, (j + 0.5) / SUBSAMPLES)
                for i in range(SUBSAMPLES) for j in range(SUBSAMPLES)]

    def rim(self, px, py, margin):
        """Points `margin` pixels outside pixel (px, py), facing each row and column of its
        subsamples and its corners: where an edge lies on the pixel's border they are across it."""
        inside = [(i + 0.5) / SUBSAMPLES for i in range(SUBSAMPLES)]
        outside = (-margin, 1 + margin)
        return [self.screen(px, py, f, g) for f in outside for g in inside + list(outside)] + \
            [self.screen(px, py, g, f) for f in outside for g in inside]

    def raster(self, x, y):
        """Continuous raster position of screen point (x, y)."""
        return (x + self.half) / self.pixel, (self.half - y) / self.pixel


def normalize(v):
    length = math.sqrt(sum(c * c for c in v))
    return tuple(c / length for c in v)


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def smoothstep(lo, hi, x):
    """RISpec smoothstep: 0 below lo, 1 above hi, Hermite 3t² - 2t³ between."""
    if x <= lo:
        return 0.0
    if x >= hi:
        return 1.0
    t = (x - lo) / (hi - lo)
    return t * t * (3 - 2 * t)


def sphere_normal(x, y):
    """Normal of the unit sphere seen along +z at screen (x, y) (facing the camera)."""
    return (x, y, -math.sqrt(max(0.0, 1 - x * x - y * y)))


def close(value, want, relative, absolute):
    return abs(value - want) <= relative * abs(want) + absolute


# ---- matte under a distantlight -------------------------------------------------------------

MATTE_LIGHTS = {  # name: distantlight from, to (L = normalize(from - to))
    "axis": ((0, 0, 0), (0, 0, 1)),
    "oblique": ((0, 0, 0), (1, -1, 2)),
}


@check("shading")
def matte_sphere_is_kd_times_n_dot_l(b, me):
    """A unit sphere with matte Kd=0.5 Ka=0 under a distantlight of intensity 1: Ci = 0.5·N·L
    at every pixel (1%), once with the light along the view axis and once oblique (Ci = 0 where
    N·L < 0). An ambientlight of 0.3 must not show (Ka = 0)."""
    frame = Frame(96, 1.2)
    for name, (source, target) in MATTE_LIGHTS.items():
        world = ('LightSource "ambientlight" 1 "intensity" 0.3\n'
                 f'LightSource "distantlight" 2 "intensity" 1 "from" [{fmt(source)}] '
                 f'"to" [{fmt(target)}]\n'
                 'Surface "matte" "Ka" 0 "Kd" 0.5\nSphere 1 -1 1 360')
        b.frame(me, name, frame.options(), world)
    yield
    for name, (source, target) in MATTE_LIGHTS.items():
        light = normalize(sub(source, target))
        image, checked = b.image(me, name), 0
        for (px, py), value in image.pixels.items():
            points = frame.subsamples(px, py)
            if max(x * x + y * y for x, y in points) > 0.95 ** 2:
                continue  # the silhouette's pixels are only partly covered
            want = sum(0.5 * max(0.0, dot(sphere_normal(x, y), light)) for x, y in points)
            want /= len(points)
            for c in range(3):
                expect(close(value[c], want, 0.01, 0.001),
                       f"{name}: pixel ({px},{py}) channel {c} is {value[c]:.5f}, "
                       f"0.5·N·L = {want:.5f}")
            expect(value[3] == 1, f"{name}: alpha {value[3]} inside the sphere at ({px},{py})")
            checked += 1
        expect(checked > 4000, f"{name}: only {checked} pixels checked")


def fmt(values):
    return " ".join(f"{v:g}" for v in values)


# ---- pointlight falls off as 1/d² -----------------------------------------------------------

POINT_DISTANCES = (1, 2)


@check("shading")
def pointlight_falls_off_as_inverse_square(b, me):
    """A plane facing the camera with matte Kd=1 Ka=0, lit by a pointlight of intensity 1 at
    distance d in front of it: Ci = cos θ / r² = d / (x² + y² + d²)^(3/2) at every pixel (1%),
    and the centre is 4 times brighter at d = 1 than at d = 2."""
    frame = Frame(64, 2)
    for d in POINT_DISTANCES:
        world = (f'LightSource "pointlight" 1 "intensity" 1 "from" [0 0 {-d}]\n'
                 'Surface "matte" "Ka" 0 "Kd" 1\n'
                 'Polygon "P" [-3 -3 0  3 -3 0  3 3 0  -3 3 0]')
        b.frame(me, str(d), frame.options(), world)
    yield
    for d in POINT_DISTANCES:
        for (px, py), value in b.image(me, str(d)).pixels.items():
            points = frame.subsamples(px, py)
            want = sum(d / (x * x + y * y + d * d) ** 1.5 for x, y in points) / len(points)
            expect(close(value[0], want, 0.01, 0.0005),
                   f"d = {d}: pixel ({px},{py}) is {value[0]:.5f}, d/r³ = {want:.5f}")
    centre = [(31, 31), (32, 31), (31, 32), (32, 32)]
    near = sum(b.image(me, "1").pixels[p][0] for p in centre)
    far = sum(b.image(me, "2").pixels[p][0] for p in centre)
    expect(close(near / far, 4.0, 0.01, 0), f"centre at d = 1 over d = 2: {near / far:.4f}, "
           "expected 4 (1/d²)")


# ---- plastic peaks at the mirror direction --------------------------------------------------

HIGHLIGHT_LIGHTS = {"upright": (1, 1, -2), "left": (-2, 1, -1)}  # distantlight from; to = 0


@check("shading")
def plastic_highlight_is_at_the_mirror_direction(b, me):
    """Plastic with Ks=1 only (Kd = Ka = 0, roughness 0.05) on a unit sphere under a
    distantlight: the brightest pixel is where the normal is the half vector
    H = normalize(L + V) (N = H, the mirror configuration), within 1.5 pixels, and its value is
    Ks·Cl·(N·H)^(8/roughness) = 1 there (2%)."""
    frame = Frame(200, 1)
    for name, source in HIGHLIGHT_LIGHTS.items():
        world = (f'LightSource "distantlight" 1 "from" [{fmt(source)}] "to" [0 0 0]\n'
                 'Surface "plastic" "Ka" 0 "Kd" 0 "Ks" 1 "roughness" 0.05\n'
                 'Sphere 1 -1 1 360')
        b.frame(me, name, frame.options(), world)
    yield
    for name, source in HIGHLIGHT_LIGHTS.items():
        half = normalize(tuple(l + v for l, v in zip(normalize(source), (0, 0, -1))))
        want = frame.raster(half[0], half[1])  # the sphere point whose normal is H
        pixels = b.image(me, name).pixels
        (px, py), value = max(pixels.items(), key=lambda item: item[1][0])
        distance = math.hypot(px + 0.5 - want[0], py + 0.5 - want[1])
        expect(distance <= 1.5, f"{name}: brightest pixel ({px},{py}), the mirror direction "
               f"is at raster ({want[0]:.2f},{want[1]:.2f}): {distance:.2f} pixels away")
        expect(close(value[0], 1.0, 0.02, 0), f"{name}: peak {value[0]:.4f}, expected 1")


# ---- shadows of every light type ------------------------------------------------------------

# A card (the occluder) 1 unit above a floor, both matte Kd=1 Ka=0, both facing the camera.
OCCLUDER = ((-1.5, -0.5), (-0.5, 0.5), -1.0)  # x range, y range, z
FLOOR_Z = 0.0
DISTANT_TOWARDS = normalize((-1.5, 0, -1))  # towards the distantlight
POINT_FROM = (-3, 0, -2)
SPOT = {"from": POINT_FROM, "to": (0, 0, 0), "coneangle": 0.6, "conedeltaangle": 0.1,
        "beamdistribution": 2, "intensity": 10}
SHADOW_LIGHTS = {
    # A distantlight from (-1.5, 0, -1) (to - from 18 units long): the card's shadow is the
    # card moved by (1.5, 0) on the floor, [0, 1] x [-0.5, 0.5].
    "distant": 'LightSource "distantlight" 1 "from" [-15 0 -10] "to" [0 0 0]',
    # The same direction with to - from 0.18 long: a distant light has a direction, not a
    # distance, so the shadow must be the same.
    "distant_short": 'LightSource "distantlight" 1 "from" [-0.15 0 -0.1] "to" [0 0 0]',
    # A pointlight at (-3, 0, -2), twice as high as the card: the shadow is the card scaled by
    # 2 from the light's foot, [0, 2] x [-1, 1].
    "point": f'LightSource "pointlight" 1 "intensity" 10 "from" [{fmt(POINT_FROM)}]',
    # A spotlight there, aimed at the origin: the same shadow, inside its cone.
    "spot": ('LightSource "spotlight" 1 ' + " ".join(
        f'"{k}" [{fmt(v) if isinstance(v, tuple) else v}]' for k, v in SPOT.items())),
}
SHADOW_FRAME = Frame(80, 2.5)  # pixels of 1/16: every edge of card and shadow is a pixel border
# A camera sample may lie anywhere in its pixel, up to the border, and where a shadow edge lies
# on the border its shadow ray grazes the card's edge. The floor point it starts from is known
# to about an ulp of the camera distance (5: 4.8e-7, 1.1e-5 pixels on the shadow), so a sample
# that close to the edge may fall either way. Such a pixel may be one sample off; an edge
# misplaced by 0.01 pixel would move one sample in about 2.5 pixels of each edge.
EDGE_MARGIN = 1e-4  # pixels
MAX_GRAZING = 2  # pixels of a frame that may be one grazing sample off


def in_occluder(x, y):
    (x0, x1), (y0, y1), _ = OCCLUDER
    return x0 <= x <= x1 and y0 <= y <= y1


def light_at(kind, p):
    """(unit vector towards the light, arriving Cl, distance to the light) at floor point p,
    as the light shaders define them."""
    if kind.startswith("distant"):
        return DISTANT_TOWARDS, 1.0, math.inf
    to_light = sub(POINT_FROM, p)
    distance2 = dot(to_light, to_light)
    towards = normalize(to_light)
    if kind == "point":
        return towards, 10 / distance2, math.sqrt(distance2)
    axis = normalize(sub(SPOT["to"], SPOT["from"]))
    cosangle = -dot(towards, axis)
    if cosangle < math.cos(SPOT["coneangle"]):
        return towards, 0.0, math.sqrt(distance2)  # outside illuminate's cone
    cl = SPOT["intensity"] * cosangle ** SPOT["beamdistribution"] / distance2
    cl *= smoothstep(math.cos(SPOT["coneangle"]),
                     math.cos(SPOT["coneangle"] - SPOT["conedeltaangle"]), cosangle)
    return towards, cl, math.sqrt(distance2)


def shadowed(p, towards, distance):
    """Whether the segment from floor point p towards the light crosses the card."""
    _, _, z = OCCLUDER
    t = (z - p[2]) / towards[2]
    if t <= 0 or t >= distance:
        return False
    return in_occluder(p[0] + t * towards[0], p[1] + t * towards[1])


def floor_radiance(kind, x, y):
    """(Ci of the floor at (x, y) unshadowed, whether the card shadows it)."""
    p = (x, y, FLOOR_Z)
    towards, cl, distance = light_at(kind, p)
    unshadowed = cl * max(0.0, dot((0, 0, -1), towards))
    return unshadowed, shadowed(p, towards, distance)


def add_shadow_frames(b, me, kinds):
    (x0, x1), (y0, y1), z = OCCLUDER
    for kind in kinds:
        world = ('Attribute "light" "shadows" "on"\n' + SHADOW_LIGHTS[kind] + '\n'
                 'Surface "matte" "Ka" 0 "Kd" 1\n'
                 'Polygon "P" [-4 -4 0  4 -4 0  4 4 0  -4 4 0]\n'
                 f'Polygon "P" [{x0} {y0} {z}  {x1} {y0} {z}  {x1} {y1} {z}  {x0} {y1} {z}]')
        b.frame(me, kind, SHADOW_FRAME.options(), world)


def expect_shadows_where_projected(b, me, kinds):
    """Every floor pixel is the light's unshadowed radiance (1%) outside the card's projected
    shadow and black inside it."""
    failures = {}
    for kind in kinds:
        in_shadow = lit = 0
        wrong, grazing = failures.setdefault(kind, []), []
        for (px, py), value in sorted(b.image(me, kind).pixels.items()):
            points = SHADOW_FRAME.subsamples(px, py)
            if any(in_occluder(x, y) for x, y in points):
                continue  # the card itself is seen there
            samples = [floor_radiance(kind, x, y) for x, y in points]
            if len({dark for _, dark in samples}) > 1:
                wrong.append(f"pixel ({px},{py}) straddles the predicted shadow edge")
                continue
            values = [0.0 if dark else ci for ci, dark in samples]
            want = sum(values) / len(values)
            # Where the light changes fast across the pixel (the spot's soft rim), 16 jittered
            # samples estimate its mean only to a fraction of that change.
            spread = max(values) - min(values)
            dark = samples[0][1]
            in_shadow += dark
            lit += not dark and want > 0.01
            tolerance = 0.002 + 0.1 * spread
            if close(value[0], want, 0.01, tolerance):
                continue
            rim = SHADOW_FRAME.rim(px, py, EDGE_MARGIN)
            on_edge = any(floor_radiance(kind, x, y)[1] != dark for x, y in rim)
            one = sum(ci for ci, _ in samples) / len(samples) / len(points)
            if on_edge and close(value[0], want + (one if dark else -one), 0.01, tolerance):
                grazing.append(f"pixel ({px},{py}) is {value[0]:.4f}, one grazing sample "
                               f"from {want:.4f}")
            else:
                wrong.append(f"pixel ({px},{py}) is {value[0]:.4f}, expected {want:.4f} "
                             f"({'in' if dark else 'out of'} the shadow)")
        if len(grazing) > MAX_GRAZING:
            wrong.extend(grazing)
        expect(in_shadow >= 200 and lit >= 800,
               f"{kind}: only {in_shadow} shadowed and {lit} lit pixels checked")
    report = [f"{kind}: {len(w)} wrong pixels, e.g.\n  " + "\n  ".join(w[:4])
              for kind, w in failures.items() if w]
    expect(not report, "\n".join(report))


@check("shading")
def shadows_land_where_projection_says(b, me):
    """A card above a floor under a distantlight, a pointlight and a spotlight with
    Attribute "light" "shadows" "on": the floor is the light's radiance (1%) outside the card's
    projected shadow and black inside it. The shadow's edges fall on pixel borders, so an edge
    misplaced by a fraction of a pixel shows as a column or row of wrong pixels."""
    kinds = ("distant", "point", "spot")
    add_shadow_frames(b, me, kinds)
    yield
    expect_shadows_where_projected(b, me, kinds)


@check("shading")
def distant_shadow_ignores_the_length_of_to_minus_from(b, me):
    """The same card and distantlight direction with to - from only 0.18 long: a distant light
    has a direction and no position, so its shadow is the same. (Today the shadow ray of every
    light ends at the tip of L, and a solar light's L is to - from: the card, 1.8 units away,
    casts no shadow.)"""
    add_shadow_frames(b, me, ("distant_short",))
    yield
    expect_shadows_where_projected(b, me, ("distant_short",))


if __name__ == "__main__":
    if "--group" not in sys.argv:
        sys.argv[1:1] = ["--group", "shading"]
    sys.exit(analytic_checks.main())
