#!/usr/bin/env python3
"""Fails when a lesson's Japanese step text uses a rendering docs/japanese-terms.md says to avoid.

The glossary's one table has the columns | English | Japanese | not | note |: "Japanese" is the term
to write, "not" the variants to avoid, separated by " / ". Every lessons/*/lesson.ja.md is read line
by line, and each line that contains a variant is reported with the term to use instead. The table
is checked first: a missing or malformed table is an error of its own, since a checker that reads
nothing would pass everything.

  check_japanese_terms.py [ROOT]                check the tree at ROOT (default: this repository)
  check_japanese_terms.py ROOT --expect FILE    check the checker: what it reports at ROOT must be
                                                exactly the lines of FILE
Standard library only (python3 is on CI).
"""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1]))
import checker_cli  # noqa: E402 (tests/checker_cli.py: the command line every checker shares)

GLOSSARY = "docs/japanese-terms.md"
COLUMNS = ["English", "Japanese", "not", "note"]


class TableError(Exception):
    """The glossary cannot be used; the message names the file and the reason."""


def cells(line):
    """The cells of a markdown table row, stripped ("| a | b |" -> ["a", "b"])."""
    inner = line.strip()
    inner = inner[1:] if inner.startswith("|") else inner
    inner = inner[:-1] if inner.endswith("|") else inner
    return [cell.strip() for cell in inner.split("|")]


def is_separator(row):
    return bool(row) and all(cell and set(cell) <= set("-: ") and "-" in cell for cell in row)


def read_terms(path):
    """[(line number, English, Japanese, [variants])] from the glossary's table; TableError if unusable."""
    if not path.is_file():
        raise TableError(f"{GLOSSARY}: missing (the table of Japanese terms the lessons follow)")
    lines = path.read_text(encoding="utf-8").splitlines()
    starts = [i for i, line in enumerate(lines) if line.lstrip().startswith("|")
              and (i == 0 or not lines[i - 1].lstrip().startswith("|"))]
    if not starts:
        raise TableError(f"{GLOSSARY}: no table (expected one with the columns | {' | '.join(COLUMNS)} |)")
    if len(starts) > 1:
        raise TableError(f"{GLOSSARY}:{starts[1] + 1}: a second table; the glossary has exactly one")
    start = starts[0]
    header = cells(lines[start])
    if header != COLUMNS:
        raise TableError(f"{GLOSSARY}:{start + 1}: the table's columns are | {' | '.join(header)} |, "
                         f"expected | {' | '.join(COLUMNS)} |")
    if start + 1 >= len(lines) or not is_separator(cells(lines[start + 1])):
        raise TableError(f"{GLOSSARY}:{start + 2}: no |---| line under the table's header")
    terms = []
    for i in range(start + 2, len(lines)):
        if not lines[i].lstrip().startswith("|"):
            break
        where = f"{GLOSSARY}:{i + 1}"
        row = cells(lines[i])
        if len(row) != len(COLUMNS):
            raise TableError(f"{where}: {len(row)} cells, expected {len(COLUMNS)} ({' | '.join(COLUMNS)})")
        english, japanese, avoid, _note = row
        if not english:
            raise TableError(f"{where}: empty English cell")
        if not japanese:
            raise TableError(f'{where}: empty Japanese cell for "{english}"')
        variants = [v.strip() for v in avoid.split(" / ")] if avoid else []
        if any(not v for v in variants):
            raise TableError(f'{where}: an empty variant in the "not" cell of "{english}" '
                             f'(variants are separated by " / ")')
        for variant in variants:
            if variant in japanese:
                raise TableError(f'{where}: the variant "{variant}" is part of its own term "{japanese}", '
                                 f"so every correct use would be reported")
        terms.append((i + 1, english, japanese, variants))
    if not terms:
        raise TableError(f"{GLOSSARY}:{start + 1}: the table has no rows")
    # A variant inside a term another row prescribes would report that correct term too.
    for line, english, _japanese, variants in terms:
        for variant in variants:
            for other_line, _other_english, other_japanese, _ in terms:
                if variant in other_japanese:
                    raise TableError(f'{GLOSSARY}:{line}: the variant "{variant}" of "{english}" is part of '
                                     f'"{other_japanese}", the term of line {other_line}')
    return terms


def problems(root):
    """(the lines to print, number of files, number of terms); TableError if the table is unusable."""
    terms = read_terms(root / GLOSSARY)
    files = sorted((root / "lessons").glob("*/lesson.ja.md"))
    # The handout's own Japanese words (headings, captions, column names) follow the same table.
    handout_words = [path for path in [root / "common/app/handout_words.cpp"] if path.is_file()]
    found = []
    for path in files + handout_words:
        name = path.relative_to(root).as_posix()
        for number, text in enumerate(path.read_text(encoding="utf-8").splitlines(), start=1):
            for _line, _english, japanese, variants in terms:
                for variant in variants:
                    if variant in text:
                        found.append(f'{name}:{number}: "{variant}" is written "{japanese}" in this project '
                                     f"({GLOSSARY})")
    return found, len(files), len(terms)


def reported(root):
    """The lines check_japanese_terms reports at root: each variant found, or what keeps it from checking."""
    try:
        found, file_count, _ = problems(root)
    except TableError as error:
        return [f"check_japanese_terms: {error}"]
    if file_count == 0:
        return [f"check_japanese_terms: no lessons/*/lesson.ja.md under {root}"]
    return found


def main(argv):
    def passed(root):
        _, file_count, term_count = problems(root)
        return f"{file_count} lesson.ja.md files, {term_count} terms from {GLOSSARY}, no variant to avoid"

    def failed(_root, found):
        if found[0].startswith("check_japanese_terms:"):
            return None  # the glossary or the lessons could not be read: nothing to fix line by line
        return (f"{len(found)} line{'s' if len(found) != 1 else ''} to fix "
                "(write the second word in quotes instead of the first)")

    return checker_cli.run("check_japanese_terms", reported, passed, __doc__, argv[1:], failed=failed)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
