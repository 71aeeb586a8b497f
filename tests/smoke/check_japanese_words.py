#!/usr/bin/env python3
"""Every step of a lesson headless with --lang ja and the overlay: everything the panel shows in
Japanese. Fails on a shown fact's label or a parameter's label without Japanese (an ASCII-only label:
code names and units may stand inside a Japanese one, not alone), on a key no words file has
(missingWords), and on a glyph of the words missing from the overlay's font.
  check_japanese_words.py <lesson executable> <work folder>
"""
import json
import os
import re
import subprocess
import sys


def japanese(text):
    return any(ord(c) > 0x7F for c in text)


def main():
    exe, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    listing = subprocess.run([exe, "--list-steps"], capture_output=True, text=True, timeout=60)
    steps = len(re.findall(r"^\d+\. ", listing.stdout, re.M))
    if steps == 0:
        print("FAIL: --list-steps listed no steps:", listing.stdout, listing.stderr)
        return 1
    failures = []
    for step in range(1, steps + 1):
        report_file = os.path.join(work, f"step-{step}.json")
        run = subprocess.run([exe, "--headless", "--overlay", "--lang", "ja", "--frames", "2", "--size", "320x180",
                              "--step", str(step), "--report", report_file],
                             capture_output=True, text=True, timeout=300)
        if run.returncode != 0:
            failures.append(f"step {step}: the run failed ({run.returncode}):\n{run.stderr[-2000:]}")
            continue
        with open(report_file, encoding="utf-8") as f:
            report = json.load(f)
        if report.get("language") != "ja":
            failures.append(f"step {step}: the report's language is {report.get('language')!r}, not 'ja'")
        for key in report.get("missingWords", []):
            failures.append(f"step {step}: no words for {key}")
        for fact in report.get("shownFacts", []):
            if not japanese(fact["label"]):
                failures.append(f"step {step}: the fact label {fact['label']!r} has no Japanese")
        for param in report.get("params", []):
            if not japanese(param.get("label", "")):
                failures.append(f"step {step}: the parameter {param['name']} shows {param.get('label')!r}, no Japanese")
        font = re.findall(r"\((\d+) not in the font\)", run.stderr + run.stdout)
        if font and font[-1] != "0":
            failures.append(f"step {step}: {font[-1]} glyphs of the Japanese words are not in the overlay's font")
    if failures:
        print("FAIL:\n" + "\n".join(failures))
        return 1
    print(f"every label of {steps} steps in Japanese")
    return 0


if __name__ == "__main__":
    sys.exit(main())
