#!/usr/bin/env python3
"""What a frame costs from Python against the CLI (target: at most 3% more). Builds nothing: give
it a build folder with tools/toyhost and the Python module (BUILD/python).

Both sides do the same work per frame: render it and read it back into memory. The CLI streams
raw RGBA to stdout (`--out -`, sent to /dev/null) and reports its frame loop's time (first frame
and the rest); the Python side, in a fresh process each time like the CLI, times
`session.step(); session.frame()` (a new numpy array per frame), and the render() iterator, over
the same frames, from after `import toyhost` (which imports numpy) and the session's creation, as
the CLI's clock starts after its start-up. Runs alternate CLI / Python and the median of each is
kept, with a 90% interval on each ratio: one run varies by tens of percent on a small machine.

usage: tools/bench/python_bench.py BUILD_DIR [--reps N] [--quick] [--write docs/performance.md]
(--write replaces the block between "<!-- python-bench:begin -->" and "<!-- python-bench:end -->")"""

import argparse
import os
import resource
import pathlib
import random
import re
import statistics
import subprocess
import sys
import time

REPO = pathlib.Path(__file__).resolve().parents[2]


def children_cpu():
    """CPU seconds (user + system, every thread) used so far by this process's finished children."""
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def cli_seconds(toyhost, target, size, frames):
    """The CLI's frame loop (first frame + the rest) from its summary line, in seconds."""
    done = subprocess.run([str(toyhost), "run", str(target), "--headless", "--size", f"{size[0]}x{size[1]}",
                           "--frames", str(frames), "--out", "-"],
                          stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, check=True)
    line = next(l for l in done.stderr.splitlines() if " frames at " in l)
    first = re.search(r"first frame ([0-9.]+) (ms|s)", line)
    rest = re.search(r"then \d+ frames in ([0-9.]+) (ms|s)", line)

    def seconds(match):
        return float(match.group(1)) / (1000 if match.group(2) == "ms" else 1) if match else 0.0

    return seconds(first) + seconds(rest)


def python_seconds(build, target, size, frames, way="step"):
    """The same frames from Python, in a child process: seconds of its loop (`way`: step() then
    frame() per frame, or the render() iterator)."""
    env = dict(os.environ, PYTHONPATH=str(pathlib.Path(build) / "python"))
    done = subprocess.run([sys.executable, __file__, "--child", way, str(target), str(size[0]), str(size[1]), str(frames)],
                          stdout=subprocess.PIPE, text=True, check=True, env=env)
    return float(done.stdout.strip())


def child(way, target, width, height, frames):
    import toyhost

    with toyhost.Session(toyhost.load(target), size=(width, height)) as session:
        start = time.perf_counter()
        if way == "step":
            for _ in range(frames):
                session.step()
                session.frame()
        else:
            for _ in session.render(frames):
                pass
        print(time.perf_counter() - start)


def interval_and_verdict(python, cli):
    """The ratio of the medians' 90% interval (bootstrap: both sides' runs resampled) and the
    verdict: met only where the whole interval is within 3%, NOT met where all of it is above."""
    draw = random.Random(1)
    ratios = sorted(statistics.median(draw.choices(python, k=len(python)))
                    / statistics.median(draw.choices(cli, k=len(cli))) for _ in range(2000))
    low, high = ratios[100], ratios[1899]
    if high <= 1.03:
        verdict = "met"
    elif low > 1.03:
        verdict = "NOT met"
    else:
        median_met = statistics.median(python) / statistics.median(cli) <= 1.03
        verdict = f"{'median met' if median_met else 'median not met'}, not shown either way"
    return f"{low:.3f}-{high:.3f} | <= 1.03: {verdict}"


