#!/usr/bin/env python3
"""Dask shards against one session (docs/performance.md, "Dask shards"): toyhost.farm.render of a
shadertoy in S shards on a LocalCluster of W worker processes (one thread each) against one
Session rendering the same frames, each yielding every frame into memory. Builds nothing: give it
a build folder with the Python module (BUILD/python), so the same script measures any build.

Pairs alternate which side runs first; the median of each side's wall time and CPU time is kept.
The single session runs in a fresh process and is timed there from after `import toyhost` (load,
session, compile, frames); its CPU is that process's (every thread). The shards run on a cluster
started once before the pairs (its start-up is not counted, as a real cluster is already up); their
wall time is from submitting the shards to the last frame received, their CPU is the worker
processes' plus this process's (the scheduler and client run here). Each shard's own compute time
comes from Dask's task stream. Every pair checks the shards' frames against the session's, byte
for byte.

usage: tools/bench/farm_bench.py BUILD_DIR [--target shadertoys/ocean] [--size 320x180]
       [--frames 240] [--shards 4] [--workers 2] [--reps 3]"""

import argparse
import hashlib
import json
import os
import pathlib
import resource
import statistics
import subprocess
import sys
import time

REPO = pathlib.Path(__file__).resolve().parents[2]
DATE = "2024-01-01T00:00:00"

SINGLE = r"""
import hashlib, json, resource, sys, time
import toyhost
target, width, height, frames, date = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4]), sys.argv[5]
def cpu():
    u = resource.getrusage(resource.RUSAGE_SELF)
    return u.ru_utime + u.ru_stime
wall0, cpu0 = time.perf_counter(), cpu()
with toyhost.Session(toyhost.load(target), size=(width, height), date=date) as session:
    digests = [(i, hashlib.sha256(a.tobytes()).hexdigest()) for i, a in session.render(frames)]
print(json.dumps({"wall": time.perf_counter() - wall0, "cpu": cpu() - cpu0, "frames": digests}))
"""


def single(python_dir, target, size, frames):
    env = {**os.environ, "PYTHONPATH": str(python_dir)}
    done = subprocess.run([sys.executable, "-c", SINGLE, str(target), str(size[0]), str(size[1]), str(frames), DATE],
                          capture_output=True, text=True, env=env, check=True)
    return json.loads(done.stdout)


def self_cpu():
    u = resource.getrusage(resource.RUSAGE_SELF)
    return u.ru_utime + u.ru_stime


def sharded(client, workers, target, size, frames, shards):
    import toyhost.farm
    from dask.distributed import get_task_stream

    def worker_cpu():
        total = 0.0
        for process in workers:
            times = process.cpu_times()
            total += times.user + times.system
        return total

    wall0, cpu0 = time.perf_counter(), worker_cpu() + self_cpu()
    with get_task_stream(client) as stream:
        digests = [(i, hashlib.sha256(a.tobytes()).hexdigest())
                   for i, a in toyhost.farm.render(target, frames, client=client, shards=shards, size=size, date=DATE)]
    wall = time.perf_counter() - wall0
    cpu = worker_cpu() + self_cpu() - cpu0
    tasks = []
    for task in stream.data:
        if "_render_shard_task" not in task["key"]:
            continue
        compute = [s for s in task["startstops"] if s["action"] == "compute"]
        tasks.append(sum(s["stop"] - s["start"] for s in compute))
    return {"wall": wall, "cpu": cpu, "frames": digests, "tasks": tasks}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("build", type=pathlib.Path)
    parser.add_argument("--target", type=pathlib.Path, default=REPO / "shadertoys/ocean")
    parser.add_argument("--size", default="320x180")
    parser.add_argument("--frames", type=int, default=240)
    parser.add_argument("--shards", type=int, default=4)
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--reps", type=int, default=3)
    a = parser.parse_args()
    size = tuple(int(v) for v in a.size.split("x"))
    python_dir = (a.build / "python").resolve()
    sys.path.insert(0, str(python_dir))
    import psutil
    import toyhost
    from dask.distributed import Client, LocalCluster

    print(f"toyhost {toyhost.__version__} from {python_dir}; {a.target.name} {a.size}, {a.frames} frames; "
          f"{a.shards} shards on LocalCluster(n_workers={a.workers}, threads_per_worker=1)", flush=True)
    env_path = os.environ.get("PYTHONPATH", "")
    os.environ["PYTHONPATH"] = str(python_dir) + (os.pathsep + env_path if env_path else "")
    with LocalCluster(n_workers=a.workers, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
            Client(cluster) as client:
        pids = list(client.run(os.getpid).values())
        workers = [psutil.Process(pid) for pid in pids]
        singles, shards = [], []
        for rep in range(a.reps):
            order = ["single", "shards"] if rep % 2 == 0 else ["shards", "single"]
            got = {}
            for side in order:
                if side == "single":
                    got[side] = single(python_dir, a.target, size, a.frames)
                else:
                    got[side] = sharded(client, workers, a.target, size, a.frames, a.shards)
            if [list(f) for f in got["single"]["frames"]] != [list(f) for f in got["shards"]["frames"]]:
                sys.exit("the shards' frames differ from the single session's")
            singles.append(got["single"])
            shards.append(got["shards"])
            print(f"pair {rep + 1} ({' then '.join(order)}): one session {got['single']['wall']:.2f} s wall, "
                  f"{got['single']['cpu']:.2f} s CPU; {a.shards} shards {got['shards']['wall']:.2f} s wall, "
                  f"{got['shards']['cpu']:.2f} s CPU; shard tasks "
                  + ", ".join(f"{t:.2f}" for t in got["shards"]["tasks"]) + " s; frames identical", flush=True)

    def median(runs, key):
        return statistics.median(r[key] for r in runs)

    sw, sc, fw, fc = median(singles, "wall"), median(singles, "cpu"), median(shards, "wall"), median(shards, "cpu")
    print(f"medians of {a.reps}: one session {sw:.2f} s wall, {sc:.2f} s CPU; {a.shards} shards {fw:.2f} s wall, "
          f"{fc:.2f} s CPU; shards / session: wall {fw / sw:.2f}x, CPU {fc / sc:.2f}x")


if __name__ == "__main__":
    main()
