#!/usr/bin/env python3
"""Bad input gets a located error and the exit status the user guide promises, and leaves no
output file behind (issue 20's robustness list). One small input per item; each case names the
command, the files it is given, the exit status, a piece of the message, and the outputs that
must not exist afterwards.

    robustness_checks.py --gonio build/bin/gonio"""

import argparse
import gzip
import os
import shutil
import signal
import struct
import subprocess
import sys
import tempfile
import time

SPHERE = """Format 8 8 1
Display "{image}" "file" "rgba"
WorldBegin
Sphere 1 -1 1 360
WorldEnd
"""


IDENTITY = "[1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1]"


def blobby_scene(code, floats=IDENTITY):
    """A frame whose one primitive is a Blobby with the given code and float arrays."""
    return ('Format 8 8 1\nDisplay "a.tif" "file" "rgba"\nWorldBegin\n'
            f'Blobby 1 {code} {floats} [""]\nWorldEnd\n')


def scene(image, before=""):
    return before + SPHERE.format(image=image)


def make_texture(picture, texture="out.tx"):
    return f'MakeTexture "{picture}" "{texture}" "periodic" "clamp" "box" 1 1\n'


# A 1x1 RGB picture OpenImageIO reads (PFM: a text header, then little-endian floats).
PFM_PIXEL = b"PF\n1 1\n-1.0\n" + struct.pack("<3f", 0.25, 0.5, 0.75)


def two_frames():
    frame = "FrameBegin {n}\n" + SPHERE + "FrameEnd\n"
    return frame.format(n=1, image="frame1.tif") + frame.format(n=2, image="frame2.tif")


def gzip_cut(text, fraction):
    data = gzip.compress(text.encode(), mtime=0)
    return data[: int(len(data) * fraction)]


# A small valid .grd (made once by main: GRD_PATHS Lambert paths, every photon kept as a splat)
# and the same file with one field changed and its checksum made right again, so that only the
# range check can catch it.
GRD_PATHS = 2000
SMALL_GRD = {}
WEIGHTS = 84 + 32 * GRD_PATHS  # formats.md: the splat weights follow S 32-byte centres


def grd_checksum(data):
    """formats.md's checksum: a 64-bit FNV-style hash over 8-byte little-endian words."""
    mask, value = (1 << 64) - 1, 0xcbf29ce484222325
    for i in range(0, len(data), 8):
        word = int.from_bytes(data[i:i + 8].ljust(8, b"\0"), "little")
        value = ((value ^ word) * 0x100000001b3) & mask
        value ^= value >> 29
    return value


class ChangedGrd:
    """SMALL_GRD with the struct `layout` value at `offset` replaced."""

    def __init__(self, *changes):
        self.changes = changes  # (offset, layout, value), ...

    def content(self):
        data = bytearray(SMALL_GRD["bytes"])
        for offset, layout, value in self.changes:
            struct.pack_into("<" + layout, data, offset, value)
        struct.pack_into("<Q", data, len(data) - 16, grd_checksum(bytes(data[:-16])))
        return bytes(data)


def photon_map(line):
    return "2\n" + line + "\n0.5 0 0.5 1 0.159 0.5 0.5 0.5\n"


BRDF_SHADER = """surface b(string g = "") {
    normal Nf = faceforward(normalize(N), I);
    Ci = 0;
    illuminance(P, Nf, PI / 2)
        Ci += Cl * brdf(g, Nf, normalize(-I), normalize(L), normalize(dPdu));
    Oi = 1;
}
"""


def brdf_scene(grid):
    return scene("s.tif", "").replace(
        "WorldBegin\n", f'WorldBegin\nLightSource "distantlight" 1\nSurface "b" "string g" "{grid}"\n')


