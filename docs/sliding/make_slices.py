#!/usr/bin/env python3
"""Pictures of docs/sliding-unknown.md: which loads stick for every admissible distribution, depend on the
distribution, or slide for every one, on a slice of load space, for the four-legged table and the dinner
plate of docs/theory-sliding.md §6. Every cell is the certified answer of wrenchkit.limit_surface at the cell's
centre (hybrid mode, certificate checked by the independent checker); nothing is interpolated.

    PYTHONPATH=build/python /usr/bin/python3 docs/sliding/make_slices.py   (./build.sh gallery runs it)
"""
import os
import sys
from fractions import Fraction

import wrenchkit

TABLE = {"name": "four-legged table", "support": {"mu": 1, "weight": 1, "pressure_center": [0, 0], "points": [
    {"at": [1, 1]}, {"at": [-1, 1]}, {"at": [-1, -1]}, {"at": [1, -1]}]}}
RIM = [(1, 0), ("3/5", "4/5"), (0, 1), ("-3/5", "4/5"), (-1, 0), ("-3/5", "-4/5"), (0, -1), ("3/5", "-4/5"), (0, 0)]
PLATE = {"name": "dinner plate", "body": {"com": [0, 0]},
         "support": {"mu": 1, "weight": 1, "points": [{"at": [x, y]} for x, y in RIM]}}
COLOURS = {"sticks": "#4c9a2a", "depends": "#e0b030", "impending": "#7d3c98", "slides": "#c0392b",
           "undecided": "#888888"}


def slice_svg(scene, title, xlabel, ylabel, load_of, extent, n, path):
    """A grid of n × n cells over [-extent, extent]², each coloured by the certified answer at its centre."""
    size, margin = 360, 50
    cell = size / n
    out = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif" font-size="12">'
           % (size + 2 * margin + 200, size + 2 * margin),
           '<rect width="100%" height="100%" fill="white"/>',
           '<text x="%d" y="20" font-size="13">%s</text>' % (10, title)]
    counts = {}
    for i in range(n):
        for j in range(n):
            a = Fraction(-extent) + Fraction(2 * extent) * Fraction(2 * i + 1, 2 * n)
            b = Fraction(-extent) + Fraction(2 * extent) * Fraction(2 * j + 1, 2 * n)
            r = wrenchkit.limit_surface(scene, load=load_of(a, b))
            m = r["motion"]
            counts[m] = counts.get(m, 0) + 1
            out.append('<rect x="%.2f" y="%.2f" width="%.2f" height="%.2f" fill="%s"/>'
                       % (margin + i * cell, margin + (n - 1 - j) * cell, cell + 0.3, cell + 0.3, COLOURS[m]))
    out.append('<rect x="%d" y="%d" width="%d" height="%d" fill="none" stroke="black"/>' % (margin, margin, size, size))
    out.append('<text x="%d" y="%d" text-anchor="middle">%s (from %s to %s)</text>'
               % (margin + size / 2, margin + size + 20, xlabel, -extent, extent))
    out.append('<text x="15" y="%d" transform="rotate(-90 15 %d)" text-anchor="middle">%s (from %s to %s)</text>'
               % (margin + size / 2, margin + size / 2, ylabel, -extent, extent))
    y = margin
    for k, words in (("sticks", "sticks for every distribution"), ("depends", "depends (sticks for some)"),
                     ("impending", "impending (on every limit surface)"), ("slides", "slides for every distribution"),
                     ("undecided", "undecided (near a boundary)")):
        out.append('<rect x="%d" y="%d" width="12" height="12" fill="%s"/><text x="%d" y="%d">%s</text>'
                   % (margin + size + 15, y, COLOURS[k], margin + size + 32, y + 11, words))
        y += 22
    out.append("</svg>")
    open(path, "w").write("\n".join(out) + "\n")
    return counts


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 40
    t = slice_svg(TABLE, "Four-legged table, legs (±1, ±1), μ = W = 1: loads (fx, 0, m)", "fx", "m",
                  lambda a, b: (a, 0, b), 2, n, os.path.join(here, "table_fx_m.svg"))
    p = slice_svg(PLATE, "Dinner plate, rim radius 1 and centre, μ = W = 1: loads (fx, 0, m)", "fx", "m",
                  lambda a, b: (a, 0, b), Fraction(3, 2), n, os.path.join(here, "plate_fx_m.svg"))
    print("table", t, "plate", p)


if __name__ == "__main__":
    main()
