#!/usr/bin/env python3
"""Checks of Imager shaders through `gonio render` (issue 3): the standard imager `background`
composites a colour under the filtered pixels exactly, c + (1 - a)·background with alpha 1,
before Exposure; an Imager that names a missing shader or a surface shader is reported at its
RIB line and the frame is still written, without an imager; an imager's texture() reads the
map at raster coordinates, and its option() the frame's options.

    imager_checks.py --gonio build/bin/gonio"""

import subprocess
import sys

from analytic_checks import workspace_main, expect, read_images

SIZE, HALF = 32, 2.0  # an orthographic frame of SIZE² pixels over [-HALF, HALF]²
PIXEL = 2 * HALF / SIZE
BACKGROUND = (0.2, 0.4, 0.6)
COLOUR = (0.9, 0.5, 0.1)  # the sphere's, through the constant surface: Ci = Os·Cs

OPTIONS = f"""Format {SIZE} {SIZE} 1
PixelSamples 4 4
PixelFilter "box" 1 1
Quantize "rgba" 0 0 0 0
Projection "orthographic"
ScreenWindow -{HALF} {HALF} -{HALF} {HALF}
"""
WORLD = 'Translate 0 0 5\nWorldBegin\nSurface "constant"\nColor [0.9 0.5 0.1]\n' \
        'Sphere 1 -1 1 360\nWorldEnd\n'


def frame(number, display, options=""):
    return f'FrameBegin {number}\nDisplay "{display}" "tiff" "rgba"\n{OPTIONS}{options}' \
           f'{WORLD}FrameEnd\n'


def pixel_distances(px, py):
    """The nearest and farthest distance of pixel (px, py)'s square from the frame's centre."""
    x0, x1 = -HALF + px * PIXEL, -HALF + (px + 1) * PIXEL
    y0, y1 = HALF - (py + 1) * PIXEL, HALF - py * PIXEL
    nx, ny = min(max(0, x0), x1), min(max(0, y0), y1)
    far = max((x * x + y * y) ** 0.5 for x in (x0, x1) for y in (y0, y1))
    return (nx * nx + ny * ny) ** 0.5, far


def close(a, b, tolerance=1e-5):
    return all(abs(x - y) <= tolerance for x, y in zip(a, b))


def check_background_is_exact(ws):
    background = " ".join(str(c) for c in BACKGROUND)
    imager = f'Imager "background" "background" [{background}]\n'
    aqsis = f'Imager "background" "color bgcolor" [{background}]\n'  # Aqsis's spelling
    ws.render(frame(1, "plain.tif") + frame(2, "imager.tif", imager) +
              frame(3, "exposed.tif", imager + "Exposure 2 1\n") + frame(4, "bgcolor.tif", aqsis))
    plain, imaged, exposed, bgcolor = read_images(
        *(ws.path(f) for f in ("plain.tif", "imager.tif", "exposed.tif", "bgcolor.tif")))
    expect(bgcolor.pixels == imaged.pixels, "\"bgcolor\" should fill as \"background\" does")
    outside = inside = edge = 0
    for (px, py), was in plain.pixels.items():
        got, doubled = imaged.pixels[(px, py)], exposed.pixels[(px, py)]
        near, far = pixel_distances(px, py)
        where = f"pixel {(px, py)}: {got} (without the imager {was})"
        if near > 1.001:
            outside += 1
            expect(close(was, (0, 0, 0, 0)), f"{where}: the plain render is not empty here")
            expect(close(got, (*BACKGROUND, 1)), f"{where}, expected the background, alpha 1")
            # Exposure comes after the imager (RISpec §4.1.2): gain 2 doubles the background.
            expect(close(doubled, (*(2 * c for c in BACKGROUND), 1)),
                   f"pixel {(px, py)} with Exposure 2 1: {doubled}, expected twice the "
                   "background: the imager runs before exposure")
        elif far < 0.999:
            inside += 1
            expect(close(was, (*COLOUR, 1)), f"{where}: the plain sphere is not its colour")
            expect(close(got, was), f"{where}, expected the sphere unchanged")
        elif 0.05 < was[3] < 0.95:
            edge += 1
            want = [c + (1 - was[3]) * b for c, b in zip(was[:3], BACKGROUND)] + [1]
            expect(close(got, want), f"{where}, expected c + (1 - a)·background = {want}")
    expect(outside > 400 and inside > 100 and edge > 20,
           f"too few pixels checked: {outside} outside, {inside} inside, {edge} on the edge")


