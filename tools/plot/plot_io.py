"""The plot scripts' contact with the outside: one-line failures and
pictures written atomically."""

import errno
import os
import sys

PROG = "dda_plot.py"


def fail(message):
    """One sentence on stderr, exit status 2 (the C++ caller shows it)."""
    message = message.rstrip()
    if not message.endswith("."):
        message += "."
    print(f"{PROG}: {message}", file=sys.stderr)
    sys.exit(2)


def sync_folder(folder):
    fd = os.open(folder, os.O_RDONLY | os.O_DIRECTORY)
    try:
        os.fsync(fd)
    except OSError as exc:
        if exc.errno != errno.EINVAL:  # a filesystem that cannot sync folders
            raise
    finally:
        os.close(fd)


def write_atomically(out, write):
    """Calls write(temporary_path), then moves the file to `out`: on the disk
    before the rename, and the rename itself after it, as the C++ writer does
    (common/src/atomic_file.cpp), so a crash never leaves `out` empty."""
    folder, base = os.path.split(os.path.abspath(out))
    ext = os.path.splitext(base)[1].lower()
    tmp = os.path.join(folder, f".{base}.tmp-{os.getpid()}{ext}")
    try:
        write(tmp)
        with open(tmp, "rb") as f:
            os.fsync(f.fileno())
        os.replace(tmp, out)
        sync_folder(folder)
    except OSError as exc:
        fail(f"{out}: cannot write: {exc.strerror or exc}")
    finally:
        if os.path.exists(tmp):
            os.remove(tmp)


def save_atomically(fig, out):
    ext = os.path.splitext(out)[1].lower()
    # The tight box leaves out a 3D axes' z label unless told about it.
    labels = [ax.zaxis.label for ax in fig.axes if hasattr(ax, "zaxis")]
    write_atomically(out, lambda tmp: fig.savefig(tmp, format=ext[1:], dpi=150, bbox_inches="tight",
                                                  bbox_extra_artists=fig.get_default_bbox_extra_artists() + labels))


def origin_of(f, dims):
    """The local origin of an open dda HDF5 file (docs/formats.md): its
    positions are the user's coordinates less it; zeros when it has none."""
    return [float(f.attrs.get(k, 0.0)) for k in ("origin_x", "origin_y", "origin_z")[:dims]]


def label_user_coordinates(axes, origin):
    """Figures are drawn in the file's local coordinates (full precision, a
    model far from the origin would be rounded to the spacing of doubles
    there); the tick labels of each axis (matplotlib x, y[, z] axes, in
    order) give the user's coordinates, local + origin, to 15 digits."""
    from matplotlib.ticker import FuncFormatter
    for k, (axis, o) in enumerate(zip(axes, origin)):
        if o != 0:
            axis.set_major_formatter(FuncFormatter(lambda v, pos, o=o: "%.15g" % (v + o)))
            if k == 0 and len(axes) == 2:  # long numbers side by side would overlap on a map
                axis.set_tick_params(labelrotation=30)
