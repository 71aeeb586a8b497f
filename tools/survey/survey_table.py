#!/usr/bin/env python3
"""The survey's table, in markdown: one row per lesson and step, for each run folder given as NAME=DIR
(made by frame_survey.sh: DIR/<lesson>/step-K/report.json) the median frame of the run (the report's
cpuMs, the first frame left out: it builds the programs) and, where the report has one, the size the
picture rendered at. A step over the frame budget (200 ms) is marked in bold.

    survey_table.py before=out/survey/before after=out/survey/after
"""
import json
import statistics
import sys
from pathlib import Path

BUDGET_MS = 200.0


def runs(folder: Path):
    table = {}
    for report in folder.glob("fxlab-*/step-*/report.json"):
        data = json.loads(report.read_text())
        frames = [f["cpuMs"] for f in data.get("frames", [])][1:]
        if not frames:
            continue
        lesson = report.parent.parent.name.split("-")[1]
        step = int(report.parent.name.split("-")[1])
        picture = data.get("picture", {})
        rendered = f"{picture['rendered'][0]}x{picture['rendered'][1]}" if picture else ""
        table[(lesson, step)] = (statistics.median(frames), rendered)
    return table


def main(args):
    columns = []
    for arg in args:
        name, _, folder = arg.partition("=")
        columns.append((name, runs(Path(folder))))
    keys = sorted({key for _, table in columns for key in table})
    header = ["lesson", "step"]
    for name, table in columns:
        header.append(f"{name} (ms)")
        if any(rendered for _, rendered in table.values()):
            header.append(f"{name}: picture")
    print("| " + " | ".join(header) + " |")
    print("|" + "---|" * len(header))
    for lesson, step in keys:
        row = [lesson, str(step)]
        for _, table in columns:
            ms, rendered = table.get((lesson, step), (None, ""))
            row.append("" if ms is None else (f"**{ms:.0f}**" if ms > BUDGET_MS else f"{ms:.0f}"))
            if any(r for _, r in table.values()):
                row.append(rendered)
        print("| " + " | ".join(row) + " |")


if __name__ == "__main__":
    main(sys.argv[1:])