LONG_SUM_SHADER = "surface long() { Ci = " + " + ".join(["u"] * 20000) + "; }\n"
# f26 inlines f25 twice, ... : 2^26 copies of f0 once inlined.
DOUBLING_SHADER = "float f0(float x) { return x; }\n" + "".join(
    f"float f{i}(float x) {{ return f{i - 1}(x) + f{i - 1}(x); }}\n" for i in range(1, 27)
) + "surface doubling() { Ci = f26(u); }\n"
ENDLESS_SHADER = "surface endless(float k = 1) { float i = 0; while (k > 0) i += 1; Ci = i; }\n"
ENDLESS_SCENE = scene("s.tif", 'Option "limits" "float shadertimeout" [0.5]\n').replace(
    "WorldBegin\n", 'WorldBegin\nSurface "endless"\n')

# (name, arguments after gonio, files {name: text or bytes}, stdin file, exit status,
#  message piece, files that must not exist). Every file a case is given must be unchanged after.
CASES = [
    ("format_overflows_int", ["render", "--strict", "s.rib"],
     {"s.rib": scene("a.tif", "Format 2147483647 2147483647 1\n")}, None,
     1, "s.rib:1:1: error: Format 2147483647 2147483647: the resolution must be at most", ["a.tif"]),
    ("format_beyond_memory", ["render", "--strict", "s.rib"],
     {"s.rib": scene("a.tif", "Format 1000000 1000000 1\n").replace("Format 8 8 1\n", "")}, None,
     1, "s.rib:1:1: error: Format 1000000 1000000: the image needs", ["a.tif"]),
    ("pixel_samples_huge", ["render", "--strict", "s.rib"],
     {"s.rib": scene("a.tif", "PixelSamples 1e30 1e30\n")}, None,
     1, "s.rib:1:1: error: PixelSamples must be at most 1024", ["a.tif"]),
    ("filter_width_huge", ["render", "--strict", "s.rib"],
     {"s.rib": scene("a.tif", 'PixelFilter "gaussian" 1e9 1e9\n')}, None,
     1, "s.rib:1:1: error: PixelFilter widths must be at most 256", ["a.tif"]),
    # A gzip stream cut short: frame 2 must not vanish silently.
    ("gzip_cut_in_the_middle", ["render", "s.rib.gz"],
     {"s.rib.gz": gzip_cut(two_frames() * 4, 0.6)}, None,
     1, "error: cannot read the file: the compressed stream ends early", []),
    ("gzip_header_only", ["render", "s.rib.gz"],
     {"s.rib.gz": gzip_cut(scene("a.tif"), 1.0)[:10]}, None,
     1, "s.rib.gz:1:1: error: cannot read the file: the compressed stream ends early", ["a.tif"]),
    ("gzip_cut_on_stdin", ["render", "-"],
     {"s.rib.gz": gzip_cut(scene("a.tif"), 0.5)}, "s.rib.gz",
     1, "<stdin>:1:1: error: cannot read the file: the compressed stream ends early", ["a.tif"]),
    ("scene_without_world", ["render", "s.rib"],
     {"s.rib": "Format 8 8 1\n"}, None,
     1, "s.rib has no WorldBegin ... WorldEnd", []),
    ("empty_scene_on_stdin", ["render", "-"],
     {"empty.rib": ""}, "empty.rib",
     1, "the standard input has no WorldBegin ... WorldEnd", []),
    ("missing_scene", ["render", "nothere.rib"], {}, None,
     2, "cannot open scene file 'nothere.rib'", []),
    ("folder_as_shader", ["shader", "folder.sl"], {"folder.sl/": None}, None,
     1, "folder.sl: error: cannot read the shader file: not a regular file", []),
    ("shader_includes_dev_zero", ["shader", "z.sl"],
     {"z.sl": '#include "/dev/zero"\nsurface z() {}\n'}, None,
     1, "z.sl:1:1: error: cannot include '/dev/zero': not a regular file", []),
    ("synth_negative_paths", ["brdf", "synth", "lambert:0.5", "-n", "-5", "-o", "x.pm"], {}, None,
     2, "--paths: must be a positive whole number, got '-5'", ["x.pm"]),
    ("synth_zero_paths", ["brdf", "synth", "lambert:0.5", "-n", "0", "-o", "x.pm"], {}, None,
     2, "--paths: must be a positive whole number, got '0'", ["x.pm"]),
    # BRDFLight scene errors are scene errors (exit 1), not output ones (2).
    ("brdflight_negative_rays", ["render", "s.rib"],
     {"s.rib": 'Option "BRDFLight" "string texturename" "m.pm" "integer rays" -5\n'
               "WorldBegin\nPolygon \"P\" [0 0 0 1 0 0 1 1 0]\nWorldEnd\n"}, None,
     1, 's.rib:1:48: error: Option "BRDFLight" "rays": expected a positive number of photon paths, got -5\n', ["m.pm"]),
    ("brdflight_without_geometry", ["render", "s.rib"],
     {"s.rib": 'Option "BRDFLight" "string texturename" "m.pm" "integer rays" 100\n'
               "WorldBegin\nWorldEnd\n"}, None,
     1, "the scene has no geometry to trace photons through", ["m.pm"]),
    # The refusal comes before anything is read, so the input need not be a real map.
    ("opt_output_is_its_input", ["brdf", "opt", "4", "8", "17deg", "0", "a.pm", "./a.pm"],
     {"a.pm": "the photon map to keep\n"}, None,
     2, "the output ./a.pm is also an input (a.pm)", []),
    ("merge_output_is_an_input", ["brdf", "merge", "b.pm", "a.pm", "-o", "a.pm"],
     {"a.pm": "one map\n", "b.pm": "another\n"}, None,
     2, "the output a.pm is also an input (a.pm)", []),
    # Values a .grd's checksum cannot catch (formats.md: a range check per field).
    ("grd_nan_weight", ["brdf", "eval", "x.grd", "30", "0", "30", "180"],
     {"x.grd": ChangedGrd((WEIGHTS, "f", float("nan")))}, None,
     1, f"x.grd: the weight of splat 0 is nan; expected a finite number within ±1e30 (at byte "
        f"{WEIGHTS})", []),
    ("grd_huge_energy", ["brdf", "info", "x.grd"],
     {"x.grd": ChangedGrd((WEIGHTS + 4 * 3 * GRD_PATHS + 4 * 3 * 7, "f", 1e35))}, None,
     1, "x.grd: the energy of splat 7 is 1e+35; expected a finite number within ±1e30", []),
    ("grd_splat_not_a_direction", ["brdf", "info", "x.grd"],
     {"x.grd": ChangedGrd((84 + 3 * 32 + 16, "f", 2.0))}, None,
     1, "x.grd: splat 3's centre is not two unit vectors on the upper hemisphere with theta_in "
        "in [0, pi/2] (at byte 180)", []),
    ("grd_negative_energy_min", ["brdf", "info", "x.grd"],
     {"x.grd": ChangedGrd((44, "d", -1.0))}, None,
     1, "x.grd: energy_min -1 is not a finite number >= 0 (at byte 44)", []),
    ("grd_infinite_mass", ["brdf", "info", "x.grd"],
     {"x.grd": ChangedGrd((68, "d", float("inf")))}, None,
     1, "x.grd: the kernel mass inf is not a finite number > 0", []),
    # The largest rings x rects the format allows: rejected at once, not after a minute and a
    # half of building a grid of 2.5 million cells.
    ("grd_largest_rings_rects", ["brdf", "info", "x.grd"],
     {"x.grd": ChangedGrd((28, "I", 1000), (32, "I", 4000))}, None,
     1, "does not match rings and rects", []),
    ("pm_phi_huge", ["brdf", "info", "x.pm"],
     {"x.pm": photon_map("0.5 0 0.5 1e30 0.159 0.5 0.5 0.5")}, None,
     1, "x.pm:2: expected phi_in and phi_out within ±4π radians", []),
    ("pm_probability_tiny", ["brdf", "opt", "4", "8", "17deg", "0", "x.pm", "x.grd"],
     {"x.pm": photon_map("0.5 0 0.5 1 1e-38 0.5 0.5 0.5")}, None,
     1, "x.pm:2: expected a probability density in [1e-12, 1e12] per steradian", ["x.grd"]),
    ("pm_energy_huge", ["brdf", "info", "x.pm"],
     {"x.pm": photon_map("0.5 0 0.5 1 0.159 -1e30 0.5 0.5")}, None,
     1, "x.pm:2: expected energies within ±1e6", []),
    # A 20,000-term sum overflowed the type checker's stack (exit 139).
    ("shader_long_sum", ["shader", "long.sl"], {"long.sl": LONG_SUM_SHADER}, None,
     1, "error: expressions or statements nested more than 500 deep", []),
    # Functions that call the next one twice, 26 deep, inlined for ever.
    ("shader_inline_blowup", ["shader", "doubling.sl"], {"doubling.sl": DOUBLING_SHADER}, None,
     1, "error: the shader is larger than 262144 instructions once its functions are inlined",
     []),
    # An endless loop is stopped by the time budget (every later run at once), the frame fails.
    ("shader_endless_loop", ["render", "s.rib"],
     {"s.rib": ENDLESS_SCENE, "endless.sl": ENDLESS_SHADER}, None,
     1, "endless.sl:1: error: the shader ran longer than its time budget of 0.5 s", ["s.tif"]),
    # Blobby code arrays that would read past the float array, name no operation, or refer
    # forward (a cycle): a located error, and the strict frame is not written.
    ("blobby_float_index_beyond_the_floats", ["render", "--strict", "s.rib"],
     {"s.rib": blobby_scene("[1001 10]")}, None,
     1, "s.rib:4:1: error: Blobby: code[1]: the ellipsoid's 16 floats start at 10, but the "
     "float array has 16", ["a.tif"]),
    ("blobby_unknown_opcode", ["render", "--strict", "s.rib"],
     {"s.rib": blobby_scene("[1001 0 9 0]")}, None,
     1, "s.rib:4:1: error: Blobby: code[2]: unknown opcode 9", ["a.tif"]),
    ("blobby_forward_reference", ["render", "--strict", "s.rib"],
     {"s.rib": blobby_scene("[0 2 0 1 1001 0]")}, None,
     1, "s.rib:4:1: error: Blobby: code[2]: instruction 0 uses instruction 0, which is not an "
     "earlier one", ["a.tif"]),
    # Texture making: a picture that is missing or is no picture is an error at the request,
    # and no texture (nor temporary) is left; a RIB that only makes textures has done its work.
    ("make_texture_missing_picture", ["render", "s.rib"],
     {"s.rib": make_texture("missing.tif")}, None,
     1, 's.rib:1:1: error: MakeTexture: cannot find the picture "missing.tif"', ["out.tx"]),
    ("make_texture_not_a_picture", ["render", "s.rib"],
     {"s.rib": make_texture("bad.tif"), "bad.tif": "not a picture\n"}, None,
     1, 's.rib:1:1: error: MakeTexture "out.tx": cannot read the picture "./bad.tif"',
     ["out.tx"]),
    ("make_cube_face_missing_face", ["render", "s.rib"],
     {"s.rib": 'MakeCubeFaceEnvironment "p.pfm" "p.pfm" "p.pfm" "p.pfm" "p.pfm" "nz.pfm" '
               '"cube.env" 90 "box" 1 1\n', "p.pfm": PFM_PIXEL}, None,
     1, 's.rib:1:1: error: MakeCubeFaceEnvironment: cannot find the picture "nz.pfm"',
     ["cube.env"]),
    ("make_texture_huge_filter_width", ["render", "s.rib"],
     {"s.rib": 'MakeTexture "p.pfm" "out.tx" "periodic" "clamp" "gaussian" 1e9 2\n',
      "p.pfm": PFM_PIXEL}, None,
     1, "s.rib:1:1: error: MakeTexture: the filter widths must be in (0, 256] pixels, got 1e+09 2",
     ["out.tx"]),
    ("make_texture_only", ["render", "s.rib"],
     {"s.rib": make_texture("p.pfm"), "p.pfm": PFM_PIXEL}, None, 0, "", []),
    # brdf() with a file it cannot use fails the render; no picture shaded black is written.
    ("brdf_missing_grd", ["render", "s.rib"],
     {"s.rib": brdf_scene("missing.grd"), "b.sl": BRDF_SHADER}, None,
     1, 'brdf("missing.grd"): missing.grd: cannot open', ["s.tif"]),
    ("brdf_corrupt_grd", ["render", "s.rib"],
     {"s.rib": brdf_scene("x.grd"), "b.sl": BRDF_SHADER,
      "x.grd": ChangedGrd((WEIGHTS, "f", float("nan")))}, None,
     1, "frame 0 is not written: its shaders met the errors above", ["s.tif"]),
    # MakeShadow of what is not a depth map: a located error, no shadow map (issue 20).
    ("makeshadow_missing_input", ["render", "s.rib"],
     {"s.rib": 'MakeShadow "nothere.z" "out.sm"\n' + scene("a.tif")}, None,
     1, 's.rib:1:1: error: MakeShadow cannot make "out.sm": cannot open "nothere.z": No such file',
     ["out.sm"]),
    ("makeshadow_of_a_colour_image", ["render", "s.rib"],
     {"s.rib": "FrameBegin 1\n" + scene("rgb.tif") + 'FrameEnd\nMakeShadow "rgb.tif" "out.sm"\n'},
     None, 1, 's.rib:8:1: error: MakeShadow cannot make "out.sm": "rgb.tif" holds 4 channels of '
     "8-bit integers; a depth map is one channel of 32-bit floats", ["out.sm"]),
    ("makeshadow_of_text", ["render", "s.rib"],
     {"s.rib": 'MakeShadow "notes.txt" "out.sm"\n' + scene("a.tif"), "notes.txt": "not a map\n"},
     None, 1, 's.rib:1:1: error: MakeShadow cannot make "out.sm": "notes.txt" is neither a zfile '
     "nor a TIFF depth map", ["out.sm"]),
    ("makeshadow_of_a_truncated_zfile", ["render", "s.rib"],
     {"s.rib": 'MakeShadow "cut.z" "out.sm"\n' + scene("a.tif"),
      "cut.z": struct.pack("<ihh32f10f", 0x2f0867ab, 4, 4, *([0.0] * 42))},
     None, 1, '"cut.z" is truncated: fewer depths than its 4 x 4 pixels', ["out.sm"]),
]


