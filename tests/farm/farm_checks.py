#!/usr/bin/env python3
"""gonio farm end to end, on a backend: `local` (child processes) or `slurm` (a real single-host
Slurm cluster started here, slurm_cluster.py). The same jobs and checks on both:

* 16 BRDFLight shards of the Lambert plane: the merged map equals the unsplit run's map line for
  line (so its counts are exactly the summed counts), and its iopt grid gives 1/pi within the 5%
  of tests/photon/cli_test.sh at the same angles (the single run's bias test);
* frame 1 of a 3-frame scene as 4x4 tiles: the joined image is identical, pixel for pixel, to the
  unsplit render (idiff -fail 0);
* the 3 frames as 3 tasks, each identical to `gonio render --frames N`;
* faults: an attempt killed with SIGKILL midway is retried and the job completes with a correct
  map; a corrupt shard is detected (assemble names it) and redone by the next submit; a missing
  task is reported by name.

Usage: farm_checks.py --gonio GONIO --ribs RIBS_DIR --backend local|slurm
"""

import argparse
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import slurm_cluster  # noqa: E402

INV_PI = 0.3183099
failures = []


def expect(ok, what):
    if not ok:
        failures.append(what)
        print("FAIL:", what, flush=True)


class Farm:
    def __init__(self, gonio, work, backend, env):
        self.gonio, self.work, self.backend, self.env = gonio, work, backend, env

    def run(self, *args, check=True):
        r = subprocess.run([self.gonio, *args], cwd=self.work, env=self.env,
                           capture_output=True, text=True)
        if check and r.returncode != 0:
            raise RuntimeError(f"gonio {' '.join(args)}: exit {r.returncode}\n{r.stdout}{r.stderr}")
        return r

    def plan(self, job, scene, *options):
        self.run("farm", "plan", scene, "-o", job, *options)
        return os.path.join(self.work, job)

    def submit(self, job):
        """Runs the job to its end; returns the text of its logs."""
        if self.backend == "local":
            r = self.run("farm", "submit", job, "--backend", "local", "--jobs", "2", check=False)
            return r.returncode, r.stdout + r.stderr
        self.run("farm", "submit", job)
        return self.wait(job)

    def wait(self, job, seconds=90):
        deadline = time.time() + seconds
        while time.time() < deadline:
            line = self.run("farm", "status", job).stdout
            if "; assembled" in line:
                return 0, self.logs(job)
            queued = any(s in line for s in ("PENDING", "RUNNING", "CONFIGURING", "COMPLETING"))
            if "none queued" in line and "assemble" not in line and not queued:
                return 1, self.logs(job)  # everything left the queue and nothing assembled
            time.sleep(0.5)
        raise RuntimeError(f"{job}: not done after {seconds} s: {line}\n{self.logs(job)}")

    def logs(self, job):
        folder = os.path.join(self.work, job, "logs")
        text = ""
        for name in sorted(os.listdir(folder)) if os.path.isdir(folder) else []:
            with open(os.path.join(folder, name), errors="replace") as f:
                text += f.read()
        return text


def read(path):
    with open(path) as f:
        return f.read()


def header(path):
    """(photons, paths) of a photon map's first line; one number when all paths escaped up."""
    with open(path) as f:
        numbers = [int(n) for n in f.readline().split()]
    return numbers[0], numbers[-1]


def eval_grd(farm, grd, angles):
    out = farm.run("brdf", "eval", grd, *angles.split()).stdout.split()
    return float(out[-1])