def check_unusable_imagers_are_reported(ws):
    with open(ws.path("flat.sl"), "w") as f:
        f.write("surface flat() { Ci = 1; Oi = 1; }\n")
    rib = frame(1, "missing.tif", 'Imager "nosuch"\n') + frame(2, "surface.tif", 'Imager "flat"\n')
    proc = ws.render(rib, name="bad", expect_code=1)
    lines = rib.splitlines()
    missing_line = lines.index('Imager "nosuch"') + 1
    surface_line = lines.index('Imager "flat"') + 1
    for message in (f"bad.rib:{missing_line}:1: error: cannot find shader 'nosuch'",
                    f"bad.rib:{surface_line}:1: error: \"flat\" is a surface shader, not an "
                    "imager shader"):
        expect(message in proc.stderr, f"expected '{message}' in:\n{proc.stderr}")
    images = read_images(ws.path("missing.tif"), ws.path("surface.tif"))
    for image in images:
        expect(close(image.pixels[(0, 0)], (0, 0, 0, 0)),
               f"corner pixel {image.pixels[(0, 0)]}: the frame was not written without imager")


BACKDROP = """imager backdrop(string map = "") {
    color c = texture(map, xcomp(P) / 32, ycomp(P) / 32);
    Ci += (1 - alpha) * c;
    alpha = 1;
}
"""
LEFT, RIGHT = (0.25, 0.5, 0.75), (1.0, 0.5, 0.0)


def check_imagers_read_textures(ws):
    """An imager looks textures up on the texture search path, at raster coordinates: the left
    half of the map shows left of the sphere, the right half right of it."""
    with open(ws.path("backdrop.sl"), "w") as f:
        f.write(BACKDROP)
    colours = ",".join(str(c) for c in LEFT), ",".join(str(c) for c in RIGHT)
    subprocess.run(["oiiotool", "--pattern", f"checker:width=16:height=64:color1={colours[0]}:"
                    f"color2={colours[1]}", "32x32", "3", "-d", "float", "-o", "halves.tif"],
                   cwd=ws.dir, check=True)
    proc = ws.render(frame(1, "backdrop.tif", 'Imager "backdrop" "string map" "halves.tif"\n') +
                     frame(2, "nomap.tif", 'Imager "backdrop" "string map" "nosuch.tif"\n'),
                     expect_code=0)
    backdrop, = read_images(ws.path("backdrop.tif"))
    checked = 0
    for (px, py), got in backdrop.pixels.items():
        near, _ = pixel_distances(px, py)
        seam = abs(px + 0.5 - SIZE / 2) < 3
        border = min(px, py, SIZE - 1 - px, SIZE - 1 - py) < 2
        if near <= 1.001 or seam or border:
            continue  # the sphere, or where the texture filter blurs a seam or the black beyond
        want = (*(LEFT if px < SIZE / 2 else RIGHT), 1)
        expect(close(got, want, 1e-3), f"pixel {(px, py)}: {got}, expected {want}")
        checked += 1
    expect(checked > 250, f"only {checked} pixels checked")
    warnings = [line for line in proc.stderr.splitlines() if "nosuch.tif" in line]
    expect(len(warnings) == 1 and "backdrop.sl:2" in warnings[0],
           f"a missing map should warn once, at the imager's texture() line:\n{proc.stderr}")


RESOLUTION = """imager resolution() {
    uniform float format[3] = {0, 0, 0};
    float found = option("Format", format);
    Ci = color(format[0] / 100, format[1] / 100, found);
    Oi = 1;
}
"""


def check_imagers_read_options(ws):
    """option("Format", f) in an imager gives the resolution (an imager that divides by it
    must see it), everywhere in the frame."""
    with open(ws.path("resolution.sl"), "w") as f:
        f.write(RESOLUTION)
    ws.render(frame(1, "resolution.tif", 'Imager "resolution"\n'))
    image, = read_images(ws.path("resolution.tif"))
    want = (SIZE / 100, SIZE / 100, 1)
    wrong = [(p, v) for p, v in image.pixels.items() if not close(v[:3], want)]
    expect(not wrong, f"{len(wrong)} pixels are not {want}, e.g. {wrong[:1]}")


CHECKS = [check_background_is_exact, check_unusable_imagers_are_reported,
          check_imagers_read_textures, check_imagers_read_options]


def main():
    return workspace_main(__doc__.split("\n\n")[0], CHECKS, "gonio_imager_")


if __name__ == "__main__":
    sys.exit(main())