def as_bytes(content):
    if isinstance(content, ChangedGrd):
        return content.content()
    return content if isinstance(content, bytes) else content.encode()


def read_file(path):
    with open(path, "rb") as f:
        return f.read()


def write_files(root, files):
    """Writes each file (name: text or bytes); a name ending in / is made as a folder."""
    for name, content in files.items():
        path = os.path.join(root, name)
        if name.endswith("/"):
            os.makedirs(path)
        else:
            with open(path, "wb") as f:
                f.write(as_bytes(content))


def run_case(gonio, root, case):
    """Returns the reason the case failed, or None."""
    name, arguments, files, stdin_name, status, message, absent = case
    work = os.path.join(root, name)
    os.makedirs(work)
    write_files(work, files)
    stdin = open(os.path.join(work, stdin_name), "rb") if stdin_name else subprocess.DEVNULL
    try:
        result = subprocess.run([gonio] + arguments, cwd=work, stdin=stdin, capture_output=True,
                                text=True, timeout=60)
    except subprocess.TimeoutExpired:
        return "did not finish within 60 s"
    finally:
        if stdin_name:
            stdin.close()
    output = result.stdout + result.stderr
    if result.returncode != status:
        return f"exit status {result.returncode}, expected {status}:\n{output}"
    if message not in output:
        return f"the output lacks {message!r}:\n{output}"
    changed = [f for f, content in files.items() if not f.endswith("/") and
               read_file(os.path.join(work, f)) != as_bytes(content)]
    if changed:
        return f"changed its input {', '.join(changed)}"
    left = [f for f in absent if os.path.exists(os.path.join(work, f))]
    if left:
        return f"left {', '.join(left)} behind"
    leftovers = [f for f in os.listdir(work) if ".tmp" in f]
    if leftovers:
        return f"left temporary files {', '.join(leftovers)}"
    return None


