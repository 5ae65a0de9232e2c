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
