#!/usr/bin/env python3
"""End-to-end checks of the path tracer (Option "pathtrace", issue 17 item 4), through
`gonio render`, against analytic answers:

* the furnace lit by its own wall: a closed sphere that is an arealight of radiance 1 on its
  inside and matte of albedo ρ: L = 1 / (1 - ρ), 2 and 5, within 1% (σ printed, < 0.25%);
* the white furnace of a splat BRDF as a path-traced surface: a disk with a kd = 1 grid
  inside a black emitting sphere shows its albedo, 1 within 1%;

* the furnace: a closed matte sphere of albedo ρ and radius 1, lit by a point light of intensity
  π at its centre, seen by a camera there. The first bounce has radiance L₁ = ρ E₀ / π = ρ
  everywhere (E₀ = I / r² at normal incidence); the wall is then a uniform emitter of L₁ and
  every later bounce multiplies by ρ (a sphere's wall gathers π L from a uniform wall of
  radiance L), so L = L₁ / (1 - ρ): 1 for ρ = 0.5, 4 for ρ = 0.8. Within 1%, at 64 × 64 pixels
  × 16 paths, with Russian roulette on: the paths' own spread gives the standard error of the
  mean (σ ≈ 0.2%, computed and printed from the pixels), and maxdepth 200 leaves a bias of
  ρ^200 < 1e-19;
* the same furnace lined with a splat BRDF: brdfsurface with a .grd of a synthetic kd = 1
  Lambert map and Kb = 0.5, sampled from its splats (brdfsim/splat_sampler.h): L = Kb π f(0→0) /
  (1 - Kb a(0)) with the grid's own f and albedo a (`gonio brdf eval`, `info`; within 2% of 1),
  within 4σ of the paths' noise (σ ≈ 0.4% at 32 × 32 pixels × 16 paths) plus 0.2%;
* bad input: a missing or broken .grd is an error at the Surface's line (exit 1);
* determinism: a Cornell-like box with diffuse walls, a glossy sphere, a point light and an area
  light renders to the same pixels with 1 and 2 threads.

    pathtrace_checks.py --gonio build/bin/gonio"""

import math
import os
import re
import sys

from analytic_checks import expect, read_images, workspace_main

SIZE, SAMPLES = 64, 4  # 64 × 64 pixels, 4 × 4 paths each


def furnace(name, surface, options="", size=SIZE):
    return (f'Option "pathtrace" "integer enable" [1] "integer maxdepth" [200] {options}\n'
            f"Format {size} {size} 1\nPixelSamples {SAMPLES} {SAMPLES}\n"
            'PixelFilter "box" 1 1\nProjection "perspective" "fov" [90]\n'
            f'Quantize "rgba" 0 0 0 0\nDisplay "{name}.tif" "tiff" "rgba"\n'
            'WorldBegin\nLightSource "pointlight" 1 "from" [0 0 0] "intensity" [3.14159265]\n'
            f"{surface}\nSphere 1 -1 1 360\nWorldEnd\n")


def mean_and_error(image, c=0):
    """The mean of channel c (red) and its standard error from the spread of the pixels (each
    pixel averages its own independent paths)."""
    values = image.channel(c)
    n = len(values)
    mean = sum(values) / n
    variance = sum((v - mean) ** 2 for v in values) / (n - 1)
    return mean, math.sqrt(variance / n)


def check_furnace(ws, name, surface, expected, tolerance, options="", size=SIZE):
    ws.render(furnace(name, surface, options, size), name)
    (image,) = read_images(ws.path(name + ".tif"))
    mean, error = mean_and_error(image)
    print(f"     {name}: {mean:.5f} ± {error:.5f} (expected {expected})")
    expect(error < 0.25 * tolerance * expected,
           f"{name}: the noise {error:.5f} is too large for a {tolerance:.0%} check")
    expect(abs(mean / expected - 1) < tolerance,
           f"{name}: radiance {mean:.5f} ± {error:.5f}, expected {expected} within "
           f"{tolerance:.0%}")


def furnace_rho_05(ws):
    check_furnace(ws, "furnace05", 'Surface "matte" "Kd" [0.5] "Ka" [0]', 1.0, 0.01)


def furnace_rho_08(ws):
    # Roulette from bounce 8: the first 8 bounces (83% of the answer) are then exact, which
    # keeps σ at 0.2% for 16 paths a pixel; the rest still goes through the roulette.
    check_furnace(ws, "furnace08", 'Surface "matte" "Kd" [0.8] "Ka" [0]', 4.0, 0.01,
                  '"integer rrdepth" [8]')