def expect_source_date_epoch_makes_files_byte_identical(gonio, root):
    """TIFF and OpenEXR carry the time of writing (as OpenImageIO writes them); with
    SOURCE_DATE_EPOCH two renders a second apart must give the same bytes. Returns the reason
    it failed, or None."""
    work = os.path.join(root, "source_date_epoch")
    os.makedirs(work)
    environment = dict(os.environ, SOURCE_DATE_EPOCH="1700000000")
    for image in ("d.tif", "d.exr"):
        write_files(work, {"s.rib": scene(image)})
        renders = []
        for attempt in range(2):
            if attempt:
                time.sleep(1.1)  # the stamp has whole seconds
            subprocess.run([gonio, "render", "s.rib"], cwd=work, env=environment, check=True,
                           capture_output=True, timeout=60)
            with open(os.path.join(work, image), "rb") as f:
                renders.append(f.read())
        if renders[0] != renders[1]:
            return f"two renders of {image} differ"
    return None


def expect_catrib_output_linear_in_nesting(gonio, root):
    """10,000 nested AttributeBegin blocks: catrib's output stays within 20 times the input
    (indenting every level printed 200 MB). Returns the reason it failed, or None."""
    depth = 10000
    text = ("WorldBegin\n" + "AttributeBegin\n" * depth + "Sphere 1 -1 1 360\n"
            + "AttributeEnd\n" * depth + "WorldEnd\n")
    work = os.path.join(root, "catrib_nesting")
    os.makedirs(work)
    write_files(work, {"s.rib": text})
    result = subprocess.run([gonio, "catrib", "s.rib"], cwd=work, capture_output=True, timeout=60)
    if result.returncode != 0:
        return f"exit status {result.returncode}: {result.stderr.decode()}"
    if len(result.stdout) > 20 * len(text):
        return f"{len(result.stdout)} bytes printed for a {len(text)}-byte scene"
    return None


