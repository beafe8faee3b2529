#!/usr/bin/env python3
"""Checks of message passing, textureinfo, random() and AOV displays through `gonio render`
(issue 3): values that one shader passes to another reach the image exactly; an AOV of a
constant output parameter equals it; the N AOV of a sphere is its analytic normal; random()
gives the same image for --threads 1 and 2 and a different one for another --seed, and so does
random() stored in a uniform variable (one value per shader run); an image too
large for the machine is a located error.

    message_checks.py --gonio build/bin/gonio"""

import math
import os
import subprocess
import sys

from analytic_checks import EVERY_SAMPLE_SHADED, workspace_main, expect, read_images

SIZE, HALF = 16, 2.0  # an orthographic frame of SIZE² pixels over [-HALF, HALF]²
RADIUS = 1.5          # the sphere's

OPTIONS = f"""Format {SIZE} {SIZE} 1
PixelSamples 4 4
PixelFilter "box" 1 1
{EVERY_SAMPLE_SHADED}Quantize "rgba" 0 0 0 0
Projection "orthographic"
ScreenWindow -{HALF} {HALF} -{HALF} {HALF}
Translate 0 0 5
"""

SHADERS = {
    # displacement -> surface -> atmosphere, each reading the one before it.
    "msgdisp.sl": 'displacement msgdisp(output varying float bumpval = 0;) { bumpval = 0.25; }',
    "msgsurf.sl": """surface msgsurf(output float kd = 0.6; output varying color tint = 0;) {
    float d = 0, missing = 0;
    float ok = displacement("bumpval", d);
    float none = surface("nothing", missing);
    tint = color(0.1, 0.2, 0.3);
    Ci = color(d, ok - none, 0);
    Oi = 1;
}""",
    "msgatmo.sl": """volume msgatmo() {
    float k = 0;
    if (surface("kd", k) == 1) Ci = color(comp(Ci, 0), comp(Ci, 1), k);
}""",
    # lightsource() reads the current light's parameter: the intensities add up.
    "msglight.sl": """surface msglight() {
    float sum = 0;
    illuminance(P) {
        float i = 0;
        if (lightsource("intensity", i) == 1) sum += i;
    }
    Ci = sum;
    Oi = 1;
}""",
    "msgtexinfo.sl": """surface msgtexinfo() {
    float res[2] = {0, 0}, channels = 0;
    string kind = "";
    textureinfo("info.tif", "resolution", res);
    textureinfo("info.tif", "channels", channels);
    textureinfo("info.tif", "type", kind);
    float bad = textureinfo("missing.tif", "resolution", res);
    float notTexture = kind == "texture" ? 0 : 1;
    Ci = color(res[0] / 128, res[1] / 128, channels / 10 + bad + notTexture);
    Oi = 1;
    printf("type=%s\\n", kind);
}""",
    "msgrandom.sl": 'surface msgrandom() { Ci = color random(); Oi = 1; }',
    "msguniformrandom.sl": """surface msguniformrandom() {
    uniform color k = color(random(), random(), random());
    Ci = k;
    Oi = 1;
}""",
    "primvarvalue.sl": 'surface primvarvalue(varying float myval = 0) { Ci = myval; Oi = 1; }',
}


def scene(displays, world):
    return f"{displays}{OPTIONS}WorldBegin\n{world}\nWorldEnd\n"


def sphere_pixels():
    """Pixels whose every 4x4 sub-sample point lies well inside the sphere, with the mean
    normal over those points (camera space = world space moved along z)."""
    pixel = 2 * HALF / SIZE
    for py in range(SIZE):
        for px in range(SIZE):
            points = [(-HALF + (px + (i + 0.5) / 4) * pixel, HALF - (py + (j + 0.5) / 4) * pixel)
                      for i in range(4) for j in range(4)]
            if max(x * x + y * y for x, y in points) > (0.95 * RADIUS) ** 2:
                continue
            normals = [(x / RADIUS, y / RADIUS, -math.sqrt(1 - (x * x + y * y) / RADIUS ** 2))
                       for x, y in points]
            yield (px, py), [sum(n[c] for n in normals) / len(normals) for c in range(3)]


