#!/usr/bin/env python3
"""The example's pass/fail check (exit status 1 on failure).

* the wedge's yield acceleration (`dda wedge --json`, shaking along +y)
  against the expected value (docs/validation.md V4: 0.2074 g for phi = 30 deg);
* each back-fitted segment friction angle (`dda backfit` JSON) against the
  true angle of the friction table that made the measurement (the table must
  be constant inside each segment);
* the overall RMS misfit of the back-fit against the noise level of the
  measurement (a fit that explains the data leaves about the noise).
"""
import argparse
import json
import sys

from friction_table import read_friction_table  # (this folder)


def phi_at(rows, t):
    """Piecewise-linear angle at t (t not at a step)."""
    if t <= rows[0][0]:
        return rows[0][1]
    for (t0, p0), (t1, p1) in zip(rows, rows[1:]):
        if t0 <= t <= t1 and t1 > t0:
            return p0 + (p1 - p0) * (t - t0) / (t1 - t0)
    return rows[-1][1]


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--wedge", required=True, help="dda wedge --json output")
    ap.add_argument("--backfit", required=True, help="dda backfit -o output")
    ap.add_argument("--friction-table", required=True, help="the true friction table")
    ap.add_argument("--expected-yield", type=float, required=True, help="g")
    ap.add_argument("--yield-tol", type=float, required=True, help="g")
    ap.add_argument("--phi-tol", type=float, required=True, help="deg")
    ap.add_argument("--noise", type=float, required=True, help="noise sd of the measurement (m)")
    ap.add_argument("--rms-factor", type=float, default=1.5,
                    help="fail if the back-fit RMS exceeds this times the noise sd")
    a = ap.parse_args()
    failures = []

    with open(a.wedge) as f:
        w = json.load(f)
    ky = w["yield_acceleration_g"]
    ok = ky is not None and abs(ky - a.expected_yield) <= a.yield_tol
    kys = "none" if ky is None else f"{ky:.5f}"
    print(f"yield acceleration along +y: {kys} g, expected {a.expected_yield} g "
          f"(tolerance {a.yield_tol} g): {'ok' if ok else 'FAIL'}")
    if not ok:
        failures.append("yield acceleration")

    with open(a.backfit) as f:
        bf = json.load(f)
    rows = read_friction_table(a.friction_table)
    print(f"{'segment':>14} {'true phi':>9} {'fitted phi':>11} {'error':>8}  {'mu':>7} {'mean v [mm/s]':>13}")
    for s in bf["segments"]:
        t0, t1 = s["t0"], s["t1"]
        inside = [phi_at(rows, t0 + (t1 - t0) * k / 20.0) for k in range(1, 20)]
        if max(inside) - min(inside) > 1e-9:
            failures.append(f"friction table not constant in {t0:g}..{t1:g} s")
            continue
        true = inside[0]
        err = s["phi_deg"] - true
        ok = abs(err) <= a.phi_tol
        print(f"{t0:6g} .. {t1:4g} s {true:9.3f} {s['phi_deg']:11.4f} {err:+8.4f}  {s['mu']:7.4f} "
              f"{1000 * s['mean_speed']:13.4f}  {'ok' if ok else 'FAIL'}")
        if not ok:
            failures.append(f"segment {t0:g}..{t1:g} s")
    r = bf["regression"]
    print(f"regression over the segments: mu = {r['a']:.4f} {r['b']:+.5f} ln(v / {bf['v_ref']:g} m/s), "
          f"R^2 = {r['r2']:.4f}")
    ok = bf["rms"] <= a.rms_factor * a.noise
    print(f"back-fit RMS misfit {1000 * bf['rms']:.4f} mm, noise sd {1000 * a.noise:g} mm "
          f"(limit {a.rms_factor:g} x noise): {'ok' if ok else 'FAIL'}")
    if not ok:
        failures.append("back-fit RMS")

    if failures:
        print("CHECK FAILED: " + "; ".join(failures), file=sys.stderr)
        sys.exit(1)
    print("check passed")


if __name__ == "__main__":
    main()
