#!/usr/bin/env python3
"""End-to-end checks of area lights and shadows (issue 17) through `gonio render`.

The camera looks up (+z) from below at the plane z = 0, so it sees the plane's lit side from
behind and never the lights or blockers above it; the plane's shader returns the irradiance
diffuse() gathers about the world normal +z. With the arealight shader, whose Cl is the
radiance times cos θ at the emitter over the squared distance, and each of the n runs weighted
by 1/(pdf·n), that is E = ∫ L cos θ cos θ' / r² dA.

* disk: a disk of radius a at height h facing down, radiance L: on the axis E = π L a²/(h²+a²)
  (a Lambertian receiver under a uniform disk); the mean over the central pixels within 1% at
  256 light samples. Noise: one shaded point's 256-point stratified estimate is within about
  0.5% (the integrand varies by ~40% over the disk, stratified error ~N^-3/4), and the check
  averages 64 pixels × 4 independently shifted sample sets, so the 1% is ~20 standard errors
  of the noise and a weighting or pdf error of 1% fails it. Also written the way Pixie's
  arealight is (N = normalize(N) in the light), which must give the same.
* penumbra: a sphere between the disk and the plane; each pixel against the numerically
  integrated irradiance from the part of the disk the sphere leaves visible (a 160 × 320 polar
  grid, quadrature error < 0.2% of the unshadowed value), within 2% of the unshadowed value at
  256 samples and 16 pixel samples (noise ~0.4% there, mostly in the penumbra).
* transmission: a point light (shadows on) above a half-transparent plate: 1 − Os passes per
  colour component; "transparent" lets all through, "opaque" none.
* shadow map: a light shader written for shadow maps (shadow("map", Ps)) is shadowed by the map
  an earlier frame wrote from the light with a "shadow" display (exactly but in the two pixels
  beside the edge, which the filter softens) (the fallback to rays where the
  map is missing: tests/render/shadow_map_checks.py).
* threads: the penumbra's pixels are the same on 1 and 2 threads (and change with --seed).

    arealight_checks.py --gonio build/bin/gonio"""

import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "render"))
from analytic_checks import (expect, float_tiff, frames_main, read_images,  # noqa: E402
                             workspace_main)

SHADERS = {
    # The irradiance about world +z, whatever side the camera sees.
    "irradiance.sl": """
surface irradiance() {
    Ci = diffuse(normalize(normal "world" (0, 0, 1)));
    Oi = 1;
}
""",
    # The arealight semantics as Pixie's library writes them: the light's N normalised in place.
    "inplace_arealight.sl": """
light inplace_arealight(float intensity = 1; color lightcolor = 1) {
    N = normalize(N);
    illuminate(P, N, PI / 2) {
        Cl = intensity * lightcolor * (N . normalize(L)) / (L . L);
    }
}
""",
    # A point light written for a shadow map.
    "mapped.sl": """
light mapped(float intensity = 1; point from = point "shader" (0, 0, 0);
             string shadowname = "") {
    illuminate(from) {
        Cl = intensity / (L . L);
        if (shadowname != "") Cl *= 1 - shadow(shadowname, Ps, "width", 0.25);
    }
}
""",
}

DISK_A, DISK_H, RADIANCE = 1.0, 1.0, 2.0
PEN_A, PEN_H, SPHERE_R, SPHERE_Z = 0.5, 2.0, 0.3, 1.0


def camera(width, height, window, samples):
    return (f"Format {width} {height} 1\nPixelSamples {samples} {samples}\n"
            f"PixelFilter \"box\" 1 1\nProjection \"orthographic\"\n"
            f"ScreenWindow {window}\nTranslate 0 0 1\n")


PLANE = 'Surface "irradiance"\nPolygon "P" [-5 -5 0  5 -5 0  5 5 0  -5 5 0]'


def disk_light(shader, a, h, samples, shadows="off"):
    return (f'AttributeBegin\nAttribute "light" "nsamples" [{samples}] "shadows" "{shadows}"\n'
            f'AreaLightSource "{shader}" 1 "intensity" [{RADIANCE}]\n'
            f'ReverseOrientation\nDisk {h} {a} 360\nAttributeEnd\nIlluminate 1 1\n')


PEN_WINDOW = (0.0, 1.2, -0.05, 0.05)
PEN_W, PEN_H_PIXELS = 48, 4


def plate(opacity, transmission):
    mode = f'Attribute "visibility" "transmission" "{transmission}"\n' if transmission else ""
    return (f'AttributeBegin\nOpacity {opacity}\n{mode}'
            'Polygon "P" [-5 -5 1  5 -5 1  5 5 1  -5 5 1]\nAttributeEnd\n')


POINT_LIGHT = ('Attribute "light" "shadows" "on"\n'
               'LightSource "pointlight" 1 "from" [0 0 2]\n')