def check_messages_and_aovs(ws):
    ws.render(scene('Display "out.tif" "tiff" "rgba"\nDisplay "+kd.tif" "file" "kd"\n'
                    'Display "+tint.tif" "file" "tint"\nDisplay "+N.tif" "file" "N"\n',
                    'Displacement "msgdisp"\nSurface "msgsurf"\nAtmosphere "msgatmo"\n'
                    f'Sphere {RADIUS} -{RADIUS} {RADIUS} 360'))
    out, kd, tint, normal = read_images(*(ws.path(f) for f in
                                          ("out.tif", "kd.tif", "tint.tif", "N.tif")))
    expect(kd.channels == 1 and tint.channels == 3 and normal.channels == 3,
           f"AOV channels: kd {kd.channels}, tint {tint.channels}, N {normal.channels}")
    checked = 0
    for xy, want_n in sphere_pixels():
        got = out.pixels[xy]
        expect(all(abs(a - b) < 1e-5 for a, b in zip(got, (0.25, 1, 0.6, 1))),
               f"pixel {xy}: {got}, expected displacement's 0.25, 1 (found, and 0 for a "
               f"missing parameter), the surface's kd 0.6 through the atmosphere, alpha 1")
        expect(abs(kd.pixels[xy][0] - 0.6) < 1e-5, f"kd AOV at {xy}: {kd.pixels[xy]}")
        expect(all(abs(a - b) < 1e-5 for a, b in zip(tint.pixels[xy], (0.1, 0.2, 0.3))),
               f"tint AOV at {xy}: {tint.pixels[xy]}")
        # 0.02: the pixel means over jittered samples of a curved normal.
        expect(all(abs(a - b) < 0.02 for a, b in zip(normal.pixels[xy], want_n)),
               f"N AOV at {xy}: {normal.pixels[xy]}, analytic mean normal {want_n}")
        checked += 1
    expect(checked > 50, f"only {checked} pixels checked")
    expect(kd.pixels[(0, 0)][0] == 0, "the kd AOV is not 0 where nothing was hit")


def check_lightsource(ws):
    ws.render(scene('Display "light.tif" "tiff" "rgba"\n',
                    'LightSource "distantlight" 1 "intensity" 0.2\n'
                    'LightSource "pointlight" 2 "intensity" 0.3 "from" [0 0 -3]\n'
                    'LightSource "ambientlight" 3 "intensity" 5\n'
                    f'Surface "msglight"\nSphere {RADIUS} -{RADIUS} {RADIUS} 360'), name="light")
    (image,) = read_images(ws.path("light.tif"))
    for xy, _ in sphere_pixels():
        expect(abs(image.pixels[xy][0] - 0.5) < 1e-5,
               f"pixel {xy}: {image.pixels[xy][0]}, expected 0.2 + 0.3 from lightsource() "
               "(the ambient light is not in illuminance)")


def check_textureinfo(ws):
    subprocess.run(["oiiotool", "--pattern", "constant:color=0.5,0.5,0.5", "64x32", "3",
                    "-o", ws.path("info.tif")], check=True, capture_output=True)
    proc = ws.render(scene('Display "tex.tif" "tiff" "rgba"\n',
                           f'Surface "msgtexinfo"\nSphere {RADIUS} -{RADIUS} {RADIUS} 360'),
                     name="tex")
    # The type both printed and compared in the shader (a string written by a built-in's output
    # argument once compared equal at the first point of a batch only).
    types = set(line for line in proc.stdout.splitlines() if line.startswith("type="))
    expect(types == {"type=texture"}, f"textureinfo type: {types}, expected texture")
    (image,) = read_images(ws.path("tex.tif"))
    for xy, _ in sphere_pixels():
        expect(all(abs(a - b) < 1e-5 for a, b in zip(image.pixels[xy], (0.5, 0.25, 0.3))),
               f"pixel {xy}: {image.pixels[xy][:3]}, expected 64/128, 32/128, 3/10 + 0 (a "
               "missing file) + 0 (type == \"texture\")")


