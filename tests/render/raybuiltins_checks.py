#!/usr/bin/env python3
"""End-to-end checks, through `gonio render`, of the ray-traced built-ins (issue 17 item 3)
against analytic answers.

A probe surface shader evaluates a built-in at one fixed world point (the origin, axis +z) at
every pixel of an 8x8 frame, so each pixel is an independent estimate from its own random
stream; the probe sits on a card below the origin (z = -2, seen by a camera looking up +z),
which the probed rays, all going up, never meet. Each pixel must lie within 2% of the answer.

Cosine-distributed rays (the default) in a cone of half-angle α hit a target that covers
θ <= θ0 about the axis with probability sin²θ0 / sin²α (the cdf of p(θ) ∝ cos θ sin θ, Malley's
method, pbrt-v3 §13.6.3). So, at 1024 samples:

* occlusion at the base of the half-space z <= 0 (the ground disk) is 0, inside a hemisphere
  of radius 1 it is 1 (every ray meets the dome);
* under an infinite plane perpendicular to the axis at distance d, with "maxdist" D, a ray is
  occluded when d / cos θ <= D: 1 - (d/D)² = 0.84 for d = 1, D = 2.5;
* under a coaxial disc of radius a at height h, a² / (a² + h²) = 0.5 for a = h = 1 (the form
  factor of a parallel coaxial disc, Howell's catalogue B-12); with "distribution" "uniform"
  1 - h / sqrt(a² + h²) = 0.2929; with "coneangle" π/4 and a = 0.5, 0.2 / 0.5 = 0.4;
* "samplebase" 2 jitters the origins over a disc of radius one pixel (0.5 units here), whose
  mean of the off-axis form factor F(ρ) = ½(1 - (h² + ρ² - a²) / sqrt((h² + ρ² + a²)² - 4a²ρ²))
  is integrated here numerically;
* indirectdiffuse is E/π: under the disc of constant radiance Cs it is 0.5 Cs, plus 0.5 of a
  constant environment map's colour E with "environmentmap"; under an infinite matte plane
  (Kd 0.5) lit by a distant light of intensity 1 at 60° from its normal it is 0.5 cos 60° =
  0.25;
* gather() over the disc: hits/samples is 0.5, the mean "ray:length" of the hits is
  E[h / cos θ | θ <= θ0] = 2h(1 - cos θ0) / sin²θ0 = 1.1716, their mean "surface:Ci" is Cs,
  and hits + misses = samples;
* an ambient light in the style of Pixie's ambientocclusion runs at the surface points: a ground
  point at distance rho from the disc's axis gets Cl = 1 - F(rho);
* visibility() across the disc is 0 and beside it 1; transmission() through it with Opacity
  0.25 is 0.75 and beside it 1;
* the frame is the same, bit for bit, with --threads 1 and --threads 2.

Noise expected at 1024 samples: the rays are stratified over a 32 x 32 grid of (u1, u2) and each
target above is a range of u1 only, so only the 32 strata of one column straddle its edge: the
standard deviation is sqrt(32 q(1 - q)) / 1024 <= 0.0028, q the straddled part of that column
(plain Monte Carlo would give up to 0.016). Where the edge falls on a column boundary (the discs
of a = h, whose edge is at u1 = 1/2) the estimate is exact. The acceptance cases (half-space,
hemisphere, plane) must be within 2% at every pixel; the further cases, whose answers are
smaller, within 4 σ = 0.011 at every pixel and 2% in the mean over the 64 pixels (σ/8).
The checks print the largest deviation they saw.

    raybuiltins_checks.py --gonio build/bin/gonio

All frames go into one RIB file per thread count; images are read with one oiiotool."""

import argparse
import math
import os
import re
import subprocess
import sys
import tempfile

from analytic_checks import expect, read_images, render_in_folder, run_checks

