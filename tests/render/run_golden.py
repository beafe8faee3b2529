#!/usr/bin/env python3
"""Golden-image tests in the style of OSL's testsuite: render every scene of scenes/ with
`gonio render` and compare each image it writes with the reference of the same name in
tests/golden/ using `idiff` under explicit thresholds.

    run_golden.py --gonio build/bin/gonio [--update] [--jobs 2] [SCENE ...]

Each scene renders in its own folder under --out, so the Display names in the scene are the
file names of its images. With --update the rendered images replace the references (look at
every one before committing it: see README.md)."""

import argparse
import concurrent.futures
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
IMAGE_EXTENSIONS = (".tif", ".tiff", ".exr", ".png")

# An 8-bit step is 1/255 = 0.0039: a reference and a render may differ by one step in at most
# half a percent of the pixels (floating-point differences between machines flip a few edge
# samples), and no pixel may differ by more than 0.1. Renders are deterministic, so on one
# machine the images are identical.
IDIFF_THRESHOLDS = ["-fail", "0.004", "-failpercent", "0.5", "-hardfail", "0.1",
                    "-warn", "0.002", "-warnpercent", "0.1"]


def render_scene(gonio, scene, outdir):
    """Renders `scene` with the working folder `outdir`. Returns (ok, message, images)."""
    shutil.rmtree(outdir, ignore_errors=True)
    os.makedirs(outdir)
    proc = subprocess.run([gonio, "render", scene], cwd=outdir, capture_output=True, text=True)
    images = sorted(f for f in os.listdir(outdir) if f.endswith(IMAGE_EXTENSIONS))
    if proc.returncode != 0:
        return False, f"gonio render exited with {proc.returncode}:\n{proc.stderr}", images
    if not images:
        return False, "gonio render wrote no image", images
    return True, "", images


def compare(rendered, golden, diff_image):
    """Runs idiff; returns (ok, idiff's report). idiff exits 0 (pass) or 1 (warning) to pass."""
    proc = subprocess.run(["idiff", *IDIFF_THRESHOLDS, "-o", diff_image, "-abs", "-scale", "20",
                           rendered, golden], capture_output=True, text=True)
    return proc.returncode in (0, 1), proc.stdout + proc.stderr


def run_one(args, scene_file):
    stem = os.path.splitext(os.path.basename(scene_file))[0]
    outdir = os.path.join(args.out, stem)
    ok, message, images = render_scene(args.gonio, scene_file, outdir)
    lines, produced = [], list(images)
    if not ok:
        return stem, False, [message], produced
    for image in images:
        rendered = os.path.join(outdir, image)
        golden = os.path.join(args.golden, image)
        if args.update:
            shutil.copyfile(rendered, golden)
            lines.append(f"updated {golden}")
            continue
        if not os.path.exists(golden):
            ok = False
            lines.append(f"{image}: no reference {golden} (run tests/render/update_goldens)")
            continue
        same, report = compare(rendered, golden, os.path.join(outdir, "diff_" + image))
        if not same:
            ok = False
            lines.append(f"{image}: differs from {golden}\n{report}")
    return stem, ok, lines, produced


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--gonio", required=True)
    parser.add_argument("--scenes", default=os.path.join(HERE, "scenes"))
    parser.add_argument("--golden", default=os.path.join(HERE, "..", "golden"))
    parser.add_argument("--out", default="golden_out")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--update", action="store_true", help="replace the references")
    parser.add_argument("names", nargs="*", help="scene names (default: all)")
    args = parser.parse_args()
    args.gonio = os.path.abspath(args.gonio)
    args.out = os.path.abspath(args.out)
    args.golden = os.path.abspath(args.golden)

    scenes = sorted(os.path.join(args.scenes, f) for f in os.listdir(args.scenes)
                    if f.endswith(".rib"))
    if args.names:
        scenes = [s for s in scenes if os.path.splitext(os.path.basename(s))[0] in args.names]
        if len(scenes) != len(args.names):
            sys.exit(f"run_golden: unknown scene among {args.names}")

    scene_failures, all_images = 0, set()
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        for stem, ok, lines, produced in pool.map(lambda s: run_one(args, s), scenes):
            all_images.update(produced)
            print(f"{'ok  ' if ok else 'FAIL'} {stem} ({', '.join(produced) or 'no image'})")
            for line in lines:
                print("     " + line.replace("\n", "\n     "))
            scene_failures += not ok
    stale = []
    if not args.names and not args.update:
        # A reference that no scene writes any more would silently stop being tested.
        stale = sorted(f for f in os.listdir(args.golden)
                       if f.endswith(IMAGE_EXTENSIONS) and f not in all_images)
        for f in stale:
            print(f"FAIL stale reference {f}: no scene writes it")
    print(f"{len(scenes) - scene_failures} of {len(scenes)} scenes passed")
    return 1 if scene_failures or stale else 0

if __name__ == "__main__":
    sys.exit(main())
