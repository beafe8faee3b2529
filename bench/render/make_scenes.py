#!/usr/bin/env python3
"""Writes issue 21's benchmark scenes into a folder: the renders gonio is timed on against Pixie.

    bench/render/make_scenes.py OUTDIR [--renderer gonio|pixie]

* spheres10k.rib, spheres10k_8x8.rib: 10,000 plastic spheres (100 x 100, radius 0.3 on a 0.6
  grid), 1280x720, PixelSamples 4 4 (and 8 8), gaussian 2 2, ambient + distant + point light.
* mirror.rib: the 400 spheres of spheres400.rib over a mirror floor whose shader (mirror.sl,
  written beside) calls trace() once per shaded point, 1280x720, 4 4.
* shadows.rib: the 400 spheres over a matte floor, lit by a point light and a distant light
  that cast ray-traced shadows, 1280x720, 4 4.

The scenes are generated rather than committed because the 10k-sphere files are 600 KB each.
Pixie asks for ray-traced shadows differently (shadowdistant takes "shadowname" "raytrace",
shadowpoint traces without one, and objects need Attribute "visibility" "integer
transmission" [1]: Pixie's transmission is a number, and it drops the word "opaque", so nothing
cast shadows in its render), hence --renderer.
"""

import argparse
import os

LIGHTS = """  LightSource "ambientlight" 1 "intensity" 0.1
  LightSource "distantlight" 2 "from" [-1 1 -1] "to" [0 0 0] "intensity" 0.8
  LightSource "pointlight" 3 "from" [4 4 -6] "intensity" 60
"""

PLASTIC = """  Surface "plastic" "Ka" 1 "Kd" 0.5 "Ks" 0.5 "roughness" 0.1
  Color [0.8 0.3 0.2]
"""

MIRROR_SHADER = """/* mirror: a perfect mirror with a little diffuse, one trace() per shaded point. */
surface mirror(float Kd = 0.2, Kr = 0.8)
{
    normal Nf = faceforward(normalize(N), I);
    Oi = Os;
    Ci = Os * (Kd * Cs * diffuse(Nf) + Kr * trace(P, reflect(normalize(I), Nf)));
}
"""


def header(name, width, height, samples, camera_z, fov):
    return f"""##RenderMan RIB
version 3.04
Display "{name}.tif" "tiff" "rgba"
Format {width} {height} 1
PixelSamples {samples} {samples}
PixelFilter "gaussian" 2 2
Projection "perspective" "fov" [{fov}]
Translate 0 0 {camera_z}
"""


def sphere_grid(count, spacing=0.6, radius=0.3):
    half = (count - 1) * spacing / 2
    lines = []
    for j in range(count):
        for i in range(count):
            x, y = i * spacing - half, j * spacing - half
            lines.append(f"  TransformBegin Translate {x:.4g} {y:.4g} 0 "
                         f"Sphere {radius} -{radius} {radius} 360 TransformEnd\n")
    return "".join(lines)


def spheres10k(samples):
    name = "spheres10k" if samples == 4 else f"spheres10k_{samples}x{samples}"
    return name, (header(name, 1280, 720, samples, 70, 45) + "WorldBegin\n" + LIGHTS + PLASTIC +
                  sphere_grid(100) + "WorldEnd\n")


def floor(z_offset=0.31):
    # A square floor just behind the spheres (the camera looks along +z).
    return (f"  AttributeBegin\n    Translate 0 0 {z_offset}\n"
            "    Polygon \"P\" [-12 -12 0  12 -12 0  12 12 0  -12 12 0]\n  AttributeEnd\n")


def mirror():
    body = (LIGHTS + "  AttributeBegin\n    Surface \"mirror\"\n    Color [0.9 0.9 0.9]\n" +
            floor() + "  AttributeEnd\n" + PLASTIC + sphere_grid(20))
    return "mirror", header("mirror", 1280, 720, 4, 16, 45) + "WorldBegin\n" + body + "WorldEnd\n"


def shadows(renderer):
    if renderer == "pixie":
        lights = """  LightSource "ambientlight" 1 "intensity" 0.1
  LightSource "shadowdistant" 2 "from" [-1 1 -1] "to" [0 0 0] "intensity" 0.8 "shadowname" "raytrace"
  LightSource "shadowpoint" 3 "from" [4 4 -6] "intensity" 60
  Attribute "visibility" "integer transmission" [1]
"""
    else:
        lights = ("  Attribute \"light\" \"shadows\" \"on\"\n" + LIGHTS)
    body = (lights + "  AttributeBegin\n    Surface \"matte\"\n    Color [0.8 0.8 0.8]\n" +
            floor() + "  AttributeEnd\n" + PLASTIC + sphere_grid(20))
    return "shadows", header("shadows", 1280, 720, 4, 16, 45) + "WorldBegin\n" + body + "WorldEnd\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("outdir")
    parser.add_argument("--renderer", choices=["gonio", "pixie"], default="gonio")
    args = parser.parse_args()
    os.makedirs(args.outdir, exist_ok=True)
    scenes = [spheres10k(4), spheres10k(8), mirror(), shadows(args.renderer)]
    for name, text in scenes:
        with open(os.path.join(args.outdir, name + ".rib"), "w") as f:
            f.write(text)
    with open(os.path.join(args.outdir, "mirror.sl"), "w") as f:
        f.write(MIRROR_SHADER)


if __name__ == "__main__":
    main()