SHADERS = {
    # An ambient light in the style of Pixie's ambientocclusion: it runs at the surface points.
    "occlusionlight.sl": """
light occlusionlight(float samples = 1024) {
    normal Nf = faceforward(normalize(N), I);
    Cl = 1 - occlusion(P, Nf, samples);
}
""",
    # The ambient light at each point, and where the point is (world x, y).
    "ambientonly.sl": """
surface ambientonly() {
    point Pw = transform("world", P);
    Ci = color(comp(ambient(), 0), xcomp(Pw), ycomp(Pw));
    Oi = 1;
}
""",
    "probe.sl": """
/* One ray-traced built-in at the world point `at` about the world axis `axis`. */
surface probe(string mode = "occlusion", distribution = "cosine", envmap = "";
              point at = point(0, 0, 0); vector axis = vector(0, 0, 1);
              float samples = 1024, maxdist = 1e30, coneangle = PI / 2, samplebase = 0) {
    point Pc = transform("world", "current", at);
    vector Nc = normalize(vtransform("world", "current", axis));
    if (mode == "occlusion") {
        Ci = occlusion(Pc, Nc, samples, "maxdist", maxdist, "coneangle", coneangle,
                       "distribution", distribution, "samplebase", samplebase);
    } else if (mode == "indirect") {
        Ci = indirectdiffuse(Pc, Nc, samples, "environmentmap", envmap);
    } else if (mode == "gather") {
        float hits = 0, misses = 0, length = 0, sumlength = 0;
        color hitcolour = 0, sumcolour = 0;
        gather("illuminance", Pc, Nc, PI / 2, samples, "ray:length", length,
               "surface:Ci", hitcolour) {
            hits += 1;
            sumlength += length;
            sumcolour += hitcolour;
        } else {
            misses += 1;
        }
        Ci = color(hits / samples, sumlength / max(hits, 1),
                   hits + misses == samples ? comp(sumcolour, 0) / max(hits, 1) : -1);
    } else {
        point far = Pc + 2 * Nc;
        vector beside = vtransform("world", "current", vector(5, 0, 0));
        Ci = color(visibility(Pc, far), comp(transmission(Pc, far), 0),
                   comp(transmission(Pc + beside, far + beside), 0)
                       * visibility(Pc + beside, far + beside));
    }
    Oi = 1;
}
""",
}

SIZE, HALF = 8, 2.0
PIXEL = 2 * HALF / SIZE
CAMERA = (f"Format {SIZE} {SIZE} 1\nPixelSamples 1 1\nPixelFilter \"box\" 1 1\n"
          f"Projection \"orthographic\"\nScreenWindow -{HALF} {HALF} -{HALF} {HALF}\n"
          "Translate 0 0 5\n")
CARD = 'Polygon "P" [-3 -3 -2  3 -3 -2  3 3 -2  -3 3 -2]'
CS = (0.8, 0.4, 0.2)
ENV = (0.1, 0.3, 0.5)


def probe(**params):
    text = "".join(f' "string {k}" "{v}"' if isinstance(v, str) else f' "float {k}" {v}'
                   for k, v in params.items())
    return f'AttributeBegin\nSurface "probe"{text}\n{CARD}\nAttributeEnd\n'


def disc(radius, height, extra=""):
    return (f'AttributeBegin\n{extra}Translate 0 0 {height}\nDisk 0 {radius} 360\n'
            'AttributeEnd\n')


CONSTANT = f'Surface "constant"\nColor [{CS[0]} {CS[1]} {CS[2]}]\n'
SUN = ('LightSource "distantlight" 1 "intensity" 1 "from" [0 0 0] '
       f'"to" [{math.sin(math.radians(60))} 0 {math.cos(math.radians(60))}]\n')
FRAMES = {
    "halfspace": probe() + disc(100, 0),
    "hemisphere": probe() + 'Sphere 1 0 1 360\n',
    "plane_maxdist": probe(maxdist=2.5) + disc(1e4, 1),
    "disc": probe() + disc(1, 1),
    "disc_uniform": probe(distribution="uniform") + disc(1, 1),
    "disc_cone": probe(coneangle=math.pi / 4) + disc(0.5, 1),
    "disc_samplebase": probe(samplebase=2) + disc(1, 1),
    "indirect_disc": probe(mode="indirect") + disc(1, 1, CONSTANT),
    "indirect_env": probe(mode="indirect", envmap="env.tx") + disc(1, 1, CONSTANT),
    "indirect_lit_plane": SUN + probe(mode="indirect") +
    disc(1e4, 1, 'Surface "matte" "Ka" 0 "Kd" 0.5\n'),
    "gather_disc": probe(mode="gather") + disc(1, 1, CONSTANT),
    "segments": probe(mode="segment") + disc(1, 1, 'Opacity [0.25 0.25 0.25]\n'),
    # Seen from above (camera at world z = +5 looking down): a ground plane under a disc the
    # camera sees through (one-sided, facing down).
    "ambient_light": 'LightSource "occlusionlight" 1\nSurface "ambientonly"\n'
    'Polygon "P" [-3 -3 0  -3 3 0  3 3 0  3 -3 0]\n' +
    disc(1, 1, 'Sides 1\nReverseOrientation\n'),
}
CAMERA_ABOVE = CAMERA.replace("Translate 0 0 5", "Rotate 180 1 0 0\nTranslate 0 0 -5")


