#!/usr/bin/python3
"""Tests scripts/check_readme_numbers.py on a tiny README and outputs written
here: each source kind (JSON, CSV, printed text) with a matching number, then
mismatches, a missing source and a marker without a number, which must all be
reported, one line each, with exit status 1."""
import json
import os
import subprocess
import sys
import tempfile

CHECKER = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts", "check_readme_numbers.py")


def run(readme_text, folder):
    readme = os.path.join(folder, "README.md")
    with open(readme, "w", encoding="utf-8") as f:
        f.write(readme_text)
    p = subprocess.run([sys.executable, CHECKER, readme, os.path.join(folder, "out")],
                       capture_output=True, text=True)
    return p.returncode, p.stdout + p.stderr


def expect(cond, what, output):
    if not cond:
        sys.exit(f"FAILED: {what}\n--- checker output:\n{output}")


with tempfile.TemporaryDirectory() as d:
    out = os.path.join(d, "out")
    os.makedirs(out)
    with open(os.path.join(out, "r.json"), "w") as f:
        json.dump({"uy": {"mp1": -0.004452}, "by_mm": {"0.5": 1.2919}, "segs": [{"phi": 30.00023}],
                   "blocks": 82}, f)
    with open(os.path.join(out, "h.csv"), "w") as f:
        f.write("step,t,ke\n1,0.0,1.0\n2,0.5,12.84\n3,1.0,-20.0\n4,1.5,0.5\n")
    with open(os.path.join(out, "run.log"), "w") as f:
        f.write("results.h5: 10072 steps to t = 5 s\nFS = 1.5663 (double-face)\n")

    good = """# Example
Settles 4.45 mm<!-- check: r.json uy.mp1 scale=-1000 --> at mp1, 1.29 B<!-- check: r.json by_mm[0.5] -->.
| seg | 30.0002°<!-- check: r.json segs.0.phi --> | +0.0002°<!-- check: r.json segs.0.phi offset=-30 --> |
82 blocks<!-- check: r.json blocks -->; 10 072 steps<!-- check: run.log '(\\d+) steps to t' -->;
FS = 1.5663<!-- check: run.log 'FS = ([\\d.]+)' -->; last 0.5<!-- check: h.csv ke -->, max 12.8<!-- check: h.csv ke row=max -->,
min −20<!-- check: h.csv ke row=min -->, 20<!-- check: h.csv ke row=absmax abs -->, mean −1.4<!-- check: h.csv ke row=mean -->,
at 0.5 s 13<!-- check: h.csv ke at=t:0.5 -->. E = 15.3 GPa is an input and not marked.
"""
    code, output = run(good, d)
    expect(code == 0, "matching numbers pass", output)
    expect("13 marked numbers, 0 problem(s)" in output, "every marker counted", output)

    # Printed precision: 4.45 needs 4.445..4.455; 4.452 rounds to 4.45, not 4.4 or 4.46.
    bad = """Settles 4.46 mm<!-- check: r.json uy.mp1 scale=-1000 -->.
Close but not the printed digits: 4.4 mm<!-- check: r.json uy.mp1 scale=-1000 -->.
Missing: 3 mm<!-- check: nothing.json a -->, no key 1<!-- check: r.json uy.mp9 -->.
No number here<!-- check: r.json blocks -->, no column 2<!-- check: h.csv vx -->.
"""
    code, output = run(bad, d)
    lines = [line for line in output.splitlines() if line.startswith(("MISMATCH", "ERROR"))]
    expect(code == 1, "mismatches give exit status 1", output)
    expect(len(lines) == 6, "one line per problem", output)
    readme = os.path.join(d, "README.md")
    expect(lines[0].startswith(f"MISMATCH {readme}:1: printed 4.46, produced 4.452")
           and "source r.json uy.mp1 scale=-1000" in lines[0], "the mismatch line names all", output)
    expect(lines[1].startswith(f"MISMATCH {readme}:2: printed 4.4,"), "fewer digits still compared", output)
    expect("missing file" in lines[2] and ":3:" in lines[2], "a missing source is reported", output)
    expect("no key 'mp9'" in lines[3], "a missing key is reported", output)
    expect("no number before the marker" in lines[4], "a marker without a number is reported", output)
    expect("no column 'vx'" in lines[5], "a missing column is reported", output)

    code, output = run("# no markers\n", d)
    expect(code == 1 and "no check markers" in output, "a README without markers fails", output)
print("check_readme_numbers: ok")