def area_furnace(ws, rho, options=""):
    """The furnace lit by its own wall: the sphere is an arealight of radiance 1 on its inside
    (ReverseOrientation) and matte of albedo ρ, so L = 1 / (1 - ρ). Every vertex samples the
    wall by area and by its BSDF, weighed by the power heuristic."""
    surface = ('AreaLightSource "arealight" 2 "intensity" [1]\nReverseOrientation\n'
               f'Surface "matte" "Kd" [{rho}] "Ka" [0]')
    name = f"areafurnace{int(rho * 10)}"
    ws.render(furnace(name, surface, options).replace(
        'LightSource "pointlight" 1 "from" [0 0 0] "intensity" [3.14159265]\n', ""), name)
    (image,) = read_images(ws.path(name + ".tif"))
    mean, error = mean_and_error(image)
    expected = 1 / (1 - rho)
    print(f"     {name}: {mean:.5f} ± {error:.5f} (expected {expected:g})")
    expect(error < 0.0025 * expected, f"{name}: the noise {error:.5f} is too large")
    expect(abs(mean / expected - 1) < 0.01,
           f"{name}: radiance {mean:.5f} ± {error:.5f}, expected {expected} within 1%")


def area_furnace_rho_05(ws):
    area_furnace(ws, 0.5)


def area_furnace_rho_08(ws):
    area_furnace(ws, 0.8, '"integer rrdepth" [8]')  # as furnace_rho_08


def make_white_grid(ws):
    if not os.path.exists(ws.path("white.grd")):
        ws.run(["brdf", "synth", "lambert:1", "-n", "200000", "--stratified", "-o", "white.pm"])
        ws.run(["brdf", "opt", "4", "9", "0.3", "0", "white.pm", "white.grd"])


def inside_emitter(name, surface, samples=8):
    """A surface (Disk of radius 1 at the origin) seen orthographically along its normal from
    inside a black sphere of radiance 1 (an arealight, radius 2), at 32 × 32 pixels."""
    return ('Option "pathtrace" "integer enable" [1]\nFormat 32 32 1\n'
            f'PixelSamples {samples} {samples}\nPixelFilter "box" 1 1\n'
            'Projection "orthographic"\nScreenWindow -0.3 0.3 -0.3 0.3\n'
            f'Quantize "rgba" 0 0 0 0\nDisplay "{name}.tif" "tiff" "rgba"\n'
            "Translate 0 0 1.2\nRotate 180 1 0 0\nWorldBegin\n"
            'AttributeBegin\nAreaLightSource "arealight" 1 "intensity" [1]\nReverseOrientation\n'
            'Surface "matte" "Kd" [0] "Ka" [0]\nSphere 2 -2 2 360\nAttributeEnd\n'
            f"{surface}\nDisk 0 1 360\nWorldEnd\n")


def splat_plane_reflects_all_energy(ws):
    """The white furnace of the splat BRDF as a path-traced surface: a disk shaded with the
    kd = 1 grid inside a black sphere of radiance 1 (an arealight, radius 2), seen along its
    normal, shows its albedo ∫ f cos θ dω = 1 (`gonio brdf info` gives 1.0004 at 0°) within 1%,
    at 32 × 32 pixels × 64 paths of one bounce each (σ printed, below 0.25%)."""
    make_white_grid(ws)
    rib = inside_emitter("whiteplane", 'Surface "brdfsurface" "string grid" "white.grd"')
    ws.render(rib, "whiteplane")
    (image,) = read_images(ws.path("whiteplane.tif"))
    mean, error = mean_and_error(image)
    print(f"     whiteplane: albedo {mean:.5f} ± {error:.5f}")
    expect(error < 0.0025, f"whiteplane: the noise {error:.5f} is too large")
    expect(abs(mean - 1) < 0.01, f"whiteplane: albedo {mean:.5f} ± {error:.5f}, not 1 within 1%")


def transparent_sheet_passes_one_minus_os(ws):
    """Stochastic transparency: a black sheet of Opacity (0.25, 0.5, 0.75) in front of a wall of
    radiance 1 shows 1 − Os = (0.75, 0.5, 0.25). Each path passes with probability 1 − 0.5 and
    carries (1 − Os)/0.5, so a pixel of 64 paths has σ = (1 − Os)/8 and the image mean
    σ = (1 − Os)/256 (0.3% of red); checked within 4σ of the measured noise."""
    ws.render(inside_emitter("sheet", 'Opacity [0.25 0.5 0.75]\nSurface "matte" "Kd" [0]'),
              "sheet")
    (image,) = read_images(ws.path("sheet.tif"))
    for c, expected in enumerate((0.75, 0.5, 0.25)):
        mean, error = mean_and_error(image, c)
        print(f"     sheet channel {c}: {mean:.5f} ± {error:.5f} (expected {expected})")
        expect(error < 0.005, f"sheet channel {c}: the noise {error:.5f} is too large")
        expect(abs(mean - expected) < 4 * error + 1e-4,
               f"sheet channel {c}: {mean:.5f} ± {error:.5f}, expected {expected}")


