"""What every mssph figure shares: reading a file's provenance, stamping it on the figure, saving
PNG and SVG. Figures read only mssph's HDF5 files, so they can be restyled and redrawn at will."""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (the backend must be chosen first)


def text_attribute(h5, name, default="?"):
    value = h5.attrs.get(name, default)
    return value.decode() if isinstance(value, bytes) else str(value)


def provenance(h5):
    """Backend, device, commit and date of an mssph HDF5 file (a run log or a figure's timings)."""
    return {
        "backend": text_attribute(h5, "backend"),
        "device": text_attribute(h5, "device"),
        "precision": text_attribute(h5, "precision"),
        "commit": text_attribute(h5, "git_commit"),
        "date": text_attribute(h5, "start_time"),
    }


def stamp(figure, context, extra=""):
    """Writes where the numbers came from along the figure's bottom edge."""
    line = (f"mssph {context['commit']} | {context['backend']} ({context['precision']}) on {context['device']}"
            f" | {context['date']}")
    if extra:
        line += " | " + extra
    figure.text(0.01, 0.005, line, fontsize=6, color="0.35", ha="left", va="bottom")


def save(figure, folder, name):
    """Saves folder/name.png and folder/name.svg and returns their paths."""
    os.makedirs(folder, exist_ok=True)
    paths = [os.path.join(folder, name + ext) for ext in (".png", ".svg")]
    for path in paths:
        figure.savefig(path, dpi=150)
    plt.close(figure)
    return paths


def finish_checks(report, folder, name, label, written):
    """Writes the checks' report to folder/name.json (with its overall "passed"), prints how many
    passed and the names of the files drawn (mssph moves them from its staging folder into --out
    and says so), and exits 1 when a check failed, else 0."""
    checks = report["checks"]
    report["passed"] = all(c["passed"] for c in checks)
    checks_path = os.path.join(folder, name + ".json")
    with open(checks_path, "w") as out:
        json.dump(report, out, indent=2)
    failed = sum(not c["passed"] for c in checks)
    names = [os.path.basename(path) for path in written + [checks_path]]
    print(f"{label}: {len(checks) - failed} passed, {failed} failed; drew {', '.join(names)}")
    sys.exit(1 if failed else 0)
