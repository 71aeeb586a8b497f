#!/usr/bin/env python3
"""Reads one soak run's --resource-log CSV (a sample every tenth frame, `segments` samples a cycle) and
its report, and checks that nothing grows once the lesson has been through every step and size: every
sample of cycle 3 and later against the sample at the same point of cycle 2 (cycle 1 is the warm-up:
programs built, textures pooled, the font atlas made on first use).
  - GL objects: not one more of any kind.
  - Heap (bytes malloc holds): at most HEAP_TOLERANCE_KIB more.
  - Resident memory: each cycle's peak at most RESIDENT_TOLERANCE_KIB above cycle 2's (compared by peak,
    since the pages malloc and the driver give back come and go from one sample to the next).
  - No GL error in the report.
Prints one line of figures per lesson (the table in docs/reliability.md); exits 1 on growth."""
import csv
import json
import sys

HEAP_TOLERANCE_KIB = 1024
RESIDENT_TOLERANCE_KIB = 8192
OBJECT_KINDS = ["textures", "buffers", "framebuffers", "renderbuffers", "vertexArrays", "samplers", "queries",
                "programs", "shaders", "transformFeedbacks"]


def main():
    log, report_file, segments, seconds = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
    rows = list(csv.DictReader(open(log)))
    report = json.load(open(report_file))
    name = report.get("lesson", log)
    cycles = len(rows) // segments
    failures = []
    if cycles < 3:
        failures.append(f"{len(rows)} samples: fewer than three cycles of {segments}")
    if report.get("glErrors", 0) != 0:
        failures.append(f"{report['glErrors']} GL errors: {report.get('lastGlError', '')}")
    worst = {"heap": 0, "resident": 0}
    for c in range(2, cycles):
        for o in range(segments):
            now, then = rows[c * segments + o], rows[segments + o]
            for kind in OBJECT_KINDS:
                if int(now[kind]) > int(then[kind]):
                    failures.append(f"frame {now['frame']} (step {now['step']}, {now['width']}x{now['height']}): "
                                    f"{now[kind]} {kind}, {then[kind]} a cycle-length earlier in cycle 2")
            worst["heap"] = max(worst["heap"], int(now["heapKiB"]) - int(then["heapKiB"]))
        peak = lambda cycle: max(int(r["residentKiB"]) for r in rows[cycle * segments:(cycle + 1) * segments])
        worst["resident"] = max(worst["resident"], peak(c) - peak(1))
    if worst["heap"] > HEAP_TOLERANCE_KIB:
        failures.append(f"the heap grew by {worst['heap']} KiB after the warm-up (tolerance {HEAP_TOLERANCE_KIB})")
    if worst["resident"] > RESIDENT_TOLERANCE_KIB:
        failures.append(f"resident memory grew by {worst['resident']} KiB after the warm-up "
                        f"(tolerance {RESIDENT_TOLERANCE_KIB})")
    last = rows[-1] if rows else {}
    objects = sum(int(last.get(k, 0)) for k in OBJECT_KINDS)
    print(f"| {name} | {rows[-1]['frame'] if rows else 0} | {cycles} | {seconds} | "
          f"{int(last.get('residentKiB', 0)) // 1024} | {worst['resident']} | {worst['heap']} | {objects} | "
          f"{'growth' if failures else 'none'} |")
    for f in failures[:10]:
        print(f"FAIL: {name}: {f}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
