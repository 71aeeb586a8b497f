#!/usr/bin/env python3
"""Writes summary.md and bench-gpu.md for a tools/gpu/run.sh results folder.

bench-gpu.md holds the figures docs/bench-gpu.md asks for, each from this run's own files: lesson 07's
three particle paths at 10,000 and 100,000 particles, lesson 06's bloom chain plus output transform in
full-screen copies, lesson 08's quality combinations, lesson 10's light sweep, and how far every smoke
step is from its golden image. Every table says which renderer made it; a software renderer's run is
marked NOT A GPU in the title and in every table. A figure a file does not hold is written as "-".

    write_report.py OUT_DIR --renderer TEXT --kind TEXT --tolerance R,M --seconds N [--short]
"""
import argparse
import csv
import os
import statistics
import sys


def rows(path):
    if not os.path.isfile(path):
        return []
    with open(path, newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


def num(text, digits=3):
    try:
        v = float(text)
    except (TypeError, ValueError):
        return "-"
    return f"{v:.{digits}g}" if abs(v) < 1000 else f"{v:.0f}"


def lesson07(out):
    """The workload rows: "<path> <count>" -> frame ms and copies; the ratios the 20x target asks for."""
    table = {}
    for r in rows(os.path.join(out, "bench", "07", "bench.csv")):
        parts = r["value"].strip('"').split()
        if r["knob"] == "workload" and len(parts) == 2:
            table[(parts[0], int(parts[1]))] = (float(r["median_ms"]), float(r["copy_multiple"]))
    lines = ["| particles | one draw per particle (ms / copies) | instanced | GPU | per particle / instanced | per particle / GPU |",
             "|---|---|---|---|---|---|"]
    counts = sorted({c for (_, c) in table})
    for c in counts:
        cell = lambda p: f"{num(table[(p, c)][0])} / {num(table[(p, c)][1])}" if (p, c) in table else "-"
        ratio = lambda p: num(table[("objects", c)][0] / table[(p, c)][0]) if ("objects", c) in table and (p, c) in table and table[(p, c)][0] > 0 else "-"
        lines.append(f"| {c:,} | {cell('objects')} | {cell('instanced')} | {cell('gpu')} | {ratio('instanced')} | {ratio('gpu')} |")
    return lines if counts else ["(no workload rows: bench/07/bench.csv)"]


CHAIN = ("bloom bright pass", "bloom down", "bloom up", "bloom composite", "output transform")


def lesson06(out):
    """The finish rows: the frame in copies, and the chain plus output transform summed from passes.csv."""
    bench = rows(os.path.join(out, "bench", "06", "bench.csv"))
    passes = rows(os.path.join(out, "bench", "06", "passes.csv"))
    lines = ["| finish | frame (copies) | chain + output transform (copies) | modelled traffic, frame (MB at 1080p) | RMSE |",
             "|---|---|---|---|---|"]
    for r in bench:
        if r["knob"] != "finish":
            continue
        # The reference algorithm's row has no chain: its glow is the direct Gaussians.
        chain = 0 if r["reference"] == "1" else sum(
            float(p["copies"]) for p in passes
            if p["knob"] == "finish" and p["value"] == r["value"] and p["pass"].startswith(CHAIN))
        lines.append(f"| {r['value']}{' (reference)' if r['reference'] == '1' else ''} | {num(r['copy_multiple'])} | "
                     f"{num(chain) if chain else '-'} | {num(r.get('traffic_mb_1080p'))} | {num(r['rmse'])} |")
    return lines if len(lines) > 2 else ["(no finish rows: bench/06/bench.csv)"]


def lesson08(out):
    lines = ["| quality | frame (ms) | frame (copies) | RMSE |", "|---|---|---|---|"]
    for r in rows(os.path.join(out, "bench", "08", "bench.csv")):
        if r["knob"] == "quality":
            lines.append(f"| {r['value']} | {num(r['median_ms'])} | {num(r['copy_multiple'])} | {num(r['rmse'])} |")
    return lines if len(lines) > 2 else ["(no quality rows: bench/08/bench.csv)"]


def lesson10(out):
    runs = {}
    for r in rows(os.path.join(out, "bench", "10", "light_sweep.csv")):
        runs.setdefault((int(r["lights"]), r["culling"]), []).append(float(r["lighting_ms"]) + float(r["culling_ms"]))
    lines = ["| point lights | culling none (ms) | culling tiled (ms) | none / tiled |", "|---|---|---|---|"]
    for n in sorted({n for (n, _) in runs}):
        none, tiled = runs.get((n, "none")), runs.get((n, "tiled"))
        a = statistics.median(none) if none else None
        b = statistics.median(tiled) if tiled else None
        lines.append(f"| {n} | {num(a) if a is not None else '-'} | {num(b) if b is not None else '-'} | "
                     f"{num(a / b) if a and b else '-'} |")
    return lines if len(lines) > 2 else ["(no light sweep: bench/10/light_sweep.csv)"]


def smoke(out, tolerance):
    table = rows(os.path.join(out, "smoke.csv"))
    passed = sum(1 for r in table if r["result"] == "pass")
    worst = sorted((r for r in table if r["rmse"]), key=lambda r: -float(r["rmse"]))[:5]
    lines = [f"{passed} of {len(table)} steps within RMSE,max {tolerance} (8-bit levels) of the llvmpipe goldens."]
    if worst:
        lines += ["", "| step | RMSE | max difference | texels differing |", "|---|---|---|---|"]
        lines += [f"| {r['lesson']} step {r['step']} | {num(r['rmse'])} | {r['max_abs']} | {r['texels_differing']} |" for r in worst]
    failures = [r for r in table if r["result"] != "pass"]
    if failures:
        lines += ["", "Over the tolerance or failed: " + ", ".join(f"{r['lesson']} step {r['step']}" for r in failures)
                  + " (their pictures: smoke/<lesson>/step-K/*.actual.png and *.diff.png)."]
    return lines


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out")
    ap.add_argument("--renderer", required=True)
    ap.add_argument("--kind", required=True)
    ap.add_argument("--tolerance", required=True)
    ap.add_argument("--seconds", type=int, default=0)
    ap.add_argument("--short", action="store_true")
    a = ap.parse_args()
    mark = "" if a.kind == "GPU" else f" ({a.kind})"
    timer = open(os.path.join(a.out, "timer", "summary.txt")).read().strip() if os.path.isfile(
        os.path.join(a.out, "timer", "summary.txt")) else "(no timer run)"
    mode = "short mode (the suite's: tiny sizes, one value per knob)" if a.short else "full run"
    doc = [f"# GPU run{mark}", "",
           f"Made by `tools/gpu/run.sh` ({mode}, {a.seconds} s) on: **{a.renderer}**, {a.kind}.", ""]
    if a.kind != "GPU":
        doc += ["**Not a GPU.** These figures come from a software renderer; they show that the run works "
                "end to end, not what a GPU costs.", ""]
    doc += [f"## Lesson 07: three particle paths{mark}", ""] + lesson07(a.out)
    doc += ["", f"## Lesson 06: the bloom chain's finish{mark}", ""] + lesson06(a.out)
    doc += ["", f"## Lesson 08: the clouds' quality combinations{mark}", ""] + lesson08(a.out)
    doc += ["", f"## Lesson 10: the deferred light sweep{mark}", ""] + lesson10(a.out)
    doc += ["", f"## Smoke steps against the goldens{mark}", ""] + smoke(a.out, a.tolerance)
    doc += ["", f"## The GPU timer path{mark}", "", "```", timer, "```", ""]
    with open(os.path.join(a.out, "bench-gpu.md"), "w", encoding="utf-8") as f:
        f.write("\n".join(doc))
    log = open(os.path.join(a.out, "run.log")).read() if os.path.isfile(os.path.join(a.out, "run.log")) else ""
    with open(os.path.join(a.out, "summary.md"), "w", encoding="utf-8") as f:
        f.write(f"# tools/gpu/run.sh{mark}\n\n```\n{log}```\n\nFigures: bench-gpu.md\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
