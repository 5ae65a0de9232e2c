#!/usr/bin/env python3
"""Bit-flip sweep: damaged files must never crash, hang or confuse `dda`.

Makes one small file of each kind the project writes (2D lines, blocks and
results; 3D fractures, blocks and results) with the `dda` under test, then,
for each kind, FLIPS times: flips one random bit of a copy (random.Random
with a fixed seed, so a failure can be replayed) and runs the readers of that
kind on it (`dda info`; for results also `dda history --csv` and
`dda df --resume`, the results being of a run stopped half way). Each run must
end with exit status 0 (the flip hit bytes nobody reads) or 1 (one sentence:
the file is damaged), print at most one line on stderr, and finish within
TIMEOUT seconds. A signal, a hang, exit 3 (an internal error) or anything
else fails the sweep. docs/reliability.md, "Damaged files", has the numbers
of the full sweep (scripts/bitflip_sweep.sh).

Usage: bitflip_sweep.py DDA SOURCE_DIR WORK_DIR [--flips N] [--seed S] [--kinds k1,k2]
"""
import argparse
import collections
import os
import random
import shutil
import subprocess
import sys
import time

TIMEOUT = 20  # seconds; a healthy run takes well under one

SCENARIO_2D = """name: bitflip
seed: 7
domain:
  box: [0, 0, 20, 10]
joint_sets:
  - {name: J1, dip: 30, mean_length: 6, mean_bridge: 1, mean_spacing: 3, randomness: 0.3}
  - {name: J2, dip: 120, mean_length: 5, mean_bridge: 2, mean_spacing: 4, randomness: 0.3}
excavations:
  - {shape: rectangle, center: [10, 4], width: 4, height: 3}
points:
  - {name: roof, kind: measurement, at: [10.05, 6.3]}
  - {name: base, kind: fixed, at: [1, 0.5]}
  - {name: base2, kind: fixed, at: [19, 0.5]}
materials:
  default: {density: 2000, young: 5.0e9, poisson: 0.25, plane: stress}
joints:
  default: {friction_deg: 35}
control: {dt: 0.001, total_time: 0.004, output_interval: 0.002}
output: {vtk: false, plots: false}
"""


def run(cmd, cwd):
    r = subprocess.run(cmd, cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, timeout=300)
    if r.returncode != 0:
        sys.exit("bitflip_sweep: could not make the sample files: %s: %s" % (" ".join(cmd), r.stderr.decode()))


def make_files(dda, src, work):
    """The sample files, one per kind: {kind: (path, [reader argument lists])}."""
    with open(os.path.join(work, "s2.yaml"), "w") as f:
        f.write(SCENARIO_2D)
    run([dda, "dl", "s2.yaml", "-o", "lines.h5", "-q"], work)
    run([dda, "dc", "lines.h5", "-o", "blocks.h5", "-q"], work)
    # Results of a run stopped half way, so that `dda df --resume` reads the
    # whole file (model, frames, checkpoint) and runs the last two steps.
    run([dda, "df", "s2.yaml", "--blocks", "blocks.h5", "-o", "results.h5", "--stop-at-step", "2", "-q"], work)
    # The 3D incline of the CLI tests, a tenth of its run.
    with open(os.path.join(src, "tests", "data", "df3_incline.yaml")) as f:
        s3 = f.read().replace("total_time: 1, output_interval: 0.25", "total_time: 0.004, output_interval: 0.002").replace(
        "vtk: true", "vtk: false")
    with open(os.path.join(work, "s3.yaml"), "w") as f:
        f.write(s3)
    run([dda, "dl", "s3.yaml", "-o", "fractures.h5", "-q"], work)
    run([dda, "dc", "fractures.h5", "-o", "blocks3d.h5", "-q"], work)
    run([dda, "df", "s3.yaml", "--blocks", "blocks3d.h5", "-o", "results3d.h5", "--stop-at-step", "2", "-q"], work)
    info = lambda f: [["info", f]]
    # --resume last: it rewrites the file.
    both = lambda f: [["info", f], ["history", f, "--csv"], ["df", "--resume", f, "-q"]]
    return collections.OrderedDict([
        ("lines", ("lines.h5", info("x.h5"))),
        ("blocks", ("blocks.h5", info("x.h5"))),
        ("results", ("results.h5", both("x.h5"))),
        ("fractures", ("fractures.h5", info("x.h5"))),
        ("blocks3d", ("blocks3d.h5", info("x.h5"))),
        ("results3d", ("results3d.h5", both("x.h5"))),
    ])


def sweep_kind(dda, work, kind, original, readers, flips, rng):
    with open(os.path.join(work, original), "rb") as f:
        data = f.read()
    codes = collections.Counter()
    bad = []
    for i in range(flips):
        pos = rng.randrange(len(data))
        bit = rng.randrange(8)
        damaged = bytearray(data)
        damaged[pos] ^= 1 << bit
        with open(os.path.join(work, "x.h5"), "wb") as f:
            f.write(damaged)
        for args in readers:
            what = "%s flip %d (byte %d bit %d): dda %s" % (kind, i, pos, bit, " ".join(args))
            try:
                r = subprocess.run([dda] + args, cwd=work, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                                   timeout=TIMEOUT)
            except subprocess.TimeoutExpired:
                codes["hang"] += 1
                bad.append(what + ": no answer within %d s" % TIMEOUT)
                continue
            code = r.returncode
            codes["signal %d" % -code if code < 0 else code] += 1
            lines = r.stderr.decode(errors="replace").splitlines()
            if code < 0 or code not in (0, 1) or len(lines) > 1:
                bad.append("%s: exit %d, stderr %r" % (what, code, lines[:3]))
    return codes, bad


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("dda")
    ap.add_argument("source")
    ap.add_argument("work")
    ap.add_argument("--flips", type=int, default=300)
    ap.add_argument("--seed", type=int, default=27)
    ap.add_argument("--kinds", default="")
    a = ap.parse_args()
    dda = os.path.abspath(a.dda)
    shutil.rmtree(a.work, ignore_errors=True)
    os.makedirs(a.work)
    files = make_files(dda, os.path.abspath(a.source), a.work)
    kinds = [k for k in a.kinds.split(",") if k] or list(files)
    failures = []
    total = collections.Counter()
    for kind in kinds:
        original, readers = files[kind]
        rng = random.Random("%d-%s" % (a.seed, kind))  # one stream a kind: kinds can be swept alone
        t0 = time.time()
        codes, bad = sweep_kind(dda, a.work, kind, original, readers, a.flips, rng)
        total.update(codes)
        failures += bad
        size = os.path.getsize(os.path.join(a.work, original))
        print("%-10s %6d bytes  %5d flips  %5d runs  exit codes %s  failures %d  (%.0f s)" % (
            kind, size, a.flips, sum(codes.values()), dict(sorted(codes.items(), key=str)), len(bad),
            time.time() - t0), flush=True)
    print("total: %d runs, exit codes %s, failures %d" % (
        sum(total.values()), dict(sorted(total.items(), key=str)), len(failures)))
    for f in failures[:50]:
        print("FAIL " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
