"""The summaries the example's analyses write (analyse.py, analyse_slab.py):
JSON replaced atomically, so scripts/check_readme_numbers.py never reads a
half-written one."""
import json
import os


def write_summary(path, summary):
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        json.dump(summary, f, indent=1)
    os.replace(tmp, path)
