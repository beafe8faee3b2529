#!/usr/bin/env python3
"""End-to-end checks, through `gonio render`, of where lights are gathered and of the space of
environment() directions (issue 3):

* illuminance(P + offset) runs the pointlight at the offset position: a plane with a shader that
  gathers 1 unit closer to the light shows 1/(x² + y² + (d - 1)²) (1%), points that gather at P
  itself 1/(x² + y² + d²), in the same shader and batch, with derivatives on (neighbour points);
* a light shader's Ns is the normal of the surface point it lights, in camera space (a mirror
  at 45 degrees through a rolled camera);
* shinymetal's reflection of a lat-long environment map is the same wherever the camera looks
  from: a mirror at 45 degrees reflects the view ray to world -x; with the camera rolled by 90
  degrees about its view axis the pixel keeps its colour (the shader turns D into world space
  and environment() must use it as given), while a shader that turns D into world space twice,
  as the renderer once did, sees a pole of the map instead.

    light_env_checks.py --gonio build/bin/gonio

All frames go into one RIB file and one `gonio render`; images are read with one oiiotool."""

import os
import struct
import subprocess
import sys

from analytic_checks import EVERY_SAMPLE_SHADED, expect, frames_main

SHADERS = {
    # Gathers light at P moved towards the camera (world -z) by `dz` where x > `from_x`.
    "gather.sl": """
surface gather(float dz = 1, from_x = -1e9) {
    point Pw = transform("world", P);
    vector offset = xcomp(Pw) > from_x ? vector "world" (0, 0, -dz) : vector(0);
    color sum = 0;
    illuminance (P + offset) { sum += Cl; }
    Ci = sum;
    Oi = 1;
    if (area(P) < 0) Ci = 0;  /* derivatives on: the batch has neighbour points */
}
""",
    # Cl = |Ns|: the light shows the normal of the surface point it lights (issue 20).
    "nslight.sl": """
light nslight() {
    illuminate (point "world" (0, 0, -10)) {
        Cl = color(abs(xcomp(Ns)), abs(ycomp(Ns)), abs(zcomp(Ns)));
    }
}
""",
    "gatherall.sl": """
surface gatherall() { Ci = 0; illuminance (P) { Ci += Cl; } Oi = 1; }
""",
    # The renderer's old double transform, written out: D to world space twice.
    "twiceworld.sl": """
surface twiceworld(string texturename = "") {
    normal Nf = faceforward(normalize(N), I);
    vector D = vtransform("world", vtransform("world", reflect(I, Nf)));
    Ci = color environment(texturename, D);
    Oi = 1;
}
""",
}

SIZE, HALF = 32, 2.0  # square frames over [-HALF, HALF]², x = 0 on a pixel boundary
LIGHT_DISTANCE = 2.0
SUBSAMPLES = 4


def camera(roll=0):
    return (f"Format {SIZE} {SIZE} 1\nPixelSamples 4 4\nPixelFilter \"box\" 1 1\n"
            f"{EVERY_SAMPLE_SHADED}"
            f"Projection \"orthographic\"\nScreenWindow -{HALF} {HALF} -{HALF} {HALF}\n"
            f"Rotate {roll} 0 0 1\nTranslate 0 0 5\n")


PLANE = 'Polygon "P" [-3 -3 0  3 -3 0  3 3 0  -3 3 0]'
# The plane x + z = 0: its normal is ±(1, 0, 1)/√2, so the view ray +z reflects to world -x.
MIRROR = 'Polygon "P" [-3 -3 3  3 -3 -3  3 3 -3  -3 3 3]'
FRAMES = {
    "moved": (camera(), f'LightSource "pointlight" 1 "from" [0 0 {-LIGHT_DISTANCE}]\n'
              f'Surface "gather" "uniform float dz" 1\n{PLANE}'),
    "half_moved": (camera(), f'LightSource "pointlight" 1 "from" [0 0 {-LIGHT_DISTANCE}]\n'
                   f'Surface "gather" "uniform float dz" 1 "uniform float from_x" 0\n{PLANE}'),
    "env_roll0": (camera(0), 'Surface "shinymetal" "Ka" 0 "Ks" 0 "Kr" 1 '
                  f'"texturename" "sky.tx"\n{MIRROR}'),
    "env_roll90": (camera(90), 'Surface "shinymetal" "Ka" 0 "Ks" 0 "Kr" 1 '
                   f'"texturename" "sky.tx"\n{MIRROR}'),
    "env_twice": (camera(90), f'Surface "twiceworld" "texturename" "sky.tx"\n{MIRROR}'),
    "light_ns": (camera(90), f'LightSource "nslight" 1\nSurface "gatherall"\n{MIRROR}'),
}

