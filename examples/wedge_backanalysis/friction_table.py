"""Reading a `dda sliding3d --friction-table` CSV, shared by the example's
check and plot scripts."""


def read_friction_table(path):
    """(t, phi) rows (the first angle), comments (#), blank lines and a header skipped."""
    rows = []
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if not line:
                continue
            cells = [c for c in line.replace(";", ",").replace("\t", ",").replace(" ", ",").split(",") if c]
            try:
                rows.append((float(cells[0]), float(cells[1])))
            except ValueError:
                continue  # the header
    return rows