SMALL = camera(4, 4, "-0.01 0.01 -0.01 0.01", 1)
FRAMES = {
    "disk": (camera(8, 8, "-0.01 0.01 -0.01 0.01", 2),
             disk_light("arealight", DISK_A, DISK_H, 256) + PLANE),
    "disk_inplace": (camera(8, 8, "-0.01 0.01 -0.01 0.01", 2),
                     disk_light("inplace_arealight", DISK_A, DISK_H, 256) + PLANE),
    "penumbra": (camera(PEN_W, PEN_H_PIXELS, " ".join(map(str, PEN_WINDOW)), 4),
                 disk_light("arealight", PEN_A, PEN_H, 256, "on") +
                 f'AttributeBegin\nTranslate 0 0 {SPHERE_Z}\nSphere {SPHERE_R} -{SPHERE_R} '
                 f'{SPHERE_R} 360\nAttributeEnd\n' + PLANE),
    "plate_os": (SMALL, POINT_LIGHT + plate("0.25 0.5 0.75", None) + PLANE),
    "plate_transparent": (SMALL, POINT_LIGHT + plate("0.5 0.5 0.5", "transparent") + PLANE),
    "plate_opaque": (SMALL, POINT_LIGHT + plate("0.5 0.5 0.5", "opaque") + PLANE),
    # The depth seen from the light (2 above the plane, looking down), as the map of the next.
    "shadow_map_depth": ('Format 512 512 1\nProjection "perspective" "fov" [90]\n'
                         'Display "+light.shd" "shadow" "z"\nRotate 180 1 0 0\nTranslate 0 0 -2\n',
                         'Polygon "P" [-5 -5 1  0 -5 1  0 5 1  -5 5 1]\n' + PLANE),
    "shadow_map": (camera(32, 4, "-1 1 -0.0625 0.0625", 1),
                   'LightSource "mapped" 1 "from" [0 0 2] "string shadowname" "light.shd"\n'
                   'Polygon "P" [-5 -5 1  0 -5 1  0 5 1  -5 5 1]\n' + PLANE),
}


def disk_irradiance():
    """E = π L a² / (h² + a²) on the axis of a uniform disk."""
    return math.pi * RADIANCE * DISK_A ** 2 / (DISK_H ** 2 + DISK_A ** 2)


def mean_red(image):
    return sum(p[0] for p in image.pixels.values()) / len(image.pixels)


def disk_irradiance_on_the_axis(images):
    want = disk_irradiance()
    for name in ("disk", "disk_inplace"):
        got = mean_red(images[name])
        expect(abs(got - want) <= 0.01 * want,
               f"{name}: the mean irradiance on the axis is {got:.5f}, π L a²/(h²+a²) is "
               f"{want:.5f} ({100 * (got / want - 1):+.2f}%)")


def segment_hits_sphere(p, q):
    """Whether the segment p→q passes through the sphere of radius SPHERE_R at (0,0,SPHERE_Z)."""
    d = [q[i] - p[i] for i in range(3)]
    m = [p[0], p[1], p[2] - SPHERE_Z]
    a = sum(x * x for x in d)
    b = sum(m[i] * d[i] for i in range(3))
    c = sum(x * x for x in m) - SPHERE_R ** 2
    disc = b * b - a * c
    if disc < 0:
        return False
    root = math.sqrt(disc)
    t0, t1 = (-b - root) / a, (-b + root) / a
    return t1 > 0 and t0 < 1


def visible_irradiance(x, y, rings=160, sectors=320):
    """∫ L cos θ cos θ' / r² dA over the part of the disk light the sphere leaves visible, by
    the midpoint rule on a polar grid (exact in the unshadowed limit to O(1/rings²))."""
    total = 0.0
    for i in range(rings):
        rho = (i + 0.5) / rings * PEN_A
        area = rho * (PEN_A / rings) * (2 * math.pi / sectors)
        for j in range(sectors):
            phi = (j + 0.5) / sectors * 2 * math.pi
            q = (rho * math.cos(phi), rho * math.sin(phi), PEN_H)
            if segment_hits_sphere((x, y, 0.0), q):
                continue
            r2 = (q[0] - x) ** 2 + (q[1] - y) ** 2 + PEN_H ** 2
            total += RADIANCE * (PEN_H * PEN_H / r2) / r2 * area
    return total


def unshadowed_irradiance(rho):
    """A horizontal receiver at distance rho from the axis of a uniform disk (radius a, height
    h, radiance L) facing it: E = (π L / 2)(1 − (h² + ρ² − a²) / √((h² + ρ² + a²)² − 4a²ρ²))."""
    h2, r2, a2 = PEN_H ** 2, rho ** 2, PEN_A ** 2
    return math.pi * RADIANCE / 2 * (1 - (h2 + r2 - a2) / math.sqrt((h2 + r2 + a2) ** 2 -
                                                                     4 * a2 * r2))