def make_small_grd(gonio, root):
    work = os.path.join(root, "small_grd")
    os.makedirs(work)
    for command in (["brdf", "synth", "lambert:0.5", "-n", str(GRD_PATHS), "-o", "l.pm"],
                    ["brdf", "opt", "4", "8", "17deg", "0", "l.pm", "l.grd"]):
        subprocess.run([gonio] + command, cwd=work, check=True, capture_output=True, timeout=60)
    SMALL_GRD["bytes"] = read_file(os.path.join(work, "l.grd"))
    SMALL_GRD["path"] = os.path.join(work, "l.grd")
    SMALL_GRD["pm"] = os.path.join(work, "l.pm")


def expect_grd_reads_from_a_pipe(gonio, root):
    """A valid .grd on standard input evaluates as the file does. Returns the reason it failed,
    or None."""
    angles = ["30", "0", "30", "180"]
    from_file = subprocess.run([gonio, "brdf", "eval", SMALL_GRD["path"]] + angles,
                               capture_output=True, text=True, timeout=60)
    with open(SMALL_GRD["path"], "rb") as grid:
        from_pipe = subprocess.run([gonio, "brdf", "eval", "/dev/stdin"] + angles, stdin=grid,
                                   capture_output=True, text=True, timeout=60)
    if from_pipe.returncode != 0 or from_pipe.stdout != from_file.stdout:
        return f"exit status {from_pipe.returncode}: {from_pipe.stdout}{from_pipe.stderr}"
    return None


