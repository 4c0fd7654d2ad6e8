"""Plain-SVG line plots for the validation figures (scripts/*-figure); no plotting library."""
import csv


def read_csv(path):
    """The columns of a transient.csv by name, as floats."""
    with open(path) as f:
        rows = list(csv.DictReader(f))[1:]  # the second line holds the units
    return {name: [float(r[name]) for r in rows] for name in rows[0]}


class Panel:
    """A rectangle [x0, x1] x [y0, y1] (pixels) showing data [xmin, xmax] x [ymin, ymax]."""

    def __init__(self, x0, y0, x1, y1, xmin, xmax, ymin, ymax):
        self.box = (x0, y0, x1, y1)
        self.range = (xmin, xmax, ymin, ymax)

    def px(self, x):
        x0, _, x1, _ = self.box
        xmin, xmax, _, _ = self.range
        return x0 + (x1 - x0) * (x - xmin) / (xmax - xmin)

    def py(self, y):
        _, y0, _, y1 = self.box
        _, _, ymin, ymax = self.range
        return y1 - (y1 - y0) * (y - ymin) / (ymax - ymin)

    def axes(self, xticks, yticks, xlabel, ylabel, fmt=lambda v: f"{v:g}"):
        x0, y0, x1, y1 = self.box
        out = [f'<rect x="{x0}" y="{y0}" width="{x1 - x0}" height="{y1 - y0}" fill="none" stroke="#999"/>']
        for v in yticks:
            out.append(f'<line x1="{x0}" y1="{self.py(v):.1f}" x2="{x1}" y2="{self.py(v):.1f}" stroke="#eee"/>')
            out.append(f'<text x="{x0 - 6}" y="{self.py(v) + 4:.1f}" text-anchor="end">{fmt(v)}</text>')
        for v in xticks:
            out.append(f'<text x="{self.px(v):.1f}" y="{y1 + 16}" text-anchor="middle">{fmt(v)}</text>')
        out.append(f'<text x="{(x0 + x1) / 2}" y="{y1 + 34}" text-anchor="middle">{xlabel}</text>')
        out.append(f'<text x="{x0}" y="{y0 - 8}">{ylabel}</text>')
        return out

    def line(self, xs, ys, colour, width=1.0, dash=None):
        points = " ".join(f"{self.px(x):.1f},{self.py(y):.1f}" for x, y in zip(xs, ys))
        style = f' stroke-dasharray="{dash}"' if dash else ""
        return f'<polyline points="{points}" fill="none" stroke="{colour}" stroke-width="{width}"{style}/>'

    def label(self, x, y, text, colour="black", anchor="start", dx=0, dy=0):
        """Text at data point (x, y), shifted by (dx, dy) pixels."""
        return (f'<text x="{self.px(x) + dx:.1f}" y="{self.py(y) + dy:.1f}" text-anchor="{anchor}" '
                f'fill="{colour}">{text}</text>')


def svg(width, height, title, body):
    head = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
            f'viewBox="0 0 {width} {height}" font-family="sans-serif" font-size="12">',
            '<rect width="100%" height="100%" fill="white"/>',
            f'<text x="{width / 2}" y="22" text-anchor="middle" font-size="15">{title}</text>']
    return "\n".join(head + body + ["</svg>"]) + "\n"