def penumbra_matches_the_visible_fraction(images):
    image = images["penumbra"]
    x0, x1, y0, y1 = PEN_WINDOW
    row = PEN_H_PIXELS // 2
    y = y1 - (row + 0.5) * (y1 - y0) / PEN_H_PIXELS
    on_axis = unshadowed_irradiance(0)
    # The quadrature itself, where the sphere hides nothing, against the closed form.
    far = visible_irradiance(3.0, 0.0)
    expect(abs(far - unshadowed_irradiance(3.0)) <= 2e-3 * unshadowed_irradiance(3.0),
           f"the quadrature gives {far:.6f} unshadowed at 3, the closed form "
           f"{unshadowed_irradiance(3.0):.6f}")
    worst, profile = 0.0, []
    # Every fourth pixel of the row: the profile is smooth, and the integral costs time.
    for px in range(0, PEN_W, 4):
        x = x0 + (px + 0.5) * (x1 - x0) / PEN_W
        want = visible_irradiance(x, y)
        got = image.pixels[(px, row)][0]
        profile.append((x, want / unshadowed_irradiance(math.hypot(x, y)), want, got))
        worst = max(worst, abs(got - want))
    expect(min(f for _, f, _, _ in profile) < 0.01 and max(f for _, f, _, _ in profile) > 0.95,
           "the row does not cross from umbra to (nearly) full light: visible fractions " +
           ", ".join(f"{f:.3f}" for _, f, _, _ in profile))
    expect(worst <= 0.02 * on_axis,
           "the penumbra differs from the integrated visible fraction by up to "
           f"{worst:.4f} (allowed {0.02 * on_axis:.4f}): " +
           ", ".join(f"x={x:.3f} want {w:.4f} got {g:.4f}" for x, _, w, g in profile))


def shadows_pass_partly_transparent_objects(images):
    lit = 1 / 4  # the point light 2 above the plane's centre: 1/d², N·L = 1
    cases = {"plate_os": [lit * (1 - o) for o in (0.25, 0.5, 0.75)],
             "plate_transparent": [lit] * 3, "plate_opaque": [0.0] * 3}
    for name, want in cases.items():
        got = [sum(p[c] for p in images[name].pixels.values()) / len(images[name].pixels)
               for c in range(3)]
        expect(all(abs(g - w) <= 1e-3 * lit for g, w in zip(got, want)),
               f"{name}: the light through the plate is {got}, expected {want}")


def shadow_maps_shadow_a_light_shader(images):
    image = images["shadow_map"]
    # The blocker's shadow covers world x < 0; beyond it the light 2 above the plane gives
    # cos θ / d² = 2 / (x² + y² + 4)^(3/2).
    for (px, py), value in image.pixels.items():
        x = -1 + (px + 0.5) * 2 / 32
        y = 0.0625 - (py + 0.5) * 0.125 / 4
        want = 0.0 if x < 0 else 2 / (x * x + y * y + 4) ** 1.5
        if abs(x) < 2 / 32:
            # The pixels beside the edge: a sample there (one a pixel, anywhere in it) lies
            # within the map's filter reach of the edge, and is partly shadowed.
            lit = 2 / (x * x + y * y + 4) ** 1.5
            expect(-1e-6 <= value[0] <= lit * 1.02, f"shadow_map: edge pixel ({px},{py}) is "
                                                    f"{value[0]:.4f}, outside [0, {lit:.4f}]")
            continue
        expect(abs(value[0] - want) <= 0.02 * 0.25,
               f"shadow_map: pixel ({px},{py}) at x={x:.3f} is {value[0]:.4f}, want {want:.4f}")


CHECKS = [disk_irradiance_on_the_axis, penumbra_matches_the_visible_fraction,
          shadows_pass_partly_transparent_objects, shadow_maps_shadow_a_light_shader]


def scene_text():
    # The frame's float TIFF first, so that a "+" display among the options adds to it.
    return "".join(f'FrameBegin {number}\n{float_tiff(name + ".tif")}{options}'
                   f'WorldBegin\n{world}\nWorldEnd\nFrameEnd\n'
                   for number, (name, (options, world)) in enumerate(FRAMES.items(), 1))


def area_light_samples_do_not_depend_on_the_thread_count(ws):
    """The penumbra frame (256 light samples shifted per shaded point by its seed) gives the
    same pixels on 1 and 2 threads, and other pixels under another --seed."""
    options, world = FRAMES["penumbra"]
    with open(ws.path("p.rib"), "w") as f:
        f.write(f"{options}{float_tiff('p.tif')}WorldBegin\n{world}\nWorldEnd\n")
    for args, name in ((["--threads", "1"], "t1.tif"), (["--threads", "2"], "t2.tif"),
                       (["--seed", "7"], "s7.tif")):
        ws.run(["render", ws.path("p.rib"), *args, "-o", name])
    t1, t2, s7 = read_images(ws.path("t1.tif"), ws.path("t2.tif"), ws.path("s7.tif"))
    expect(t1.pixels == t2.pixels, "--threads 1 and --threads 2 wrote different pixels")
    expect(t1.pixels != s7.pixels, "--seed 7 did not change the light samples")


def main():
    status = frames_main(__doc__.splitlines()[0], "gonio_arealight_", SHADERS, scene_text(),
                         {name: name + ".tif" for name in FRAMES}, CHECKS)
    return status | workspace_main(__doc__.splitlines()[0],
                                   [area_light_samples_do_not_depend_on_the_thread_count],
                                   "gonio_arealight_threads_", SHADERS)


if __name__ == "__main__":
    sys.exit(main())