def check_shards(farm, ribs):
    shutil.copy(os.path.join(ribs, "lambert_plane.rib"), farm.work)
    farm.run("render", "lambert_plane.rib", "-o", "single.pm")
    job = farm.plan("shards", "lambert_plane.rib", "--photon-shards", "16", "--chunk", "2",
                    "--throttle", "2", "--brdf", "iopt 8 24 0.5 0")
    code, log = farm.submit("shards")
    expect(code == 0, f"the 16-shard job failed:\n{log}")
    merged = os.path.join(job, "photons", "frame_0000.pm")
    if not os.path.exists(merged):
        return job
    single = read(os.path.join(farm.work, "single.pm"))
    counts = [header(os.path.join(job, "shards", f"frame_0000_shard_{s:04d}.pm"))
              for s in range(16)]
    photons, paths = sum(c[0] for c in counts), sum(c[1] for c in counts)
    expect(header(merged) == (photons, 100000) and paths == 100000,
           f"merged header {header(merged)}, the shards sum to {photons} photons of {paths} paths")
    expect(read(merged) == single, "the merged map differs from the unsplit run's map")
    for angles in ["0 0 0 0", "30 0 45 90", "45 0 45 180", "60 0 30 0", "20 0 70 270"]:
        value = eval_grd(farm, os.path.join(job, "photons", "frame_0000.grd"), angles)
        expect(abs(value / INV_PI - 1) < 0.05, f"brdf eval {angles} = {value}, not 1/pi within 5%")
    print(f"shards: 16 shards, {photons} photons of {paths} paths, merged map identical to the "
          "unsplit run, iopt grid 1/pi within 5%", flush=True)
    return job


