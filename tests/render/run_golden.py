#!/usr/bin/env python3
"""Golden-image tests in the style of OSL's testsuite: render every scene of scenes/ with
`gonio render` and compare each image it writes with the reference of the same name in
tests/golden/ under explicit idiff thresholds (with `oiiotool --diff`, idiff's comparison, so
that one process compares every pair).

    run_golden.py --gonio build/bin/gonio [--update] [--jobs 2] [SCENE ...]

Each scene renders in its own folder under --out, so the Display names in the scene are the
file names of its images. With --update the rendered images replace the references (look at
every one before committing it: see README.md)."""

import argparse
import concurrent.futures
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
IMAGE_EXTENSIONS = (".tif", ".tiff", ".exr", ".png")

# An 8-bit step is 1/255 = 0.0039: a reference and a render may differ by one step in at most
# half a percent of the pixels (floating-point differences between machines flip a few edge
# samples), and no pixel may differ by more than 0.1. Renders are deterministic, so on one
# machine the images are identical. `oiiotool --diff` is idiff's comparison; one oiiotool call
# compares every pair, because each process start costs most of a second.
THRESHOLDS = ["--fail", "0.004", "--failpercent", "0.5", "--hardfail", "0.1",
              "--warn", "0.002", "--warnpercent", "0.1"]
INFO = re.compile(r"^(.*?)\s+:\s+(\d+) x\s+(\d+), (\d+) channel, (\w+) (\w+)")
DIFF = re.compile(r'^Computing diff of "(.*)" vs "(.*)"')


def render_scene(gonio, scene, outdir):
    """Renders `scene` with the working folder `outdir`. Returns (error or None, images)."""
    shutil.rmtree(outdir, ignore_errors=True)
    os.makedirs(outdir)
    proc = subprocess.run([gonio, "render", scene], cwd=outdir, capture_output=True, text=True)
    images = sorted(f for f in os.listdir(outdir) if f.endswith(IMAGE_EXTENSIONS))
    if proc.returncode != 0:
        return f"gonio render exited with {proc.returncode}:\n{proc.stderr}", images
    if not images:
        return "gonio render wrote no image", images
    return None, images


def compare_all(pairs):
    """Compares every (rendered, golden) pair in one oiiotool run. Returns {rendered: error or
    None}: an error when the sizes, channel counts or data types differ, or the pixels differ
    beyond THRESHOLDS."""
    if not pairs:
        return {}
    command = ["oiiotool", "--info", *THRESHOLDS]
    for rendered, golden in pairs:
        command += [rendered, golden, "--diff"]
    proc = subprocess.run(command, capture_output=True, text=True)
    info, reports, current = {}, {}, None
    for line in proc.stdout.splitlines():
        if m := DIFF.match(line):
            current = m[1]
            reports[current] = [line]
        elif m := INFO.match(line):
            info[m[1]] = m.groups()[1:]
            current = None
        elif current:
            reports[current].append(line)
    results = {}
    for rendered, golden in pairs:
        report = reports.get(rendered, [f"oiiotool did not compare it:\n{proc.stderr}"])
        if info.get(rendered) != info.get(golden):
            results[rendered] = (f"size, channels or type {info.get(rendered)} differ from the "
                                 f"reference's {info.get(golden)}")
        elif report[-1] in ("PASS", "WARNING"):
            results[rendered] = None
        else:
            results[rendered] = "\n".join(report)
    return results


def stem(scene):
    return os.path.splitext(os.path.basename(scene))[0]


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

    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        rendered = list(pool.map(
            lambda scene: render_scene(args.gonio, scene, os.path.join(args.out, stem(scene))),
            scenes))

    pairs, problems = [], {}
    for scene, (error, images) in zip(scenes, rendered):
        problems[scene] = [error] if error else []
        for image in images:
            path, golden = os.path.join(args.out, stem(scene), image), os.path.join(args.golden, image)
            if args.update:
                shutil.copyfile(path, golden)
            elif not os.path.exists(golden):
                problems[scene].append(f"{image}: no reference {golden} "
                                       "(see tests/render/README.md)")
            else:
                pairs.append((scene, path, golden))
    differences = compare_all([(path, golden) for _, path, golden in pairs])
    for scene, path, golden in pairs:
        if differences[path]:
            problems[scene].append(f"{os.path.basename(path)} differs from {golden}:\n"
                                   f"{differences[path]}")

    all_images = set()
    for scene, (_, images) in zip(scenes, rendered):
        all_images.update(images)
        status = "FAIL" if problems[scene] else ("new " if args.update else "ok  ")
        print(f"{status} {stem(scene)} ({', '.join(images) or 'no image'})")
        for problem in problems[scene]:
            print("     " + problem.replace("\n", "\n     "))
    failed = sum(1 for scene in scenes if problems[scene])
    stale = []
    if not args.names and not args.update:
        # A reference that no scene writes any more would silently stop being tested.
        stale = sorted(f for f in os.listdir(args.golden)
                       if f.endswith(IMAGE_EXTENSIONS) and f not in all_images)
        for f in stale:
            print(f"FAIL stale reference {f}: no scene writes it")
    print(f"{len(scenes) - failed} of {len(scenes)} scenes passed")
    return 1 if failed or stale else 0

if __name__ == "__main__":
    sys.exit(main())
