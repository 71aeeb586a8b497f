#!/usr/bin/env python3
"""Numbers in a lesson's text cannot drift from its facts (base/fact_references.hpp).

For every step of the lesson, one headless frame's report gives the step's facts, and:
  1. every reference {fact:NAME} or {fact:NAME WORD} in the step's text (lesson.md and lesson.ja.md)
     names a fact of that step, and WORD has a number after it in the fact's value;
  2. a fact that lists things with numbers ("firefly 900, sun 300, orange sphere 8") is quoted only by
     reference: lesson.md writing a number right after one of its words ("the firefly (about 800)",
     "the sun's 300") fails, with the fact's value and the reference to write. A number inside a
     tuple ("orange sphere (8, 4, 1)", a colour) is another quantity and is left alone.

  check_fact_references.py <lesson executable> <lesson folder> <work dir>
"""
import json
import re
import subprocess
import sys
from pathlib import Path

REFERENCE = re.compile(r"\{fact:([A-Za-z0-9_.]+)(?: ([^{}\n]+?))?\}")
STEP = re.compile(r"^## Step (\d+): ", re.M)
# A fact's items: "word(s) number" separated by commas.
ITEM = re.compile(r"^\s*([A-Za-z][A-Za-z ]*?) (-?\d+(?:\.\d+)?)\s*$")


def steps_of(markdown):
    """The text of each "## Step N:" section, by N (code blocks cannot hold a step heading here)."""
    out = {}
    marks = list(STEP.finditer(markdown))
    for i, m in enumerate(marks):
        end = marks[i + 1].start() if i + 1 < len(marks) else len(markdown)
        nxt = re.search(r"^## ", markdown[m.end():end], re.M)
        body = markdown[m.end(): m.end() + nxt.start()] if nxt else markdown[m.end():end]
        out[int(m.group(1))] = body
    return out


def number_after(value, word):
    for m in re.finditer(r"(?<![A-Za-z0-9_.])" + re.escape(word) + r" (-?\d[\d.e+-]*)", value):
        return m.group(1).rstrip(".")
    return None


def listed_items(value):
    """{word: number} when the fact's value is a list of "word number" items, else {}."""
    items = {}
    for part in str(value).split(","):
        m = ITEM.match(part)
        if not m:
            return {}
        items[m.group(1)] = m.group(2)
    return items


def main():
    exe, folder, work = sys.argv[1], Path(sys.argv[2]), Path(sys.argv[3])
    work.mkdir(parents=True, exist_ok=True)
    texts = {"lesson.md": steps_of((folder / "lesson.md").read_text(encoding="utf-8"))}
    if (folder / "lesson.ja.md").exists():
        texts["lesson.ja.md"] = steps_of((folder / "lesson.ja.md").read_text(encoding="utf-8"))
    failures = []
    checked = 0
    for step in sorted(texts["lesson.md"]):
        report = work / f"step-{step}.json"
        run = subprocess.run([exe, "--headless", "--size", "320x180", "--frames", "1", "--step", str(step),
                              "--report", str(report)], capture_output=True, text=True, timeout=600)
        if run.returncode != 0:
            failures.append(f"step {step}: the lesson exited {run.returncode}: {run.stderr[-2000:]}")
            continue
        facts = {k: (json.dumps(v) if isinstance(v, bool) else str(v))
                 for k, v in json.loads(report.read_text(encoding="utf-8")).get("facts", {}).items()}
        for file, steps in texts.items():
            for m in REFERENCE.finditer(steps.get(step, "")):
                name, word = m.group(1), m.group(2)
                checked += 1
                if name not in facts:
                    failures.append(f"{file} step {step}: {m.group(0)} names no fact of the step "
                                    f"(its facts: {', '.join(sorted(facts))})")
                elif word and number_after(facts[name], word) is None:
                    failures.append(f"{file} step {step}: {m.group(0)}: no number after '{word}' in "
                                    f"{name} = '{facts[name]}'")
        text = REFERENCE.sub("", texts["lesson.md"].get(step, ""))
        text = re.sub(r"\s+", " ", text)
        for name, value in facts.items():
            for word, number in listed_items(value).items():
                checked += 1
                # The word, then within a few words a number (not a tuple's first element).
                for m in re.finditer(r"\b" + re.escape(word) + r"\b(?:'s)?[^.;:,\d]{0,32}?(-?\d+(?:\.\d+)?)(?!\d)",
                                     text):
                    after = text[m.end():m.end() + 3]
                    before = text[max(m.start(1) - 1, 0):m.start(1)]
                    if before == "(" and re.match(r",\s*-?\d", after):
                        continue  # "(8, 4, 1)": a colour, not the fact's number
                    failures.append(
                        f"lesson.md step {step}: '{m.group(0)}' quotes the fact {name} ('{value}') "
                        f"with a number written by hand ({m.group(1)}; the fact says {number}): "
                        f"write {{fact:{name} {word}}}")
    for f in failures:
        print("FAIL:", f)
    print(f"{folder.name}: {checked} fact quotations checked, {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