def check_corrupt_and_missing(farm, job):
    shard3 = os.path.join(job, "shards", "frame_0000_shard_0003.pm")
    text = read(shard3)
    with open(shard3, "w") as f:  # cut mid-line, as a full disk or a crashed copy would
        f.write(text[: len(text) // 2])
    r = farm.run("farm", "assemble", "shards", check=False)
    expect(r.returncode == 1 and "task 3 (frame 0 shard 3/16)" in r.stderr,
           f"a corrupt shard: assemble exit {r.returncode}, said: {r.stderr}")
    code, log = farm.submit("shards")
    expect(code == 0 and "frame_0000_shard_0003.pm is not valid" in log and "redoing" in log,
           f"the corrupt shard was not redone (exit {code}):\n{log}")
    expect(read(os.path.join(job, "photons", "frame_0000.pm")) ==
           read(os.path.join(farm.work, "single.pm")),
           "after redoing the corrupt shard the merged map differs from the unsplit run's")
    os.remove(os.path.join(job, "shards", "frame_0000_shard_0005.pm"))
    r = farm.run("farm", "assemble", "shards", check=False)
    expect(r.returncode == 1 and "task 5 (frame 0 shard 5/16): "
           "shards/frame_0000_shard_0005.pm: missing" in r.stderr,
           f"a missing task: assemble exit {r.returncode}, said: {r.stderr}")
    status = farm.run("farm", "status", "shards").stdout
    expect("15/16 tasks done" in status, f"status with a missing task: {status}")
    print("faults: corrupt shard named and redone, missing task named", flush=True)


def check_killed_attempt(farm, ribs):
    """A long shard whose first attempt is killed with SIGKILL as soon as it runs."""
    with open(os.path.join(ribs, "lambert_plane.rib")) as f:
        rib = f.read().replace('"integer rays" 100000', '"integer rays" 1000000')
    with open(os.path.join(farm.work, "long.rib"), "w") as f:
        f.write(rib.replace("lambert_plane.pm", "long.pm"))
    job = farm.plan("killed", "long.rib", "--photon-shards", "2", "--cpus-per-task", "1")
    pidfile = os.path.join(job, "run", "task_0000.pid")
    if farm.backend == "local":
        runner = subprocess.Popen([farm.gonio, "farm", "submit", "killed", "--backend", "local",
                                   "--jobs", "2"], cwd=farm.work, env=farm.env,
                                  stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    else:
        farm.run("farm", "submit", "killed")
    deadline, killed = time.time() + 60, None
    while time.time() < deadline and killed is None:
        try:
            killed = int(read(pidfile))
            os.kill(killed, signal.SIGKILL)
        except (OSError, ValueError):
            killed = None
            time.sleep(0.01)
    expect(killed is not None, "the first shard's attempt never showed its pid")
    if farm.backend == "local":
        log = runner.communicate(timeout=120)[0]
        code = runner.returncode
    else:
        code, log = farm.wait("killed", 120)
    expect(code == 0, f"the job with a killed attempt failed:\n{log}")
    expect("attempt 1 of 3 failed: killed by signal 9" in log and "(attempt 2)" in log,
           f"the killed attempt was not retried:\n{log}")
    merged = header(os.path.join(job, "photons", "frame_0000.pm"))
    shards = [header(os.path.join(job, "shards", f"frame_0000_shard_{s:04d}.pm"))
              for s in range(2)]
    expect(merged == (sum(s[0] for s in shards), 1000000) and
           [s[1] for s in shards] == [500000, 500000],
           f"after a killed attempt the merged header is {merged}, the shards' {shards}")
    farm.run("render", "long.rib", "--photon-shard", "0/2", "-o", "long_0.pm")
    expect(read(os.path.join(job, "shards", "frame_0000_shard_0000.pm")) ==
           read(os.path.join(farm.work, "long_0.pm")),
           "the retried shard differs from gonio render --photon-shard 0/2")
    leftovers = [n for n in os.listdir(os.path.join(job, "shards")) if n.startswith(".")]
    expect(not leftovers, f"the killed attempt left {leftovers}")
    print(f"faults: attempt {killed} killed with SIGKILL, retried, map complete", flush=True)


def idiff_same(a, b):
    r = subprocess.run(["idiff", "-fail", "0", "-failpercent", "0", "-warn", "0", a, b],
                       capture_output=True, text=True)
    return r.returncode == 0, r.stdout


def expect_tiles_join_to_the_unsplit_render(farm, job_name, scene, full, render_args,
                                             plan_args, frame_image, what):
    """Renders `scene` whole into `full`, then as the tile job `job_name`; the joined frame
    must equal the whole render pixel for pixel."""
    farm.run("render", scene, *render_args, "-o", full)
    job = farm.plan(job_name, scene, *plan_args)
    code, log = farm.submit(job_name)
    expect(code == 0, f"the {what} job failed:\n{log}")
    same, text = idiff_same(os.path.join(job, "images", frame_image),
                            os.path.join(farm.work, full))
    expect(same, f"the joined {what} differ from the unsplit render:\n{text}")


def check_cropped_tiles(farm):
    """3x2 tiles of a scene with its own CropWindow, in float OpenEXR."""
    expect_tiles_join_to_the_unsplit_render(
        farm, "cropped", os.path.join(HERE, "scenes", "crop.rib"), "crop_full.exr", [],
        ["--tiles", "3x2"], "frame_0000.exr", "tiles of a CropWindow")
    print("tiles: 3x2 tiles of a CropWindow joined, identical to the unsplit render", flush=True)


def expect_failure(farm, args, code, message):
    r = farm.run(*args, check=False)
    expect(r.returncode == code and message in r.stderr,
           f"gonio {' '.join(args)}: exit {r.returncode} (expected {code}), said "
           f"{r.stderr!r}, expected {message!r}")


def check_errors(farm):
    """Bad command lines and bad job folders: clear errors, the right exit status."""
    scene = os.path.join(HERE, "scenes", "frames.rib")
    expect_failure(farm, ["render", scene, "--frames", "3-1"], 2, "is empty")
    expect_failure(farm, ["render", scene, "--frames", "x"], 2, "expected frames as A-B")
    expect_failure(farm, ["render", scene, "--frames", "7-9"], 2, "no frame in --frames 7-9")
    expect_failure(farm, ["render", scene, "--crop", "0.5", "0.2", "0", "1"], 2,
                   "--crop expects X0 X1 Y0 Y1")
    expect_failure(farm, ["render", scene, "--photon-shard", "16/16"], 2,
                   "--photon-shard expects I/N with 0 <= I < N")
    png = os.path.join(farm.work, "png.rib")
    with open(scene) as f:
        text = f.read().replace('"frames.tif" "tiff"', '"frames.png" "png"')
    with open(png, "w") as f:
        f.write(text)
    expect_failure(farm, ["farm", "plan", png, "-o", "pngjob", "--tiles", "2x2"], 1,
                   "cannot record where a tile lies")
    expect_failure(farm, ["farm", "plan", scene, "-o", "nojob", "--photon-shards", "4"], 1,
                   "--photon-shards needs a frame with Option \"BRDFLight\"")
    farm.plan("errjob", scene, "--frames", "2")
    expect_failure(farm, ["farm", "plan", scene, "-o", "errjob"], 2, "already holds a job")
    expect_failure(farm, ["farm", "task", "errjob", "5"], 1,
                   "errjob/manifest.json: error: array task 5 is out of range")
    expect_failure(farm, ["farm", "assemble", "errjob"], 1,
                   "task 0 (frame 2): images/frame_0002.tif: missing")
    expect_failure(farm, ["farm", "status", "nosuchjob"], 1,
                   "nosuchjob/manifest.json: error: cannot read the manifest")
    with open(os.path.join(farm.work, "errjob", "manifest.json"), "a") as f:
        f.write("}")
    expect_failure(farm, ["farm", "task", "errjob", "0"], 1,
                   "errjob/manifest.json: error: not valid JSON")
    print("errors: bad options, plans and job folders give clear errors", flush=True)


def check_tiles(farm, scene):
    expect_tiles_join_to_the_unsplit_render(
        farm, "tiles", scene, "full_1.tif", ["--frames", "1"],
        ["--frames", "1", "--tiles", "4x4", "--chunk", "4", "--throttle", "2"],
        "frame_0001.tif", "4x4 tiles")
    print("tiles: 16 tiles joined, identical to the unsplit render", flush=True)


def check_frames(farm, scene):
    tasks = farm.run("farm", "plan", scene, "-o", "frames", "--throttle", "2").stdout
    expect("3 tasks" in tasks, f"a 3-frame scene planned as: {tasks}")
    job = os.path.join(farm.work, "frames")
    code, log = farm.submit("frames")
    expect(code == 0, f"the 3-frame job failed:\n{log}")
    for n in (1, 2, 3):
        farm.run("render", scene, "--frames", str(n), "-o", f"direct_{n}.tif")
        same, text = idiff_same(os.path.join(job, "images", f"frame_{n:04d}.tif"),
                                os.path.join(farm.work, f"direct_{n}.tif"))
        expect(same, f"frame {n} of the farm differs from gonio render --frames {n}:\n{text}")
    print("frames: 3 frames as 3 tasks, each identical to gonio render --frames N", flush=True)


def timed(name, check, *args):
    start = time.time()
    result = check(*args)
    print(f"  ({name}: {time.time() - start:.1f} s)", flush=True)
    return result


def run_checks(farm, ribs):
    scene = os.path.join(HERE, "scenes", "frames.rib")
    job = timed("shards", check_shards, farm, ribs)
    timed("corrupt and missing", check_corrupt_and_missing, farm, job)
    timed("killed attempt", check_killed_attempt, farm, ribs)
    timed("tiles", check_tiles, farm, scene)
    timed("frames", check_frames, farm, scene)
    if farm.backend == "local":  # the same code on Slurm; run once, where it is cheaper
        timed("cropped tiles", check_cropped_tiles, farm)
        timed("errors", check_errors, farm)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--gonio", required=True)
    ap.add_argument("--ribs", required=True)
    ap.add_argument("--backend", choices=["local", "slurm"], required=True)
    args = ap.parse_args()
    gonio = os.path.abspath(args.gonio)
    # A SIGTERM (ctest, a person) unwinds through the cluster's `with`, which stops the daemons.
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(1))
    work = tempfile.mkdtemp(prefix="gonio_farm_")
    start = time.time()
    try:
        if args.backend == "local":
            run_checks(Farm(gonio, work, "local", dict(os.environ)), args.ribs)
        else:
            missing = slurm_cluster.missing_binaries()
            if missing:
                print(f"SKIPPED: the Slurm cluster test needs {', '.join(missing)} "
                      "(apt-get install slurm-wlm munge)")
                return 0
            with slurm_cluster.SlurmCluster(os.path.join(work, "cluster")) as cluster:
                print(f"slurm: cluster up in {time.time() - start:.1f} s", flush=True)
                run_checks(Farm(gonio, work, "slurm", cluster.env), args.ribs)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print(f"{args.backend}: {time.time() - start:.1f} s")
    if failures:
        print(f"{len(failures)} failure(s)")
        return 1
    print("all farm checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
