#!/usr/bin/env python3
"""Contact sheets: every view of every technique on the chosen scenes, twelve to a screenshot.

For each technique and scene this writes a session file whose view grid holds the final frame, L_air
and each intermediate the technique declares (`airlight list stages T`), four to a row, three rows to a
sheet, opens the window full screen under Xvfb on it and saves the screenshot. Look at the sheets
before calling a view done: a legend that contradicts its note, a count in red that is not an error, a
picture too thin to read are found here and by no test.

Usage: scripts/contact_sheets.py [--scenes grate,tv-room] [--techniques minmax,vsv] [--size 160x120]
                                 [--airlight build/ci/app/airlight] --out DIR
Writes DIR/TECHNIQUE_SCENE_K.png (K = 0, 1, ... for techniques with more than twelve views) and the
session files beside them. Needs xvfb-run.
"""
import argparse
import json
import os
import subprocess
import sys

PER_ROW, ROWS = 4, 3


def views_of(airlight, technique):
    out = subprocess.run([airlight, "list", "stages", technique], capture_output=True, text=True, check=True).stdout
    ids = [line.split()[1] for line in out.splitlines() if line.strip().startswith("intermediate ")]
    return ["final", "airlight"] + ids


def row_layout(cells):
    if len(cells) == 1:
        return str(cells[0])
    return "x(%.4g,%d,%s)" % (1.0 / len(cells), cells[0], row_layout(cells[1:]))


def grid_layout(count):
    rows = [row_layout(list(range(i, min(count, i + PER_ROW)))) for i in range(0, count, PER_ROW)]
    text = rows[-1]
    for k in range(len(rows) - 2, -1, -1):
        text = "y(%.4g,%s,%s)" % (1.0 / (len(rows) - k), rows[k], text)
    return text


def session(scene, technique, size, contents):
    view = {"against": "reference", "center": [0.5, 0.5], "channel": 0, "colour_map": 0, "difference": 0,
            "layer": 0, "log": False, "manual": [0.0, 1.0], "mark_negative": -1, "range": 0,
            "strip_open": False, "zoom": 1.0}
    views = [dict(view, id=i, content=c) for i, c in enumerate(contents)]
    return {"version": 1, "scene": scene, "technique": technique, "settings": {}, "size": list(size),
            "exposure": 0.0, "exposure_set": False, "view": contents[min(1, len(contents) - 1)],
            "view_grid": {"focused": 0, "layout": grid_layout(len(contents)), "maximised": -1, "views": views}}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scenes", default="grate,tv-room")
    parser.add_argument("--techniques", default="reference,raymarch,slices,polyvol,minmax,vsv,ivsv")
    parser.add_argument("--size", default="160x120")
    parser.add_argument("--airlight", default=os.path.join(os.path.dirname(__file__), "..", "build", "ci", "app",
                                                           "airlight"))
    parser.add_argument("--out", required=True)
    args = parser.parse_args()
    size = tuple(int(v) for v in args.size.split("x"))
    os.makedirs(args.out, exist_ok=True)
    script = os.path.join(args.out, "full_screen.txt")
    with open(script, "w") as f:
        f.write("key F11\nframes 4\n")
    failures = 0
    for scene in args.scenes.split(","):
        for technique in args.techniques.split(","):
            contents = views_of(args.airlight, technique)
            per_sheet = PER_ROW * ROWS
            for k in range(0, len(contents), per_sheet):
                name = "%s_%s_%d" % (technique, scene, k // per_sheet)
                state = os.path.join(args.out, name + "_session.json")
                with open(state, "w") as f:
                    json.dump(session(scene, technique, size, contents[k:k + per_sheet]), f)
                png = os.path.join(args.out, name + ".png")
                run = subprocess.run(["xvfb-run", "-a", "-s", "-screen 0 1920x1080x24", args.airlight, "gui",
                                      "--state", state, "--size", args.size, "--ui-scale", "0.8", "--script",
                                      script, "--screenshot", png], capture_output=True, text=True)
                print("%s: %s" % (png, "ok" if run.returncode == 0 else run.stderr.strip()))
                failures += run.returncode != 0
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
