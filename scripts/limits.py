#!/usr/bin/python3
"""Limit runs of the command-line program on a big mesh (not part of the test suite).

  limits.py MEDIAL_AXIS MESH.vtp [--samples N] [--rss] [--interrupt-after S ...]

--rss: one full run with --stats, then its peak RSS (getrusage of the child) and wall time.
--interrupt-after S: a run that gets SIGINT S seconds after its start; prints how long it
took from the signal to the exit, and the exit code (130 expected). Several S may be given.
Each line is also printed as one JSON object at the end. The machine's load average is
printed first, as it changes the figures.
Make the 1.55 M-triangle horse with scripts/big-horse.py."""
import json
import os
import resource
import signal
import subprocess
import sys
import tempfile
import time


def main():
    args = sys.argv[1:]
    if len(args) < 2:
        sys.exit(__doc__)
    cli, mesh = args[0], args[1]
    samples, rss, delays = 1000000, False, []
    i = 2
    while i < len(args):
        if args[i] == "--samples":
            samples = int(args[i + 1])
            i += 2
        elif args[i] == "--rss":
            rss = True
            i += 1
        elif args[i] == "--interrupt-after":
            delays.append(float(args[i + 1]))
            i += 2
        else:
            sys.exit("limits.py: unknown argument " + args[i])
    print("load average: %.2f %.2f %.2f" % os.getloadavg(), flush=True)
    results = []
    command = [cli, mesh, "-n", str(samples)]
    if rss:
        start = time.monotonic()
        run = subprocess.run(command + ["--stats"], capture_output=True, text=True)
        wall = time.monotonic() - start
        peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024.0
        row = {"run": "full", "samples": samples, "exit": run.returncode, "wall_s": round(wall, 2),
               "peak_rss_mib": round(peak, 1), "stats": run.stdout.strip()}
        print(row, flush=True)
        results.append(row)
    # An interrupted run still needs an output to ask for (the program refuses to run
    # without one); it never gets to write it.
    scratch = tempfile.TemporaryDirectory()
    interrupted = command + ["-o", os.path.join(scratch.name, "interrupted.vtp")]
    for delay in delays:
        child = subprocess.Popen(interrupted, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        time.sleep(delay)
        sent = time.monotonic()
        child.send_signal(signal.SIGINT)
        try:
            child.wait(timeout=120)
        except subprocess.TimeoutExpired:
            child.kill()
            child.wait()
        latency = time.monotonic() - sent
        row = {"run": "interrupt", "after_s": delay, "exit": child.returncode,
               "latency_s": round(latency, 3), "message": child.stderr.read().strip()[-80:]}
        print(row, flush=True)
        results.append(row)
    print(json.dumps(results))
    interrupts = [r for r in results if r["run"] == "interrupt"]
    latencies = [r["latency_s"] for r in interrupts if r["exit"] == 130]
    if latencies:
        print("max SIGINT-to-exit latency: %.3f s over %d trials" % (max(latencies), len(latencies)))
    if len(latencies) < len(interrupts):
        # A run that ended otherwise (an error, or done before the signal) has no latency.
        print("limits.py: %d of %d interrupted runs did not exit with 130" % (len(interrupts) - len(latencies), len(interrupts)))
        sys.exit(1)


if __name__ == "__main__":
    main()
