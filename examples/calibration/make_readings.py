#!/usr/bin/env python3
"""Writes readings.csv, the example's synthetic rig readings: each reading's hook load and torque as
drillflex's soft string models them (`drillflex roadmap case.yaml --model soft --readings template`, at
an open-hole friction of 0.32, the case's cased 0.18 and its TOB/WOB ratio as the bit coefficient), plus
a hook-load offset of 80 klbf and 1 % Gaussian noise (a fixed seed).

    make_readings.py DRILLFLEX_EXE
"""
import csv
import random
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
ACTIVITIES = ("drilling", "rotating", "pick_up", "slack_off")


def main():
    exe = sys.argv[1]
    rows = []
    for i in range(48):
        md = 3000.0 + 1900.0 * i / 47
        activity = ACTIVITIES[i % 4]
        wob = 10.0 + 10.0 * ((i * 7) % 11) / 10.0 if activity == "drilling" else 0.0
        rpm = 80.0 if activity in ("drilling", "rotating") else 0.0
        rows.append((round(md, 1), activity, wob, rpm))
    with tempfile.TemporaryDirectory() as work:
        template = Path(work) / "template.csv"
        with open(template, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["bit_md", "activity", "hook_load", "surface_torque", "wob", "rpm"])
            w.writerow(["ft", "-", "klbf", "ft*lbf", "klbf", "rpm"])
            for md, activity, wob, rpm in rows:
                w.writerow([md, activity, 0, "" if rpm == 0 else 0, wob, rpm])
        out = Path(work) / "out"
        subprocess.run([exe, "roadmap", str(HERE / "case.yaml"), "--model", "soft", "--friction", "0.32",
                        "--readings", str(template), "-o", str(out), "--no-report"], check=True, capture_output=True)
        with open(out / "readings.csv", newline="") as f:
            reader = csv.DictReader(f)
            next(reader)  # units
            modelled = list(reader)
    random.seed(7)
    with open(HERE / "readings.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["bit_md", "activity", "hook_load", "surface_torque", "wob", "rpm"])
        w.writerow(["ft", "-", "klbf", "ft*lbf", "klbf", "rpm"])
        for (md, activity, wob, rpm), m in zip(rows, modelled):
            hook = (float(m["modelled_hook_load"]) / 1000.0 + 80.0) * (1.0 + random.gauss(0.0, 0.01))
            torque = "" if rpm == 0 else f"{float(m['modelled_surface_torque']) * (1.0 + random.gauss(0.0, 0.01)):.0f}"
            w.writerow([md, activity, f"{hook:.2f}", torque, wob, rpm])


if __name__ == "__main__":
    main()