def render_threads_and_seed(ws, surface, name):
    """A square shaded by `surface` rendered with 1 thread, 2 threads, and 2 with --seed 7."""
    rib = scene("", f'Surface "{surface}"\nPolygon "P" [-3 -3 0  3 -3 0  3 3 0  -3 3 0]')
    ws.render(rib, name=name)
    outputs = []
    for args, out in ((["--threads", "1"], "t1"), (["--threads", "2"], "t2"),
                      (["--threads", "2", "--seed", "7"], "s7")):
        outputs.append(ws.path(f"{name}_{out}.tif"))
        ws.run(["render", ws.path(name + ".rib"), *args, "-o", outputs[-1]])
    # The pixels, not the bytes: the files carry the time they were written.
    return read_images(*outputs)


def check_random_is_deterministic(ws):
    t1, t2, s7 = render_threads_and_seed(ws, "msgrandom", "random")
    expect(t1.pixels == t2.pixels, "random(): --threads 1 and --threads 2 differ")
    changed = sum(1 for xy in t1.pixels if t1.pixels[xy] != s7.pixels[xy])
    expect(changed > 0.9 * len(t1.pixels), f"--seed 7 changed only {changed} pixels")
    # Each pixel averages 16 uniform numbers: mean 0.5, standard deviation 0.289/4.
    values = t1.channel(0)
    mean = sum(values) / len(values)
    expect(abs(mean - 0.5) < 0.03, f"mean of random() over the image: {mean}")
    expect(all(0 <= v < 1 for v in values), "random() outside [0, 1)")
    distinct = len(set(tuple(p[:3]) for p in t1.pixels.values()))
    expect(distinct > 0.9 * len(values), f"only {distinct} distinct pixels")


def check_uniform_random_is_deterministic(ws):
    """random() in a uniform colour draws one value per run of the shader from the run's own
    stream, seeded from its points: the image does not depend on the thread count."""
    u1, u2, u7 = render_threads_and_seed(ws, "msguniformrandom", "uniform")
    expect(u1.pixels == u2.pixels, "uniform random(): --threads 1 and --threads 2 differ")
    expect(u1.pixels != u7.pixels, "uniform random(): --seed 7 changed nothing")
    values = [v for p in u1.pixels.values() for v in p[:3]]
    expect(all(0 <= v < 1 for v in values), "uniform random() outside [0, 1)")


def check_primvars_reach_every_primitive(ws):
    """Two polygons, each in its own AttributeBegin under one Surface bound outside them, each
    with its own value of a user primitive variable: both values reach the shader (the second
    once shaded with the default)."""
    polygons = "".join(
        f'AttributeBegin\nPolygon "P" [{x0} -2 0  {x0 + 2} -2 0  {x0 + 2} 2 0  {x0} 2 0] '
        f'"myval" [{v} {v} {v} {v}]\nAttributeEnd\n' for x0, v in ((-2, 0.25), (0, 0.75)))
    ws.render(scene('Display "primvars.tif" "tiff" "rgba"\n',
                    'Declare "myval" "varying float"\nSurface "primvarvalue"\n' + polygons))
    (image,) = read_images(ws.path("primvars.tif"))
    for (px, py), got in image.pixels.items():
        if abs(px + 0.5 - SIZE / 2) < 1:
            continue  # the seam
        want = 0.25 if px < SIZE / 2 else 0.75
        expect(abs(got[0] - want) < 1e-5, f"pixel {(px, py)}: {got[0]}, expected {want}")


def check_too_large_an_image_is_an_error(ws):
    """A Format no machine can hold is refused at its line (exit 1), not aborted in the
    allocator (exit 134), and nothing is written."""
    proc = ws.render('Format 1000000 1000000 1\nDisplay "huge.tif" "file" "rgba"\n'
                     'WorldBegin\nSphere 1 -1 1 360\nWorldEnd\n', name="huge", expect_code=1)
    expect("huge.rib:1:1: error: Format 1000000 1000000: the image needs" in proc.stderr and
           "of this machine's memory" in proc.stderr, f"message: {proc.stderr}")
    expect(not os.path.exists(ws.path("huge.tif")), "an image was written")


CHECKS = [check_messages_and_aovs, check_lightsource, check_textureinfo,
          check_random_is_deterministic, check_uniform_random_is_deterministic,
          check_primvars_reach_every_primitive,
          check_too_large_an_image_is_an_error]


def main():
    return workspace_main(__doc__.split("\n\n")[0], CHECKS, "gonio_messages_", SHADERS)


if __name__ == "__main__":
    sys.exit(main())
