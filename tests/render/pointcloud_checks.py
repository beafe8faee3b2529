#!/usr/bin/env python3
"""End-to-end checks, through `gonio render`, of the point-cloud built-ins (issue 20):

* bake3d() in frame 1 writes cloud.ptc when the frame ends: one point per shaded point (every
  camera sample shaded: 8 x 8 pixels x 2 x 2 samples), in the documented format
  (docs/file-formats.md, "Point clouds");
* texture3d() in frame 2 reads it: at the same shading points (same camera) it returns exactly
  the baked values, so frame 2's image equals frame 1's;
* through another camera (frame 3 turned by 90 degrees about the view axis) the lookup is still
  in world space: each pixel shows the baked colour of the world point it sees (within the
  jitter of the samples);
* the file is the same byte for byte with 1 and 2 threads (points sorted before writing).

    pointcloud_checks.py --gonio build/bin/gonio"""

import struct
import sys

from analytic_checks import EVERY_SAMPLE_SHADED, expect, float_tiff, read_images, \
    workspace_main

SHADERS = {
    "bakeit.sl": """
surface bakeit() {
    color c = color(s, t, 0.25);
    bake3d("cloud.ptc", "", P, N, "_c", c, "_s", s);
    Ci = c;
    Oi = 1;
}
""",
    "lookup.sl": """
surface lookup() {
    color c = 1;
    float ss = -1;
    float found = texture3d("cloud.ptc", P, N, "_c", c, "_s", ss);
    Ci = found == 1 && abs(ss - comp(c, 0)) < 1e-6 ? c : color(1, 0, 1);
    Oi = 1;
}
""",
}

SIZE = 8


def camera(roll=0):
    return (f"Format {SIZE} {SIZE} 1\nPixelSamples 2 2\nPixelFilter \"box\" 1 1\n"
            f"{EVERY_SAMPLE_SHADED}Projection \"orthographic\"\nScreenWindow -1 1 -1 1\n"
            f"Rotate {roll} 0 0 1\nTranslate 0 0 5\n")


# A unit square facing the camera: s runs along world x, t along world -y (a bilinear patch's
# parameters, Patch "bilinear" corners in u, v order).
PLANE = 'Patch "bilinear" "P" [-1 1 0  1 1 0  -1 -1 0  1 -1 0]'


def frame(number, name, roll, surface):
    return (f"FrameBegin {number}\n{float_tiff(name)}{camera(roll)}WorldBegin\n"
            f'Surface "{surface}"\n{PLANE}\nWorldEnd\nFrameEnd\n')


SCENE = frame(1, "baked.tif", 0, "bakeit") + frame(2, "same.tif", 0, "lookup") + \
    frame(3, "rolled.tif", 90, "lookup")


def read_cloud(path):
    with open(path, "rb") as f:
        data = f.read()
    expect(data[:8] == b"GONIOPTC", "cloud.ptc does not start with GONIOPTC")
    version, channels = struct.unpack_from("<II", data, 8)
    pos, names = 16, []
    for _ in range(channels):
        (length,) = struct.unpack_from("<I", data, pos)
        name = data[pos + 4:pos + 4 + length].decode()
        (width,) = struct.unpack_from("<I", data, pos + 4 + length)
        names.append((name, width))
        pos += 8 + length
    (count,) = struct.unpack_from("<Q", data, pos)
    return version, names, count, len(data) - pos - 8


def baked_file_and_lookups(ws):
    ws.render(SCENE)
    version, names, count, rest = read_cloud(ws.path("cloud.ptc"))
    expect(version == 1 and names == [("_c", 3), ("_s", 1)],
           f"cloud.ptc: version {version}, channels {names}")
    want = SIZE * SIZE * 4
    expect(count == want, f"cloud.ptc holds {count} points, not one per shaded sample ({want})")
    expect(rest == count * (6 + 4) * 4, f"cloud.ptc has {rest} bytes of points")
    baked, same, rolled = read_images(ws.path("baked.tif"), ws.path("same.tif"),
                                      ws.path("rolled.tif"))
    for xy, value in baked.pixels.items():
        expect(same.pixels[xy][:3] == value[:3],
               f"frame 2 pixel {xy} is {same.pixels[xy][:3]}, frame 1 baked {value[:3]}")
    # Rolled by 90 degrees, pixel (x, y) sees what pixel (y, SIZE - 1 - x) saw unrolled (or the
    # other way round, with the roll's sign). The samples are jittered, so its samples find the
    # nearest baked ones, up to half a sample apart: within 0.07 in s and t, while the next
    # pixel differs by 0.125 (s and t run from 0 to 1 over 8 pixels).
    for orientation in ((lambda x, y: (y, SIZE - 1 - x)), (lambda x, y: (SIZE - 1 - y, x))):
        worst = max(max(abs(a - b) for a, b in zip(value[:3], baked.pixels[orientation(*xy)][:3]))
                    for xy, value in rolled.pixels.items())
        if worst < 0.07:
            break
    expect(worst < 0.07, f"rolled frame: a pixel differs by {worst:.3f} from the baked colour "
           "of the world point it sees")


def same_file_with_one_and_two_threads(ws):
    ws.render(SCENE, "one", ["--threads", "1"])
    with open(ws.path("cloud.ptc"), "rb") as f:
        one = f.read()
    ws.render(SCENE, "two", ["--threads", "2"])
    with open(ws.path("cloud.ptc"), "rb") as f:
        two = f.read()
    expect(one == two, "cloud.ptc differs between --threads 1 and --threads 2")


if __name__ == "__main__":
    sys.exit(workspace_main(__doc__, [baked_file_and_lookups, same_file_with_one_and_two_threads],
                            "gonio_pointcloud_", SHADERS))
