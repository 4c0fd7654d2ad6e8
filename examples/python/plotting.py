"""The examples' plots: matplotlib when it is installed, else nothing (the table is the result)."""
from __future__ import annotations

from typing import Optional, Sequence, Tuple


def plot_panels(path: str, x: Sequence[float], xlabel: str, panels: Sequence[Tuple[Sequence[float], str]],
                title: str) -> Optional[str]:
    """One panel per (y, ylabel) against ``x``, written to ``path``; the path, or None without matplotlib."""
    try:
        import matplotlib
    except ImportError:
        print("matplotlib is not installed: the plot is skipped")
        return None
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    figure, axes = plt.subplots(len(panels), 1, sharex=True, figsize=(6, 2.5 * len(panels)))
    for axis, (y, ylabel) in zip(axes if len(panels) > 1 else [axes], panels):
        axis.plot(x, y, "o-")
        axis.set_ylabel(ylabel)
        axis.grid(True)
    axes_list = axes if len(panels) > 1 else [axes]
    axes_list[-1].set_xlabel(xlabel)
    axes_list[0].set_title(title)
    figure.tight_layout()
    figure.savefig(path, dpi=120)
    plt.close(figure)
    print(f"plot written to {path}")
    return path