def off_axis_form_factor(a, h, rho):
    """A parallel differential element at distance rho from the axis of a disc of radius a,
    height h (Howell's catalogue B-13)."""
    s = h * h + rho * rho + a * a
    return 0.5 * (1 - (h * h + rho * rho - a * a) / math.sqrt(s * s - 4 * a * a * rho * rho))


def jittered_form_factor(a, h, radius, steps=4000):
    """The mean of the form factor over origins uniform on a disc of `radius` (midpoint rule
    in rho, density 2 rho / radius²)."""
    total = 0.0
    for i in range(steps):
        rho = (i + 0.5) / steps * radius
        total += off_axis_form_factor(a, h, rho) * 2 * rho / (radius * radius) * radius / steps
    return total


def check_all(image, channel, want, tolerance, what):
    worst = max(abs(value[channel] - want) for value in image.pixels.values())
    expect(worst <= tolerance,
           f"{what}: a pixel is {worst:.4f} from {want:.4f} (tolerance {tolerance:.4f})")
    print(f"     {what}: {want:.4f}, worst pixel {worst:.5f} off over {len(image.pixels)} pixels")


SIGMA = math.sqrt(32 * 0.25) / 1024  # the largest standard deviation at 1024 samples


def check_noisy(image, want, what):
    """Every pixel within 4 σ, and the mean of the pixels within 2%."""
    check_all(image, 0, want, 4 * SIGMA, what)
    values = [v[0] for v in image.pixels.values()]
    mean = sum(values) / len(values)
    expect(abs(mean - want) <= 0.02 * want,
           f"{what}: the mean is {mean:.5f}, not within 2% of {want:.5f}")


def occlusion_matches_the_analytic_fractions(images):
    check_all(images["halfspace"], 0, 0.0, 0.02, "half-space base")
    check_all(images["hemisphere"], 0, 1.0, 0.02, "inside a hemisphere")
    check_all(images["plane_maxdist"], 0, 0.84, 0.02 * 0.84, "plane at d=1, maxdist 2.5")
    check_noisy(images["disc"], 0.5, "disc a=h=1")
    check_noisy(images["disc_uniform"], 1 - 1 / math.sqrt(2), "disc, uniform distribution")
    check_noisy(images["disc_cone"], 0.4, "disc a=0.5, coneangle pi/4")


def samplebase_jitters_origins_over_a_pixel(images):
    want = jittered_form_factor(1, 1, PIXEL)  # samplebase 2: radius 2 x half a pixel
    values = [v[0] for v in images["disc_samplebase"].pixels.values()]
    mean = sum(values) / len(values)
    expect(abs(mean - want) <= 0.02 * want and abs(mean - 0.5) > 0.02 * 0.5,
           f"samplebase 2: the mean occlusion is {mean:.4f}; origins jittered over a disc of "
           f"radius {PIXEL} give {want:.4f} (0.5 without jitter)")
    print(f"     samplebase 2: mean {mean:.4f}, jittered form factor {want:.4f}")


def indirectdiffuse_is_irradiance_over_pi(images):
    for c in range(3):
        check_all(images["indirect_disc"], c, 0.5 * CS[c], 0.02 * 0.5 * CS[c],
                  f"disc of constant Cs, channel {c}")
        want = 0.5 * CS[c] + 0.5 * ENV[c]
        check_all(images["indirect_env"], c, want, 0.02 * want,
                  f"disc and environment map, channel {c}")
    check_all(images["indirect_lit_plane"], 0, 0.25, 0.02 * 0.25, "lit matte half-space")


def gather_counts_lengths_and_colours(images):
    image = images["gather_disc"]
    check_all(image, 0, 0.5, 0.02 * 0.5, "gather hits / samples")
    length = 2 * (1 - math.cos(math.pi / 4)) / 0.5
    check_all(image, 1, length, 0.02 * length, "gather mean ray:length")
    check_all(image, 2, CS[0], 0.02 * CS[0], "gather mean surface:Ci (and hits + misses)")


def an_ambient_light_runs_at_the_surface_points(images):
    """Pixie's ambientocclusion style: Cl = 1 - occlusion(P, faceforward(N, I)) at each ground
    point, against the off-axis form factor of the disc at the point's distance from its axis."""
    worst = 0.0
    for value in images["ambient_light"].pixels.values():
        rho = math.hypot(value[1], value[2])
        want = 1 - off_axis_form_factor(1, 1, rho)
        worst = max(worst, abs(value[0] - want))
    expect(worst <= 4 * SIGMA, f"ambient occlusion light: a pixel is {worst:.4f} from 1 - F(rho)")
    print(f"     ambient occlusion light: worst pixel {worst:.5f} off 1 - F(rho)")


