#!/usr/bin/env python3
"""Photon paths per second of a BRDFLight job on the local single-host Slurm cluster
(tests/farm/slurm_cluster.py), for 1, 2, 4, ... shards of the same run: wall time from
`gonio farm submit` until every shard's map is written and checked, and until `gonio farm
status` says assembled (Slurm scheduling, every task's start-up, the trace, writing and checking
the shard's text map, the merge). Each shard runs with --cpus-per-task 1, so the cluster runs as
many at once as the node has CPUs. Also the same run as one `gonio render --threads 1` and with
all threads, for the per-core rate without the farm.

Usage: run_scaling.py --gonio build/bin/gonio [--paths 2000000] [--shards 1,2,4,8,16]
"""

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "tests", "farm"))
import slurm_cluster  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--gonio", required=True)
    ap.add_argument("--paths", type=int, default=2000000)
    ap.add_argument("--shards", default="1,2,4,8,16")
    args = ap.parse_args()
    gonio = os.path.abspath(args.gonio)
    work = tempfile.mkdtemp(prefix="gonio_farm_bench_")
    with open(os.path.join(ROOT, "ribs", "lambert_plane.rib")) as f:
        rib = f.read().replace('"integer rays" 100000', f'"integer rays" {args.paths}')
    scene = os.path.join(work, "plane.rib")
    with open(scene, "w") as f:
        f.write(rib)
    try:
        for threads in ("1", "0"):
            start = time.time()
            subprocess.run([gonio, "render", scene, "-o", os.path.join(work, "one.pm"),
                            "--threads", threads], check=True, capture_output=True)
            seconds = time.time() - start
            print(f"gonio render --threads {threads}: {seconds:.2f} s, "
                  f"{args.paths / seconds / 1e6:.3f} M paths/s; load {os.getloadavg()[0]:.1f}",
                  flush=True)
        with slurm_cluster.SlurmCluster(os.path.join(work, "cluster")) as cluster:
            print(f"cluster: {cluster.cpus} CPUs", flush=True)
            for n in [int(s) for s in args.shards.split(",")]:
                job = os.path.join(work, f"job{n}")
                run = lambda *a: subprocess.run([gonio, "farm", *a], env=cluster.env, check=True,
                                                capture_output=True, text=True).stdout
                run("plan", scene, "-o", job, "--photon-shards", str(n), "--cpus-per-task", "1")
                start = time.time()
                run("submit", job)
                traced = None  # when every shard's map is written and checked
                while True:
                    status = run("status", job)
                    if traced is None and f"{n}/{n} tasks done" in status:
                        traced = time.time() - start
                    if "; assembled" in status:
                        break
                    if time.time() - start > 600:
                        raise SystemExit(f"{n} shards: not assembled after 600 s")
                    time.sleep(0.1)
                seconds = time.time() - start
                print(f"{n:3d} shards: shards done in {traced:6.2f} s "
                      f"({args.paths / traced / 1e6:.3f} M paths/s), assembled in "
                      f"{seconds:6.2f} s ({args.paths / seconds / 1e6:.3f} M paths/s); load "
                      f"{os.getloadavg()[0]:.1f}", flush=True)
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
