#!/usr/bin/python3
"""report.html and string.vtp of a drillflex run, checked in headless Chromium (CTest label `report`).

    report_test.py DRILLFLEX CASE OUTDIR [--sections static,view3d,...] [--analysis run] [--json results.json]
                   [--options "MORE OPTIONS"]

Runs `drillflex ANALYSIS CASE -o OUTDIR/results`, then:
  * renders report.html in headless Chromium (Debian's `chromium`): the page must finish with
    <body data-report-status="ok"> (report.js sets it; any script error sets "error"), every
    expected section must be there and every plot in it must hold points (data-points > 0);
    Chromium's console must show no error from the page;
  * compares the numbers the page shows (elements with data-key) with results.json, to the
    figures shown;
  * saves a PNG of each section (report.html?only=SECTION) under OUTDIR/screenshots;
  * reads string.vtp with an XML parser: as many points as static.nodes, its point data equal to
    static.csv converted to SI.
Only Python's standard library: it runs on Debian's /usr/bin/python3 as it comes.
"""
import argparse
import csv
import html.parser
import json
import math
import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET

# Field units to SI (docs/case-format.md "Results"): column of static.csv -> factor.
FIELD_TO_SI = {
    "s": 0.3048, "md": 0.3048, "lateral_offset": 0.0254, "axial_force": 4.4482216152605,
    "torque": 1.3558179483314004, "shear_force": 4.4482216152605, "bending_moment": 1.3558179483314004,
    "bending_stress": 6894.757293168361, "von_mises_stress": 6894.757293168361, "hole_offset": 0.0254,
    "offset_high_side_angle": math.pi / 180.0, "clearance": 0.0254, "hole_diameter": 0.0254,
}
# SI output: lengths, forces and stresses are SI already; the CSV's angles are in degrees.
SI_TO_SI = {k: 1.0 for k in FIELD_TO_SI}
SI_TO_SI["offset_high_side_angle"] = math.pi / 180.0

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message)
    return condition


def chromium():
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    sys.exit("report_test: no Chromium on PATH (scripts/install-deps installs Debian's chromium)")


def browse(url, extra):
    """Chromium headless on url with extra flags; returns (stdout, stderr)."""
    command = [chromium(), "--headless", "--no-sandbox", "--disable-dev-shm-usage", "--use-angle=swiftshader",
               "--enable-unsafe-swiftshader", "--virtual-time-budget=5000", "--enable-logging=stderr", "--v=0",
               "--user-data-dir=" + os.path.join(args.outdir, "chromium-profile")] + extra + [url]
    done = subprocess.run(command, capture_output=True, text=True, timeout=180)
    return done.stdout, done.stderr


class Dom(html.parser.HTMLParser):
    """The rendered page's body attributes, sections, plots and shown values."""

    def __init__(self):
        super().__init__()
        self.body = {}
        self.sections = []
        self.plots = []      # (section id, data-points)
        self.values = []     # [data-key, text]
        self._section = None
        self._value = None

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "body":
            self.body = a
        if tag in ("section", "header") and "report-section" in a.get("class", ""):
            self._section = a.get("id")
            self.sections.append(a.get("id"))
        if tag == "figure" and "plot" in a.get("class", ""):
            self.plots.append((self._section, int(a.get("data-points", "0"))))
        if tag == "span" and "data-key" in a:
            self._value = [a["data-key"], ""]
            self.values.append(self._value)

    def handle_data(self, data):
        if self._value is not None:
            self._value[1] += data

    def handle_endtag(self, tag):
        if tag == "span":
            self._value = None


def lookup(results, key):
    """A value of results.json by the report's data-key (a path; a few are reductions)."""
    static = results.get("static", {})
    if key == "static.contacts.max_normal_force":
        return max(c["normal_force"] for c in static["contacts"])
    if key == "static.nodes.max_von_mises_stress":
        return max(n["von_mises_stress"] for n in static["nodes"])
    if key == "modes.first_frequency_hz":  # the lowest mode that is a vibration (not rigid, not ω² < 0)
        return next(m["frequency_hz"] for m in results["modes"]
                    if not m["rigid_body"] and not m["negative_stiffness"] and not m["near_zero"])
    if key == "vibration.critical_rpm.0":
        return min(results["vibration"]["critical_rpm"])
    node = results
    for part in key.split("."):
        node = node[int(part)] if isinstance(node, list) else node[part]
    return node


def shown_number(text):
    return float(text.strip().split(" ")[0].replace(",", ""))