def visibility_and_transmission(images):
    image = images["segments"]
    check_all(image, 0, 0.0, 1e-6, "visibility across the disc")
    check_all(image, 1, 0.75, 1e-5, "transmission through Opacity 0.25")
    check_all(image, 2, 1.0, 1e-6, "transmission x visibility beside the disc")


def scene_text():
    return "".join(f'FrameBegin {number}\n{CAMERA_ABOVE if name == "ambient_light" else CAMERA}'
                   f'Display "{name}.exr" "file" "rgba"\nWorldBegin\n{world}WorldEnd\nFrameEnd\n'
                   for number, (name, world) in enumerate(FRAMES.items(), 1))


def make_environment(folder):
    """env.tx: a constant lat-long environment map of colour ENV."""
    subprocess.run(["oiiotool", "--pattern", "constant:color={},{},{}".format(*ENV), "16x8", "3",
                    "-d", "float", "-oenv", os.path.join(folder, "env.tx")], check=True,
                   capture_output=True)


NESTED_SHADER = ("surface nested() { normal Nf = faceforward(normalize(N), I); "
                 "Ci = Cs * indirectdiffuse(P, Nf, 16); }")
NESTED_SCENE = """Format 16 16 1
PixelSamples 1 1
Display "nested.tif" "tiff" "rgba"
Projection "perspective" "fov" [60]
Translate 0 0 3
WorldBegin
Surface "nested"
Sphere 1 -1 1 360
AttributeBegin
Translate 0 0 -3
Sphere 5 -5 5 360
AttributeEnd
WorldEnd
"""


def nested_indirectdiffuse_stops_at_the_diffuse_depth(gonio):
    """Every surface calls indirectdiffuse(16) and an enclosing sphere catches every ray, so
    each camera hit traces 16 rays whose hits are shaded; at the default maxdiffusedepth 1 the
    indirectdiffuse() of those hits brings nothing and must trace no ray: the sampled rays are
    exactly 16 per camera ray (they were 16 + 16², the second level traced and discarded)."""
    with tempfile.TemporaryDirectory(prefix="gonio_nested_") as folder:
        with open(os.path.join(folder, "nested.sl"), "w") as f:
            f.write(NESTED_SHADER + "\n")
        with open(os.path.join(folder, "scene.rib"), "w") as f:
            f.write(NESTED_SCENE)
        proc = subprocess.run([gonio, "render", "--stats", "scene.rib"], cwd=folder,
                              capture_output=True, text=True)
    expect(proc.returncode == 0, f"the nested scene did not render:\n{proc.stderr}")
    stats = proc.stderr
    found = re.search(r"(\d+) camera rays, .*?(\d+) sampled", stats)
    expect(found, f"no ray counts in --stats: {stats}")
    camera, sampled = int(found[1]), int(found[2])
    expect(sampled == 16 * camera,
           f"{sampled} sampled rays for {camera} camera rays, expected {16 * camera}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--gonio", required=True)
    args = parser.parse_args()
    gonio = os.path.abspath(args.gonio)
    images = {}
    for threads in (1, 2):
        with tempfile.TemporaryDirectory(prefix="gonio_raybuiltins_") as folder:
            make_environment(folder)
            failure = render_in_folder(gonio, folder, SHADERS, scene_text(),
                                       ["--threads", str(threads)])
            if failure:
                print(failure)
                return 1
            paths = [os.path.join(folder, name + ".exr") for name in FRAMES]
            images[threads] = dict(zip(FRAMES, read_images(*paths)))

    def same_with_one_and_two_threads(_):
        for name in FRAMES:
            expect(images[1][name].pixels == images[2][name].pixels,
                   f"{name} differs between --threads 1 and --threads 2")

    def nested_indirectdiffuse_past_the_depth(_):
        nested_indirectdiffuse_stops_at_the_diffuse_depth(gonio)

    checks = [occlusion_matches_the_analytic_fractions, samplebase_jitters_origins_over_a_pixel,
              indirectdiffuse_is_irradiance_over_pi, gather_counts_lengths_and_colours,
              an_ambient_light_runs_at_the_surface_points, visibility_and_transmission,
              same_with_one_and_two_threads, nested_indirectdiffuse_past_the_depth]
    return run_checks(checks, images[2])


if __name__ == "__main__":
    sys.exit(main())