def shadow_through_a_sheet_is_one_minus_os(ws):
    """Shadow rays through a partly transparent surface: a point light 4 above a matte ground,
    a black sheet of Opacity (0.25, 0.5, 0.75) halfway up over the half x > 0 (the camera looks
    down from below the sheet). The light reaching the ground behind the sheet is 1 − Os of
    what reaches the mirror-image point in front of it; nothing else lights the ground (the
    sheet is black), so the ratio is exact: within 0.2% over the columns away from the edge."""
    rib = ('Option "pathtrace" "integer enable" [1]\nFormat 32 32 1\nPixelSamples 2 2\n'
           'PixelFilter "box" 1 1\nProjection "orthographic"\n'
           'Quantize "rgba" 0 0 0 0\nDisplay "shadow.tif" "tiff" "rgba"\n'
           "Rotate -90 1 0 0\nTranslate 0 -1 0\nWorldBegin\n"
           'LightSource "pointlight" 1 "from" [0 4 0] "intensity" [1]\n'
           'AttributeBegin\nOpacity [0.25 0.5 0.75]\nSurface "matte" "Kd" [0]\n'
           'Polygon "P" [0 2 -10  10 2 -10  10 2 10  0 2 10]\nAttributeEnd\n'
           'Surface "matte" "Kd" [1] "Ka" [0]\n'
           'Polygon "P" [-10 0 -10  10 0 -10  10 0 10  -10 0 10]\nWorldEnd\n')
    ws.render(rib, "shadow")
    (image,) = read_images(ws.path("shadow.tif"))
    lit, shaded = [0.0] * 3, [0.0] * 3
    for (x, y), p in image.pixels.items():
        if x < 14:  # in front of the sheet (x < 0); its mirror image 31 - x lies behind it
            mirror = image.pixels[(31 - x, y)]
            for c in range(3):
                lit[c] += p[c]
                shaded[c] += mirror[c]
    expect(lit[0] > 0, "the ground is black")
    # Which half of the image lies behind the sheet depends on the camera's handedness.
    if shaded[0] > lit[0]:
        lit, shaded = shaded, lit
    for c, expected in enumerate((0.75, 0.5, 0.25)):
        ratio = shaded[c] / lit[c]
        print(f"     shadow channel {c}: behind / in front {ratio:.5f} (expected {expected})")
        expect(abs(ratio / expected - 1) < 0.002,
               f"shadow channel {c}: {ratio:.5f} of the light passes, expected {expected}")


def specularcolor_tints_the_lobe(ws):
    """plastic's specularcolor tints its Ks lobe: Kd 0, Ks 1, specularcolor (1, 0.5, 0.25) inside
    a grey emitter, one bounce (the sphere is black, the disk cannot see itself), so every path
    carries the tint exactly: green / red = 0.5 and blue / red = 0.25 in every pixel (1e-4)."""
    ws.render(inside_emitter("tint", 'Surface "plastic" "Kd" [0] "Ks" [1] "Ka" [0] '
                             '"roughness" [0.2] "specularcolor" [1 0.5 0.25]', samples=2), "tint")
    (image,) = read_images(ws.path("tint.tif"))
    expect(image.mean(0) > 0.1, f"the lobe reflects {image.mean(0)}")
    for xy, p in image.pixels.items():
        if p[0] > 0:
            expect(abs(p[1] / p[0] - 0.5) < 1e-4 and abs(p[2] / p[0] - 0.25) < 1e-4,
                   f"pixel {xy} is {p[:3]}: not tinted (1, 0.5, 0.25)")


