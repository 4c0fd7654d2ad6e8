"""The first lateral critical rotary speed against the weight on bit, on the bundled example
(examples/rotary-bha-build/case.yaml): the modes about each static equilibrium and the first lateral
mode's frequency at 1× rotation (the critical RPM the command line's modes summary gives).

    PYTHONPATH=build/python /usr/bin/python3 examples/python/critical_speed.py [--plot FILE]

prints the table; with matplotlib installed it also plots it (critical_speed.png by default).
"""
from __future__ import annotations

import argparse
from pathlib import Path

import drillflex
from plotting import plot_panels

EXAMPLE = Path(__file__).resolve().parents[1] / "rotary-bha-build" / "case.yaml"
WOB_KLBF = [5.0, 15.0, 25.0, 35.0, 45.0]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--plot", default="critical_speed.png", help="where to write the plot")
    arguments = parser.parse_args()

    case = drillflex.Case.from_file(str(EXAMPLE))
    # Only the lateral modes: the study needs the first of them.
    case = case.with_values({"analyses.modes": "{count: 4, kind: lateral}"})
    print(f"{'WOB':>6}  {'first lateral':>13}  {'critical speed':>14}")
    print(f"{'klbf':>6}  {'Hz':>13}  {'rpm':>14}")
    wobs, critical = [], []
    for wob in WOB_KLBF:
        modes = drillflex.modes(case.with_values({"operation.wob": f"{wob} klbf"}))
        if modes.first_lateral is None:
            print(f"{wob:6.0f}  no lateral mode found")
            continue
        rpm = drillflex.units.convert(modes.critical_speed, "rad/s", "rpm")
        wobs.append(wob)
        critical.append(rpm)
        print(f"{wob:6.0f}  {modes.first_frequency_hz:13.4f}  {rpm:14.1f}")
    plot_panels(arguments.plot, wobs, "weight on bit (klbf)", [(critical, "first lateral critical speed (rpm)")],
                "Critical speed against WOB, bundled example")


if __name__ == "__main__":
    main()
