"""Where to put the near-bit stabilizer: the bit's side force and build tendency against the
stabilizer's distance from the bit, on the bundled example (examples/rotary-bha-build/case.yaml).

The bundled BHA has its near-bit stabilizer right above the bit (string[1]) and a 10 ft short collar
above it (string[2]). Each position of the study swaps the two: a pony collar of length L between the
bit and the stabilizer (string[1]) and the stabilizer above it (string[2]), set with
Case.with_values. The blades then sit 1 ft (the bit) + L + 2.5 ft from the bit, and the BHA above
the stabilizer moves down by 10 ft - L (the string is that much shorter).

    PYTHONPATH=build/python /usr/bin/python3 examples/python/stabilizer_placement.py [--plot FILE]

prints the table; with matplotlib installed it also plots it (stabilizer_placement.png by default).
"""
from __future__ import annotations

import argparse
from pathlib import Path

import drillflex
from plotting import plot_panels

EXAMPLE = Path(__file__).resolve().parents[1] / "rotary-bha-build" / "case.yaml"
STABILIZER = "{type: stabilizer, name: near-bit stabilizer, od: 6.75, id: 2.8125, length: 5, blade_od: 8.4375, blade_length: 1.5}"
PONY_LENGTHS_FT = [2.0, 4.0, 6.0, 8.0, 10.0]


def placements(case: drillflex.Case):
    """(blade distance from the bit in ft, case) for the bundled placement and each pony collar."""
    yield 1.0 + 2.5, case
    for length in PONY_LENGTHS_FT:
        pony = f"{{type: collar, name: pony collar, od: 6.75, id: 2.8125, length: {length}}}"
        yield 1.0 + length + 2.5, case.with_values({"string[1]": pony, "string[2]": STABILIZER})


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--plot", default="stabilizer_placement.png", help="where to write the plot")
    arguments = parser.parse_args()

    case = drillflex.Case.from_file(str(EXAMPLE))
    lbf = lambda newton: drillflex.units.convert(newton, "N", "lbf")  # noqa: E731
    rows = []
    print(f"{'blades from bit':>15}  {'side force':>10}  {'build force':>11}  {'walk force':>10}  tendency")
    print(f"{'ft':>15}  {'lbf':>10}  {'lbf':>11}  {'lbf':>10}")
    for distance, placed in placements(case):
        bit = drillflex.static(placed).bit
        rows.append((distance, lbf(bit.side_force), lbf(bit.build_force)))
        print(f"{distance:15.1f}  {lbf(bit.side_force):10.1f}  {lbf(bit.build_force):11.1f}  "
              f"{lbf(bit.walk_force):10.1f}  {bit.inclination_tendency}, {bit.azimuth_tendency}")
    distances, side, build = zip(*rows)
    plot_panels(arguments.plot, distances, "near-bit stabilizer blades from the bit (ft)",
                [(side, "bit side force (lbf)"), (build, "build force (lbf, > 0 builds)")],
                "Near-bit stabilizer placement, bundled example")


if __name__ == "__main__":
    main()