def splat_furnace(ws):
    make_white_grid(ws)
    # What this grid predicts: the first bounce Kb·f(0→0)·E₀ (E₀ = π), then each bounce Kb·a
    # with a its albedo at normal incidence (to second order in f's ±3% ripple over the wall's
    # directions, 0.1%).
    f0 = float(ws.run(["brdf", "eval", "--grid", "white.grd", "0", "0", "0", "0"]).stdout.split()[0])
    info = ws.run(["brdf", "info", "white.grd"]).stdout
    a0 = float(re.search(r"albedo\s+0 deg: ([0-9.]+)", info)[1])
    kb = 0.5
    predicted = kb * math.pi * f0 / (1 - kb * a0)
    expect(abs(predicted - 1) < 0.02, f"the white grid predicts {predicted}, not 1 within 2%")
    ws.render(furnace("splatfurnace", f'Surface "brdfsurface" "string grid" "white.grd" '
                      f'"float Kb" [{kb}]', size=32), "splatfurnace")
    (image,) = read_images(ws.path("splatfurnace.tif"))
    mean, error = mean_and_error(image)
    print(f"     splatfurnace: {mean:.5f} ± {error:.5f} (the grid predicts {predicted:.5f})")
    expect(error < 0.005, f"splatfurnace: the noise {error:.5f} is too large")
    expect(abs(mean - predicted) < 4 * error + 0.002 * predicted,
           f"splatfurnace: radiance {mean:.5f} ± {error:.5f}, the grid predicts {predicted:.5f}")


CORNELL = """Format 48 48 1
PixelSamples 2 2
Projection "perspective" "fov" [40]
Quantize "rgba" 0 0 0 0
Display "{name}.tif" "tiff" "rgba"
Option "pathtrace" "integer enable" [1]
Translate 0 0 3.5
WorldBegin
LightSource "pointlight" 1 "from" [0.5 0.8 0] "intensity" [0.5]
AttributeBegin
AreaLightSource "arealight" 2 "intensity" [15]
Surface "matte" "Kd" [0] "Ka" [0]
Polygon "P" [-0.3 0.99 -0.3  0.3 0.99 -0.3  0.3 0.99 0.3  -0.3 0.99 0.3]
AttributeEnd
Illuminate 2 1
Surface "matte" "Kd" [0.7] "Ka" [0]
Polygon "P" [-1 -1 -1  1 -1 -1  1 -1 1  -1 -1 1]
Polygon "P" [-1 1 -1  -1 1 1  1 1 1  1 1 -1]
Polygon "P" [-1 -1 1  1 -1 1  1 1 1  -1 1 1]
AttributeBegin
Color [0.8 0.1 0.1]
Polygon "P" [-1 -1 -1  -1 -1 1  -1 1 1  -1 1 -1]
Color [0.1 0.8 0.1]
Polygon "P" [1 -1 -1  1 1 -1  1 1 1  1 -1 1]
AttributeEnd
AttributeBegin
Surface "plastic" "Kd" [0.5] "Ks" [0.5] "roughness" [0.05]
Translate -0.4 -0.6 0.3
Sphere 0.4 -0.4 0.4 360
AttributeEnd
WorldEnd
"""


def same_pixels_whatever_the_threads(ws):
    ws.render(CORNELL.format(name="one"), "one", ["--threads", "1"])
    ws.render(CORNELL.format(name="two"), "two", ["--threads", "2"])
    one, two = read_images(ws.path("one.tif"), ws.path("two.tif"))
    expect(one.pixels == two.pixels, "the path-traced pixels depend on the thread count")
    mean = one.mean(0)
    expect(mean > 0.01, f"the box is black (mean red {mean})")


def bad_grids_are_located_errors(ws):
    """A grid a path-traced brdf() surface names that is missing or not a .grd: exit 1 with the
    Surface's RIB line, never a crash."""
    with open(ws.path("bogus.grd"), "w") as f:
        f.write("bogus")
    for grid, words in (("nothere.grd", "not found"), ("bogus.grd", "truncated")):
        rib = ('Option "pathtrace" "integer enable" [1]\nFormat 8 8 1\n'
               'Display "bad.tif" "tiff" "rgba"\nWorldBegin\nLightSource "pointlight" 1\n'
               f'Surface "brdfsurface" "string grid" "{grid}"\nTranslate 0 0 5\n'
               "Sphere 1 -1 1 360\nWorldEnd\n")
        proc = ws.render(rib, "bad", expect_code=1)
        expect(re.search(rf"bad\.rib:6:1: error: path tracing: .*{words}", proc.stderr),
               f"{grid}: no located error:\n{proc.stderr}")


CHECKS = [furnace_rho_05, furnace_rho_08, area_furnace_rho_05, area_furnace_rho_08,
          splat_plane_reflects_all_energy, splat_furnace, transparent_sheet_passes_one_minus_os,
          shadow_through_a_sheet_is_one_minus_os, specularcolor_tints_the_lobe,
          same_pixels_whatever_the_threads,
          bad_grids_are_located_errors]

if __name__ == "__main__":
    sys.exit(workspace_main(__doc__, CHECKS, "gonio_pathtrace_"))