def expect_interrupt_removes_partial_files(gonio, root):
    """SIGINT and SIGTERM while a photon map is being written: the run ends by the signal, says
    it was interrupted, and leaves no *.tmp* file. Returns the reason it failed, or None."""
    for signal_number, word in ((signal.SIGINT, "interrupted"), (signal.SIGTERM, "terminated")):
        work = os.path.join(root, f"interrupt_{signal_number}")
        os.makedirs(work)
        run = subprocess.Popen([gonio, "brdf", "synth", "lambert:0.5", "-n", "1000000000", "-o",
                                "big.pm"], cwd=work, stderr=subprocess.PIPE, text=True)
        deadline = time.time() + 30
        while not any(".tmp" in f for f in os.listdir(work)) and time.time() < deadline:
            time.sleep(0.05)
        run.send_signal(signal_number)
        try:
            _, errors = run.communicate(timeout=30)
        except subprocess.TimeoutExpired:
            run.kill()
            return f"still running 30 s after signal {signal_number}"
        if run.returncode != -signal_number:
            return f"exit status {run.returncode} after signal {signal_number}: {errors}"
        if word not in errors:
            return f"no word of the signal ({word}) in: {errors}"
        left = os.listdir(work)
        if left:
            return f"left {', '.join(left)} after signal {signal_number}"
    return None