def check_vtk(outdir, results, system):
    tree = ET.parse(os.path.join(outdir, "string.vtp"))  # raises on malformed XML
    root = tree.getroot()
    check(root.tag == "VTKFile" and root.get("type") == "PolyData", "string.vtp is not VTK XML PolyData")
    piece = root.find("PolyData/Piece")
    nodes = results["static"]["nodes"]
    check(int(piece.get("NumberOfPoints")) == len(nodes),
          f"string.vtp has {piece.get('NumberOfPoints')} points, static.nodes {len(nodes)}")
    arrays = {a.get("Name"): [float(v) for v in a.text.split()] for a in piece.findall("PointData/DataArray")}
    with open(os.path.join(outdir, "static.csv")) as f:
        rows = list(csv.DictReader(f))[1:]  # the second line holds the units
    check(len(rows) == len(nodes), "static.csv and static.nodes differ in length")
    factors = FIELD_TO_SI if system == "field" else SI_TO_SI
    compared = 0
    for column, factor in factors.items():
        if column not in rows[0]:
            continue
        if not check(column in arrays, f"static.csv's column {column} is not in string.vtp"):
            continue
        for i, row in enumerate(rows):
            expected = float(row[column]) * factor
            got = arrays[column][i]
            if not check(abs(got - expected) <= 1e-8 * max(1.0, abs(expected)),
                         f"string.vtp {column}[{i}] = {got}, static.csv in SI {expected}"):
                break
        compared += 1
    check(compared >= 9, f"only {compared} static.csv columns compared with string.vtp")
    print(f"string.vtp: {len(nodes)} points, {compared} columns equal to static.csv in SI")


def main():
    os.makedirs(args.outdir, exist_ok=True)
    results_dir = os.path.join(args.outdir, "results")
    shutil.rmtree(results_dir, ignore_errors=True)
    run = subprocess.run([args.drillflex, args.analysis, args.case, "-o", results_dir] + args.options.split(),
                         capture_output=True, text=True)
    check(run.returncode == args.exit, f"drillflex {args.analysis} exited {run.returncode} (expected {args.exit}): "
                                       f"{run.stderr}")
    report = os.path.join(results_dir, "report.html")
    check(os.path.exists(report), "no report.html")
    size = os.path.getsize(report)
    print(f"report.html: {size / 1e6:.2f} MB")
    check(size < 3e6, f"report.html is {size / 1e6:.2f} MB (limit 3 MB)")
    with open(report, encoding="utf-8") as f:
        page = f.read()
    # Chart.js and three.js mention addresses in comments and strings; no element may load one.
    check("<link " not in page and "<script src" not in page and "<img src" not in page,
          "report.html refers to a file or address beside it")
    with open(os.path.join(results_dir, args.json)) as f:
        results = json.load(f)

    url = "file://" + os.path.abspath(report)
    dom_text, log = browse(url, ["--dump-dom"])
    dom = Dom()
    dom.feed(dom_text)
    check(dom.body.get("data-report-status") == "ok",
          f"the page did not finish drawing: status {dom.body.get('data-report-status')!r}, "
          f"errors {dom.body.get('data-report-errors')!r}")
    console_errors = [line for line in log.splitlines() if "CONSOLE" in line and ("Error" in line or "error" in line)]
    check(not console_errors, "console errors: " + " | ".join(console_errors))
    for section in args.sections:
        check(section in dom.sections, f"section {section!r} missing (found {dom.sections})")
    for section, points in dom.plots:
        check(points > 0, f"an empty plot in section {section!r}")
    print(f"sections {dom.sections}; {len(dom.plots)} plots, points {sum(p for _, p in dom.plots)}")
    check(len(dom.values) >= len(args.keys), f"{len(dom.values)} shown values, expected at least {len(args.keys)}")
    shown_keys = {key for key, _ in dom.values}
    for key in args.keys:
        check(key in shown_keys, f"the report does not show {key}")
    for key, text in dom.values:
        expected = lookup(results, key)
        got = shown_number(text)
        # Shown to 5 significant figures (6 for the buckling multiplier).
        check(abs(got - expected) <= 6e-5 * abs(expected) + 1e-12,
              f"{key}: the report shows {text!r}, results.json holds {expected}")
        print(f"  {key}: shown {text!r}, results.json {expected:.8g}")

    shots = os.path.join(args.outdir, "screenshots")
    os.makedirs(shots, exist_ok=True)
    for section in args.sections:
        png = os.path.join(shots, f"{section}.png")
        if os.path.exists(png):
            os.remove(png)
        browse(url + "?only=" + section, ["--window-size=1280,1600", "--hide-scrollbars", "--screenshot=" + png])
        check(os.path.exists(png) and os.path.getsize(png) > 10000, f"no screenshot of {section}")
    print(f"screenshots in {shots}")

    if "static" in results:
        check_vtk(results_dir, results, results.get("units", "SI"))
    if failures:
        print(f"{len(failures)} failures")
        sys.exit(1)
    print("report test passed")


parser = argparse.ArgumentParser()
parser.add_argument("drillflex")
parser.add_argument("case")
parser.add_argument("outdir")
parser.add_argument("--analysis", default="run")
parser.add_argument("--sections", default="header,static,view3d")
parser.add_argument("--keys", default="")
parser.add_argument("--json", default="results.json", help="the JSON file the report draws (roadmap.json)")
parser.add_argument("--options", default="", help="more options of the command, one string")
parser.add_argument("--exit", type=int, default=0, help="the command's expected exit status (3: an analysis failed)")
args = parser.parse_args()
args.sections = [s for s in args.sections.split(",") if s]
args.keys = [k for k in args.keys.split(",") if k]
main()
