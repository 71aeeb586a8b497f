#!/usr/bin/env python3
"""Reads one soak run's --resource-log CSV (a sample every tenth frame, `segments` samples a cycle) and
its report, and checks that nothing grows once the lesson has been through every step and size. Cycle
1 is the warm-up (programs built, textures pooled, the font atlas made on first use); cycle 2 is the
baseline.
  - GL objects: in no sample of cycle 3 or later one more of any kind than at the same point of cycle 2.
  - Heap (bytes malloc holds, the driver's threads included): at each point of the cycle, the least
    value over the last third of the cycles at most HEAP_TOLERANCE_KIB above the least over the first
    third after the warm-up. The least, because a frame's temporary buffers can be alive when a sample
    is taken (lesson 07's step 4 once showed 22 MB more in one sample of twenty; lesson 09 sits 0, 2 or
    4 MB higher from one sample to the next as llvmpipe's threads take and give back memory); a leak
    raises every cycle, and so the least of them.
  - Resident memory: the least of each cycle's peak over the last third at most RESIDENT_TOLERANCE_KIB
    above the median peak of the first third (pages malloc and the driver give back come and go; the
    driver's own pools can rise once more in cycle 3, as lesson 10's did by 14 MB, and then stay).
  - No GL error in the report.
Prints one line of figures per lesson (the table in docs/reliability.md); exits 1 on growth."""
import csv
import json
import statistics
import sys

# 2 MiB: lesson 10's heap settles a second time, about 1.1 MiB higher at some points of cycle 2 than of
# cycle 1, then holds for as many cycles as were run (seven: no rise after cycle 3); a leak keeps
# rising and the long run's many cycles show it.
HEAP_TOLERANCE_KIB = 2048
# 64 MiB: lesson 07's resident peak moves by about 40 MB from one cycle to the next in some runs (its
# step 4 pool's pages kept by malloc or given back); a leak shows in the heap and the GL objects.
RESIDENT_TOLERANCE_KIB = 65536
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
    third = max(1, (cycles - 1) // 3)
    early = list(range(1, 1 + third))              # the first third of the cycles after the warm-up
    late = list(range(max(2, cycles - third), cycles))  # the last third
    for c in range(2, cycles):
        for o in range(segments):
            now, then = rows[c * segments + o], rows[segments + o]
            for kind in OBJECT_KINDS:
                if int(now[kind]) > int(then[kind]):
                    failures.append(f"frame {now['frame']} (step {now['step']}, {now['width']}x{now['height']}): "
                                    f"{now[kind]} {kind}, {then[kind]} a cycle-length earlier in cycle 2")
    if late:
        # A point's heap is the least of it and its neighbours in the cycle: a frame's temporary buffers
        # alive at one sample (lesson 07's step 4 held 21 MB more at one point of one cycle, in some
        # runs) are not a leak, and a leak raises every point.
        heap = lambda c, o: min(int(rows[c * segments + k]["heapKiB"])
                                for k in range(max(0, o - 1), min(segments, o + 2)))
        for o in range(segments):
            worst["heap"] = max(worst["heap"], min(heap(c, o) for c in late) - min(heap(c, o) for c in early))
        peak = lambda c: max(int(r["residentKiB"]) for r in rows[c * segments:(c + 1) * segments])
        worst["resident"] = min(peak(c) for c in late) - int(statistics.median(peak(c) for c in early))
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
