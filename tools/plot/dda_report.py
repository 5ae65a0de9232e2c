#!/usr/bin/python3
"""The report of a run: one self-contained HTML page (docs/plots.md).

    dda_report.py RUN_FOLDER|RESULTS.h5 -o DIR

Writes DIR/report.html: the scenario and provenance, the model, the run
(steps, dt, solves per step, energy balance, warnings), the figures of
`dda plot RESULTS.h5` embedded as PNG, and the measurement points' final
and peak values. A run folder is one `dda run` wrote (it holds results.h5).
Any problem is one line on stderr and exit status 2.
"""

import argparse
import io
import os
import sys

import plot_io
from plot_io import fail, write_atomically

plot_io.PROG = "dda_report.py"  # the name its one-line errors start with

try:
    import h5py
    import matplotlib

    matplotlib.use("Agg")
except ImportError as exc:  # pragma: no cover - depends on the machine
    fail(f"needs numpy, h5py and matplotlib ({exc}); run it with /usr/bin/python3")

import report_facts as facts  # noqa: E402
import report_html as page  # noqa: E402
import results_figures as rf  # noqa: E402
from results_data import ResultsError, read_results  # noqa: E402

CAPTIONS = {
    "blocks": "Deformed blocks at the end, coloured by the displacement magnitude.",
    "blocks3d": "Deformed blocks at the end, coloured by the displacement magnitude, seen looking north, looking "
                "west and from above.",
    "sections": "Sections through the middle of the model at the end, coloured by the displacement magnitude.",
    "contacts": "Contacts of the last step: normal and shear forces between block pairs (line width proportional "
                "to the force) and the state of every contact.",
    "histories": "Measurement points: displacement components from the start of the run, and speed.",
    "energy": "Energy ledger: stored energies, and work done and losses (cumulative).",
    "steps": "The run: step length, open-close iterations per step and contacts by state.",
}


def results_path(target):
    if os.path.isdir(target):
        path = os.path.join(target, "results.h5")
        if not os.path.isfile(path):
            fail(f"{target}: holds no results.h5 (give a run folder of dda run, or a results file)")
        return path
    if not os.path.exists(target):
        fail(f"{target}: file not found")
    return target


def png_of(fig):
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=100, bbox_inches="tight")
    return buf.getvalue()


def build(r):
    """The page's HTML."""
    notes, figures = [], []
    for kind in rf.kinds_of(r):
        fig, note = rf.draw(r, kind, rf.FigureOptions())
        caption = CAPTIONS["blocks3d" if kind == "blocks" and r.dim == 3 else kind]
        if kind == "blocks" and r.bolts:
            caption += " Rock bolts: solid while intact, dashed red once broken."
        figures.append(page.figure(png_of(fig), kind, caption))
        rf.close(fig)
        if note:
            notes.append(note)
    name = facts.scenario_name(r)
    title = f"DDA run report: {name}" if name else "DDA run report"
    warnings = facts.warnings(r, notes)
    sections = [
        ("Provenance", page.key_value_table(facts.provenance(r), "provenance")),
        ("Model", page.key_value_table(facts.model(r), "model")),
        ("Run", page.key_value_table(facts.run(r), "run")),
    ]
    balance = facts.energy_balance(r)
    sections.append(("Energy balance", page.key_value_table(balance, "energy") if balance else
                     "<p>The results file keeps no energy record (a 3D file written before the 3D energy "
                     "ledger).</p>"))
    sections.append(("Warnings", "".join(f'<p class="warning">{page.esc(w)}</p>' for w in warnings)
                     if warnings else '<p id="no-warnings">None.</p>'))
    sections.append(("Figures", "".join(figures)))
    header, rows = facts.point_table(r)
    sections.append(("Measurement points", page.data_table(header, rows, "points") if header else
                     '<p id="no-points">The run has no measurement points.</p>'))
    sections.append(("Scenario", f"<pre>{page.esc(r.scenario_text)}</pre>" if r.scenario_text else
                     "<p>The results file holds no scenario text.</p>"))
    return page.page(title, sections)


def main(argv=None):
    p = argparse.ArgumentParser(prog="dda_report.py", description=__doc__.splitlines()[0])
    p.add_argument("target", help="a run folder (with results.h5) or a results file")
    p.add_argument("-o", "--output", required=True, help="folder to write report.html in")
    a = p.parse_args(argv)
    path = results_path(a.target)
    parent = os.path.dirname(os.path.abspath(a.output))
    if not os.path.isdir(parent):
        fail(f"{a.output}: cannot write: the folder {parent} does not exist")
    if os.path.exists(a.output) and not os.path.isdir(a.output):
        fail(f"{a.output}: is a file; give the folder to write report.html in")
    try:
        r = read_results(path, h5py)
    except ResultsError as exc:
        fail(str(exc))
    text = build(r)
    os.makedirs(a.output, exist_ok=True)
    out = os.path.join(a.output, "report.html")

    def write(tmp):
        with open(tmp, "w", encoding="utf-8") as f:
            f.write(text)

    write_atomically(out, write)
    return 0


if __name__ == "__main__":
    sys.exit(main())