# Writers that must fail on a full disk, each with its output name. A good file of that name
# is there before, and must still be there, unchanged, afterwards.
FULL_DISK_WRITERS = [
    ("render_png", ["render", "{work}/s.rib", "-o", "out.png"]),
    ("render_tiff", ["render", "{work}/s.rib", "-o", "out.tif"]),
    ("render_exr", ["render", "{work}/s.rib", "-o", "out.exr"]),
    ("shade_png", ["shade", "{work}/c.sl", "--res", "64x64", "-o", "out.png"]),
    ("synth_pm", ["brdf", "synth", "lambert:0.5", "-n", "20000", "-o", "out.pm"]),
    ("opt_grd", ["brdf", "opt", "4", "8", "17deg", "0", "{grd_pm}", "out.grd"]),
    ("section_png", ["brdf", "section", "2000", "{grd}", "--theta-in", "30", "--phi-in", "0",
                     "--phi-out", "180", "--plot", "out.png"]),
    ("section_svg", ["brdf", "section", "2000", "{grd}", "--theta-in", "30", "--phi-in", "0",
                     "--phi-out", "180", "--plot", "out.svg"]),
    ("map_png", ["brdf", "map", "256", "1", "0.1", "30", "0", "{grd}", "out.png"]),
]
GOOD_FILE = b"a good file from an earlier run\n"


def fill_disk(folder, free):
    """Fills `folder`'s file system with a filler file, then frees `free` bytes of it."""
    block = b"\0" * 4096
    path = os.path.join(folder, "filler")
    with open(path, "wb", buffering=0) as filler:
        try:
            while True:
                filler.write(block)
        except OSError:
            pass
    os.truncate(path, max(0, os.path.getsize(path) - free))


def full_disk_case(gonio, work, disk, name, arguments):
    """Runs one writer into the filled tmpfs `disk`; returns the reason it failed, or None."""
    output = os.path.join(disk, arguments[-1])
    values = {"work": work, "grd": SMALL_GRD["path"], "grd_pm": SMALL_GRD["pm"]}
    command = [gonio] + [a.format(**values) for a in arguments]
    result = subprocess.run(command, cwd=disk, capture_output=True, text=True, timeout=60)
    output_text = result.stdout + result.stderr
    if result.returncode == 0:
        return f"{name}: exit status 0:\n{output_text}"
    if read_file(output) != GOOD_FILE:
        return f"{name}: the earlier {arguments[-1]} was replaced"
    left = [f for f in os.listdir(disk) if f not in ("filler", arguments[-1])]
    if left:
        return f"{name}: left {', '.join(left)} behind"
    return None