# The map: 8 sectors of longitude with their own colours along the equator, centred on the
# multiples of 45 degrees (so the axis directions lie mid-sector), and a band of its own colour
# at each pole.
SECTOR_COLOURS = [(1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 1, 0), (1, 0.5, 0), (0, 0.5, 1),
                  (0.5, 0, 1), (0.5, 1, 0.5)]
POLE_COLOURS = [(1, 0, 1), (0, 1, 1)]
MAP_W, MAP_H = 64, 32


def map_texel(x, y):
    if y < MAP_H // 4:
        return POLE_COLOURS[0]
    if y >= MAP_H - MAP_H // 4:
        return POLE_COLOURS[1]
    return SECTOR_COLOURS[((x + MAP_W // 16) // (MAP_W // 8)) % 8]


def make_environment(folder):
    """sky.tx: the lat-long map above, written as an RGB PFM (rows bottom to top) and made an
    environment map with oiiotool -oenv."""
    pfm = os.path.join(folder, "sky.pfm")
    with open(pfm, "wb") as f:
        f.write(b"PF\n%d %d\n-1.0\n" % (MAP_W, MAP_H))
        for row in range(MAP_H - 1, -1, -1):
            for x in range(MAP_W):
                f.write(struct.pack("<3f", *map_texel(x, row)))
    subprocess.run(["oiiotool", pfm, "-oenv", os.path.join(folder, "sky.tx")], check=True,
                   capture_output=True)


def screen(px, py, fx, fy):
    pixel = 2 * HALF / SIZE
    return -HALF + (px + fx) * pixel, HALF - (py + fy) * pixel


def mean_over_pixel(px, py, value):
    points = [screen(px, py, (i + 0.5) / SUBSAMPLES, (j + 0.5) / SUBSAMPLES)
              for i in range(SUBSAMPLES) for j in range(SUBSAMPLES)]
    return sum(value(x, y) for x, y in points) / len(points)


def falloff(x, y, distance):
    return 1 / (x * x + y * y + distance * distance)


def check_gathered(image, name, moved_where):
    for (px, py), value in image.pixels.items():
        def want_at(x, y):
            moved = moved_where(x)
            return falloff(x, y, LIGHT_DISTANCE - 1 if moved else LIGHT_DISTANCE)
        want = mean_over_pixel(px, py, want_at)
        expect(abs(value[0] - want) <= 0.01 * want,
               f"{name}: pixel ({px},{py}) is {value[0]:.5f}, 1/d² at the gathering point "
               f"is {want:.5f}")


def illuminance_gathers_at_the_given_position(images):
    check_gathered(images["moved"], "moved", lambda x: True)
    check_gathered(images["half_moved"], "half_moved", lambda x: x > 0)


def centre(image):
    c = SIZE // 2
    return [sum(image.pixels[(x, y)][k] for x in (c - 1, c) for y in (c - 1, c)) / 4
            for k in range(3)]


def differs(a, b, tolerance):
    return max(abs(p - q) for p, q in zip(a, b)) > tolerance


def environment_reflection_does_not_turn_with_the_camera(images):
    level, rolled, twice = (centre(images[n]) for n in ("env_roll0", "env_roll90", "env_twice"))
    expect(any(not differs(level, colour, 2e-3) for colour in SECTOR_COLOURS),
           f"the reflection towards world -x is {level}, not a colour of the map's equator")
    expect(not differs(rolled, level, 1e-4),
           f"with the camera rolled 90 degrees the reflection is {rolled}, level it is {level}")
    expect(differs(twice, level, 0.2) and
           any(not differs(twice, colour, 2e-3) for colour in POLE_COLOURS),
           f"D turned to world space twice sees {twice}, expected a pole colour (the check "
           "would not catch a double transform)")


def light_shader_ns_is_the_surface_normal(images):
    """The mirror's normal ±(1, 0, 1)/√2 (world) seen through the camera rolled 90 degrees
    about its view axis is ±(0, ±1, 1)/√2 in camera space: |Ns| = (0, r, r), r = 1/√2."""
    r = 2 ** -0.5
    got = centre(images["light_ns"])
    expect(not differs(got, [0, r, r], 1e-3),
           f"Cl = |Ns| is {got}, not the mirror's camera-space normal |.| = (0, {r:.4f}, {r:.4f})")


CHECKS = [illuminance_gathers_at_the_given_position,
          environment_reflection_does_not_turn_with_the_camera,
          light_shader_ns_is_the_surface_normal]


def scene_text():
    return "".join(f'FrameBegin {number}\n{options}Display "{name}.exr" "file" "rgba"\n'
                   f'WorldBegin\n{world}\nWorldEnd\nFrameEnd\n'
                   for number, (name, (options, world)) in enumerate(FRAMES.items(), 1))


def main():
    return frames_main(__doc__.splitlines()[0], "gonio_light_env_", SHADERS, scene_text(),
                       {name: name + ".exr" for name in FRAMES}, CHECKS, make_environment)


if __name__ == "__main__":
    sys.exit(main())