def busy_ticks():
    with open("/proc/stat") as stat:
        fields = stat.readline().split()
    return sum(int(fields[i]) for i in (1, 2, 3, 6, 7, 8))


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "--child":
        child(sys.argv[2], sys.argv[3], int(sys.argv[4]), int(sys.argv[5]), int(sys.argv[6]))
        return
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("build")
    parser.add_argument("--reps", type=int, default=5)
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--write")
    args = parser.parse_args()
    toyhost = pathlib.Path(args.build) / "tools/toyhost"
    if not toyhost.exists() or not list((pathlib.Path(args.build) / "python/toyhost").glob("_toyhost*.so")):
        sys.exit(f"python_bench: build {args.build} first (tools/toyhost and the Python module)")
    # (name, target, size, frames, reps). The trivial case takes many short runs: one run's frame
    # time depends on where its threads land on the 2 cores and varies by +-20% from process to
    # process, so the medians need many processes, not many frames.
    cases = [("trivial shader 320x180", REPO / "shadertoys/bench-trivial", (320, 180), 300 if args.quick else 2000,
              args.reps * 6)]
    if (REPO.parent / "shared/shadertoys/MdXyzX/image.glsl").exists():
        cases.append(("ocean 800x450", REPO / "shadertoys/ocean", (800, 450), 8 if args.quick else 30, args.reps))
    else:
        print("python_bench: no ../shared/shadertoys: the ocean is left out", file=sys.stderr)

    started, busy_before, own_before = time.time(), busy_ticks(), os.times()
    rows, cpu_rows = [], []
    for name, target, size, frames, reps in cases:
        times = {"cli": [], "step": [], "render": []}
        cpu = {"cli": [], "step": [], "render": []}  # CPU seconds per frame, start-up cancelled
        short = max(2, frames // 10)
        for rep in range(reps):
            # Rotate which side goes first, so that a slow spell of the shared machine is shared.
            runs = [("cli", lambda n: cli_seconds(toyhost, target, size, n)),
                    ("step", lambda n: python_seconds(args.build, target, size, n, "step")),
                    ("render", lambda n: python_seconds(args.build, target, size, n, "render"))]
            for side, measure in runs[rep % 3:] + runs[:rep % 3]:
                # The whole process's CPU time (every thread: llvmpipe's, the encoders', Python's)
                # for `frames` frames minus that for `short` frames: what the frames between cost,
                # without start-up. Far steadier than wall time on a shared 2-core machine.
                before = children_cpu()
                times[side].append(measure(frames))
                middle = children_cpu()
                measure(short)
                cpu[side].append(((middle - before) - (children_cpu() - middle)) / (frames - short))
            print(f"  {name} rep {rep + 1}: " + ", ".join(f"{side} {t[-1] * 1000 / frames:.3f}" for side, t in times.items())
                  + " ms/frame; CPU " + ", ".join(f"{side} {t[-1] * 1000:.3f}" for side, t in cpu.items())
                  + " ms/frame", file=sys.stderr)
        c = statistics.median(times["cli"]) * 1000 / frames
        cc = statistics.median(cpu["cli"]) * 1000
        for way, label in (("step", "step(); frame()"), ("render", "render()")):
            p = statistics.median(times[way]) * 1000 / frames
            ratio = p / c
            rows.append(f"| {name}, {frames} frames, each read back: Python `{label}` / CLI `--out -` | "
                        f"{p:.3f} ms/frame | {c:.3f} ms/frame | **{ratio:.3f}** ({(p - c) * 1000:+.0f} us/frame) | "
                        f"{interval_and_verdict(times[way], times['cli'])} |")
            pc = statistics.median(cpu[way]) * 1000
            cpu_rows.append(f"| {name}, {frames} frames: Python `{label}` / CLI `--out -` | {pc:.3f} ms/frame | "
                            f"{cc:.3f} ms/frame | **{pc / cc:.3f}** ({(pc - cc) * 1000:+.0f} us/frame) | {interval_and_verdict(cpu[way], cpu['cli'])} |")
    elapsed = time.time() - started
    own = os.times()
    own_ticks = ((own.children_user - own_before.children_user) + (own.children_system - own_before.children_system)
                 + (own.user - own_before.user) + (own.system - own_before.system)) * os.sysconf("SC_CLK_TCK")
    others = max(0.0, (busy_ticks() - busy_before - own_ticks) / (elapsed * os.sysconf("SC_CLK_TCK") * os.cpu_count()))
    commit = subprocess.run(["git", "-C", str(REPO), "rev-parse", "--short", "HEAD"], stdout=subprocess.PIPE,
                            text=True, check=False).stdout.strip()
    dirty = subprocess.run(["git", "-C", str(REPO), "status", "--porcelain", "--untracked-files=no"],
                           stdout=subprocess.PIPE, text=True, check=False).stdout.strip()
    block = "\n".join([
        f"Measured {time.strftime('%Y-%m-%d')} on {os.cpu_count()} cores (llvmpipe); toyhost {commit}"
        f"{' with uncommitted changes' if dirty else ''}; "
        f"medians of {', '.join(f'{c[4]} runs ({c[0].split()[0]})' for c in cases)}, CLI and Python alternating; "
        f"took {elapsed:.0f} s; CPU used by other processes meanwhile: {others * 100:.0f}% of the machine.",
        "",
        "Wall time of the frame loop (each side's own clock, start-up excluded):",
        "",
        "| Case | Python | CLI | Python / CLI (medians) | 90% interval | target |",
        "| --- | --- | --- | --- | --- | --- |",
        *rows,
        "",
        "CPU time per frame, every thread of the process (a run of N frames minus a run of N/10, over",
        "the frames between: start-up cancels out):",
        "",
        "| Case | Python | CLI | Python / CLI (medians) | 90% interval | target |",
        "| --- | --- | --- | --- | --- | --- |",
        *cpu_rows,
    ])
    print(block)
    if args.write:
        doc = pathlib.Path(args.write)
        text = doc.read_text()
        begin, end = "<!-- python-bench:begin -->", "<!-- python-bench:end -->"
        if begin not in text or end not in text:
            sys.exit(f"python_bench: {doc} has no {begin} ... {end} block")
        head, rest = text.split(begin, 1)
        doc.write_text(head + begin + "\n\n" + block + "\n\n" + end + rest.split(end, 1)[1])
        print(f"python_bench: wrote {doc}", file=sys.stderr)


if __name__ == "__main__":
    main()
