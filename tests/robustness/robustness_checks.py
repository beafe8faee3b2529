#!/usr/bin/env python3
"""Bad input gets a located error and the exit status the user guide promises, and leaves no
output file behind (issue 20's robustness list). One small input per item; each case names the
command, the files it is given, the exit status, a piece of the message, and the outputs that
must not exist afterwards.

    robustness_checks.py --gonio build/bin/gonio"""

import argparse
import gzip
import os
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


def scene(image, before=""):
    return before + SPHERE.format(image=image)


def two_frames():
    frame = "FrameBegin {n}\n" + SPHERE + "FrameEnd\n"
    return frame.format(n=1, image="frame1.tif") + frame.format(n=2, image="frame2.tif")


def gzip_cut(text, fraction):
    data = gzip.compress(text.encode(), mtime=0)
    return data[: int(len(data) * fraction)]


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
]


def as_bytes(content):
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


def report(name, reason):
    """Prints the outcome of one case; returns 1 when it failed."""
    print(f"ok   {name}" if reason is None else f"FAIL {name}: {reason}")
    return reason is not None


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--gonio", required=True)
    args = parser.parse_args()
    gonio = os.path.abspath(args.gonio)
    with tempfile.TemporaryDirectory(prefix="gonio-robustness-") as root:
        failures = sum(report(case[0], run_case(gonio, root, case)) for case in CASES)
        failures += report("source_date_epoch",
                           expect_source_date_epoch_makes_files_byte_identical(gonio, root))
        failures += report("catrib_nesting", expect_catrib_output_linear_in_nesting(gonio, root))
    print(f"{len(CASES) + 2 - failures} of {len(CASES) + 2} cases as promised")
    return 1 if failures else 0

if __name__ == "__main__":
    sys.exit(main())
