"""What every mssph figure shares: reading a file's provenance, stamping it on the figure, saving
PNG and SVG. Figures read only mssph's HDF5 files, so they can be restyled and redrawn at will."""
import os

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