def full_disk_inside(gonio, root):
    """Inside a user and mount namespace (see expect_full_disk_fails_cleanly): mounts a tiny
    tmpfs, puts a good file under each writer's output name, fills the disk and runs the
    writer. Prints one line per writer; exits 1 when any failed, 77 when nothing could be
    mounted."""
    disk = os.path.join(root, "disk")
    os.makedirs(disk)
    if subprocess.run(["mount", "-t", "tmpfs", "-o", "size=256k", "tmpfs", disk]).returncode:
        return 77
    work = os.path.join(root, "full_disk")
    os.makedirs(work)
    # Outputs of 13-45 KB (noise does not compress), larger than what is left free.
    noisy = "surface c() { Ci = noise(P * 40); }\n"
    write_files(work, {"c.sl": noisy, "s.rib": f'Option "searchpath" "shader" "{work}:&"\n'
                       'Format 64 64 1\nQuantize "rgba" 0 0 0 0\n'
                       'WorldBegin\nSurface "c"\nSphere 1 -1 1 360\nWorldEnd\n'})
    failures = 0
    for free in (0, 8192):
        for name, arguments in FULL_DISK_WRITERS:
            for f in os.listdir(disk):
                os.remove(os.path.join(disk, f))
            with open(os.path.join(disk, arguments[-1]), "wb") as good:
                good.write(GOOD_FILE)
            fill_disk(disk, free)
            reason = full_disk_case(gonio, work, disk, name, arguments)
            what = f"{free} bytes free: {name}"
            print(f"ok   {what}" if reason is None else f"FAIL {what}: {reason}")
            failures += reason is not None
    subprocess.run(["umount", disk])
    return 1 if failures else 0


def expect_full_disk_fails_cleanly(gonio, root):
    """Every writer (render PNG/TIFF/EXR, shade, .pm, .grd, plots) on a full disk, and on one with
    8 KiB free (the write fails part way), exits non-zero, leaves the earlier file of its name
    unchanged and no temporary behind. The disk is a 256 KiB
    tmpfs mounted in a user namespace (`unshare -rm`), so no privilege is needed where user
    namespaces are allowed; elsewhere the check is skipped. Returns (reason or None, skipped)."""
    if not shutil.which("unshare"):
        return None, True
    inside = subprocess.run(["unshare", "-rm", sys.executable, os.path.abspath(__file__),
                             "--gonio", gonio, "--full-disk-inside", root, "--grd",
                             SMALL_GRD["path"], "--grd-pm", SMALL_GRD["pm"]],
                            capture_output=True, text=True, timeout=600)
    if inside.returncode == 77 or "unshare failed" in inside.stderr:
        return None, True
    if inside.returncode != 0:
        return f"\n{inside.stdout}{inside.stderr}", False
    return None, False


def report(name, reason):
    """Prints the outcome of one case; returns 1 when it failed."""
    print(f"ok   {name}" if reason is None else f"FAIL {name}: {reason}")
    return reason is not None


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--gonio", required=True)
    parser.add_argument("--full-disk-inside", help=argparse.SUPPRESS)
    parser.add_argument("--grd", help=argparse.SUPPRESS)
    parser.add_argument("--grd-pm", help=argparse.SUPPRESS)
    args = parser.parse_args()
    gonio = os.path.abspath(args.gonio)
    if args.full_disk_inside:
        SMALL_GRD.update(path=args.grd, pm=args.grd_pm)
        return full_disk_inside(gonio, args.full_disk_inside)
    with tempfile.TemporaryDirectory(prefix="gonio-robustness-") as root:
        make_small_grd(gonio, root)
        failures = sum(report(case[0], run_case(gonio, root, case)) for case in CASES)
        failures += report("grd_from_a_pipe", expect_grd_reads_from_a_pipe(gonio, root))
        failures += report("interrupt", expect_interrupt_removes_partial_files(gonio, root))
        failures += report("source_date_epoch",
                           expect_source_date_epoch_makes_files_byte_identical(gonio, root))
        failures += report("catrib_nesting", expect_catrib_output_linear_in_nesting(gonio, root))
        reason, skipped = expect_full_disk_fails_cleanly(gonio, root)
        if skipped:
            print("skip full_disk: no tmpfs can be mounted here (unshare -rm is not allowed)")
        else:
            failures += report("full_disk", reason)
    checks = len(CASES) + 4 + (not skipped)
    print(f"{checks - failures} of {checks} cases as promised")
    return 1 if failures else 0

if __name__ == "__main__":
    sys.exit(main())
