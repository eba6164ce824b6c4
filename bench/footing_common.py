"""Helpers shared by the footing studies in bench/ (load curves, gnuplot quoting)."""
import csv


def read_curve(path):
    """S/B and q (kPa) columns of a load_settlement CSV or a lab curve (comment lines start with #)."""
    with open(path) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    return [float(r["S_over_B"]) for r in rows], [float(r["q_kPa"]) for r in rows]


def value_at(xs, ys, x):
    """Linear interpolation of ys at x; NaN outside the curve."""
    for i in range(1, len(xs)):
        if xs[i - 1] <= x <= xs[i]:
            t = (x - xs[i - 1]) / (xs[i] - xs[i - 1]) if xs[i] > xs[i - 1] else 0.0
            return ys[i - 1] + t * (ys[i] - ys[i - 1])
    return float("nan")


def gp_quoted(text):
    """A gnuplot single-quoted string: names and paths never become script."""
    return "'" + str(text).replace("'", "''").replace("\n", " ") + "'"
