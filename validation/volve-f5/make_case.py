#!/usr/bin/env python3
"""Writes the drillflex case of Volve 15/9-F-5's 8-1/2 in section from the field folder (Equinor's open
Volve data, ../shared/field/volve-15-9-F-5: its README gives the sources, licence and caveats). The data
stays outside the repository: this script reads it where it lies and writes the case where asked.

    make_case.py FIELD_DIR OUT.yaml

What is assumed (the field folder does not give it), docs/validation.md "Volve 15/9-F-5":
  * stabilizer blades 8-7/16 in (near full gauge; the table gives the bodies' ODs only);
  * the drill pipe's and HWDP's tool joints 6-5/8 in OD, 3-1/4 in ID, one a 9.5 m joint;
  * the mud 1450 kg/m3 (1.38 s.g. at the shoe, 1.44-1.46 below);
  * the riser (0-146 m, ID 486.8 mm), the 10-3/4 in casing (146-604 m) and the 9-5/8 in casing
    (604-2921 m, ID 216.8 mm) cased; open 8-1/2 in hole below;
  * a station at MD 0 above the survey's first, and one at 3800 m continuing its last (the last
    reading is at 3791 m, the survey ends at 3790 m).
"""
import csv
import sys
from pathlib import Path


def rows(path):
    with open(path, newline="") as f:
        reader = csv.reader(f)
        header = next(reader)
        next(reader)  # units
        return [dict(zip(header, r)) for r in reader if r]


def main():
    field, out = Path(sys.argv[1]), Path(sys.argv[2])
    survey = rows(field / "survey.csv")
    stations = [(0.0, 0.0, 0.0)] + [(float(s["md"]), float(s["inclination"]), float(s["azimuth"])) for s in survey]
    last = stations[-1]
    stations.append((3800.0, last[1], last[2]))
    survey_yaml = "\n".join(f"    - [{md:g}, {inc:g}, {azi:g}]" for md, inc, azi in stations)
    out.write_text(f"""# Volve 15/9-F-5, 8-1/2 in section: written by validation/volve-f5/make_case.py from {field}
# (Equinor's open Volve data; see that folder's README for the sources, licence and caveats).
name: volve-15-9-F-5
units: SI
well:
  survey:
{survey_yaml}
  hole:
    - {{to: 146, diameter: 0.4868, cased: true}}
    - {{to: 604, diameter: 0.245364, cased: true}}
    - {{to: 2921, diameter: 0.216789, cased: true}}
    - {{diameter: 0.2159}}
  bit_md: 3791
fluid: {{density: 1450}}
string:
  - {{type: bit, od: 8.5 in, length: 0.24}}
  - {{type: stabilizer, name: near-bit stabilizer, od: 7.625 in, id: 3 in, length: 0.67, blade_od: 8.4375 in}}
  - {{type: collar, name: rotary steerable tool, od: 6.9375 in, id: 3 in, length: 6.9}}
  - {{type: sub, name: float sub, od: 6.75 in, id: 3 in, length: 1.17}}
  - {{type: stabilizer, od: 6.875 in, id: 2.8125 in, length: 1.93, blade_od: 8.4375 in}}
  - {{type: lwd, od: 6.75 in, id: 2 in, length: 8.03}}
  - {{type: mwd, od: 6.75 in, id: 5.125 in, length: 8.47}}
  - {{type: lwd, od: 6.75 in, id: 4.875 in, length: 7.56}}
  - {{type: lwd, name: PWD, od: 6.75 in, id: 2.8125 in, length: 10.72}}
  - {{type: hwdp, od: 5 in, id: 3 in, length: 9.135, count: 2, joint_od: 6.625 in, joint_id: 3.25 in}}
  - {{type: jar, od: 6.5 in, id: 2.75 in, length: 10.08}}
  - {{type: hwdp, od: 5 in, id: 3 in, length: 9.463, count: 3, joint_od: 6.625 in, joint_id: 3.25 in}}
  - {{type: pipe, od: 5 in, id: 4.276 in, length: 9.5, count: 40, joint_od: 6.625 in, joint_id: 3.25 in}}
model:
  contact: {{friction: 0.25}}
operation: {{wob: 100 kN, torque_on_bit: 3 kN*m, rpm: 130}}
analyses:
  roadmap: {{from: 2830, step: 120, friction: [0.15, 0.25, 0.35]}}
""")


if __name__ == "__main__":
    main()
