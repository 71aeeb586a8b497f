#!/usr/bin/env python3
"""Fails when a lesson's Japanese text uses a rendering docs/japanese-terms.md says to avoid.

The glossary's one table has the columns | English | Japanese | lessons | chapters | not | note |:
"Japanese" is the term to write, "lessons" where the row holds ("all", or lesson numbers and ranges
such as "01-08, 10"; "app" for the app's own words), "chapters" the chapters' own counts (free text,
not checked), "not" the variants to avoid, separated by " / ". The chapters come from two courses
and do not spell every word alike, so a row can hold for some lessons only (シェーダ in most,
シェーダー in the FBO / depth of field chapter's lesson 09).

Checked: every lessons/NN_*/lesson.ja.md and every other Japanese file of a lesson's folder (a name
with ".ja."), against the rows of that lesson; common/app/handout_words.cpp against the rows that
hold for "all" or "app". A line is reported for each variant it contains, with the term to use
instead, except where the variant is part of a term that holds there (ブラー inside 放射状ブラー,
インスペクタ inside インスペクター): so a variant may be part of a correct term and is reported only
on its own. In markdown, code (`...` and ``` blocks) is not prose and is not checked, nor is an
emphasis in ASCII (*uniform lookups last frame*: an item of the overlay's information panel quoted by
its English name). A variant in
ASCII letters ("uniform", "## Step") is checked in the markdown files only, and as a whole word
(so "uniform" does not match "glProgramUniform" or `uniform_count`).

The table is checked first: a missing or malformed table is an error of its own, since a checker that
reads nothing would pass everything.

  check_japanese_terms.py [ROOT]                check the tree at ROOT (default: this repository)
  check_japanese_terms.py ROOT --expect FILE    check the checker: what it reports at ROOT must be
                                                exactly the lines of FILE
Standard library only (python3 is on CI).
"""
import pathlib
import re
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1]))
import checker_cli  # noqa: E402 (tests/checker_cli.py: the command line every checker shares)

GLOSSARY = "docs/japanese-terms.md"
COLUMNS = ["English", "Japanese", "lessons", "chapters", "not", "note"]
APP_FILES = ["common/app/handout_words.cpp"]  # the app's own Japanese words
APP = "app"


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


def read_scope(cell, where):
    """The set of lessons a "lessons" cell names (numbers, and APP for the app's words)."""
    if cell == "all":
        return set(range(1, 100)) | {APP}
    scope = set()
    for item in [part.strip() for part in cell.split(",")]:
        match = re.fullmatch(r"(\d\d)(?:-(\d\d))?", item)
        if item == APP:
            scope.add(APP)
        elif match and int(match.group(1)) <= int(match.group(2) or match.group(1)):
            scope.update(range(int(match.group(1)), int(match.group(2) or match.group(1)) + 1))
        else:
            raise TableError(f'{where}: the lessons cell "{cell}" is not "all" or a list such as '
                             f'"01-08, 10, app" (two-digit numbers, ranges low-high)')
    return scope


def read_terms(path):
    """[(line, English, Japanese, scope, [variants])] from the glossary's table; TableError if unusable."""
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
        english, japanese, lessons, _chapters, avoid, _note = row
        if not english:
            raise TableError(f"{where}: empty English cell")
        if not japanese:
            raise TableError(f'{where}: empty Japanese cell for "{english}"')
        scope = read_scope(lessons, where)
        variants = [v.strip() for v in avoid.split(" / ")] if avoid else []
        if any(not v for v in variants):
            raise TableError(f'{where}: an empty variant in the "not" cell of "{english}" '
                             f'(variants are separated by " / ")')
        terms.append((i + 1, english, japanese, scope, variants))
    if not terms:
        raise TableError(f"{GLOSSARY}:{start + 1}: the table has no rows")
    # A variant that is itself a term where both rows hold could never be reported: the table
    # contradicts itself.
    for line, english, _japanese, scope, variants in terms:
        for variant in variants:
            for other_line, _other, other_japanese, other_scope, _ in terms:
                if variant == other_japanese and scope & other_scope:
                    raise TableError(f'{GLOSSARY}:{line}: the variant "{variant}" of "{english}" is the term of '
                                     f"line {other_line} for the same lessons, so it is never reported")
    return terms


def prose_lines(path):
    """(number, text) of each line to check; in markdown, code spans and ``` blocks blanked."""
    markdown = path.suffix == ".md"
    in_code = False
    for number, text in enumerate(path.read_text(encoding="utf-8").splitlines(), start=1):
        if markdown:
            if text.lstrip().startswith("```"):
                in_code = not in_code
                continue
            if in_code:
                continue
            text = re.sub(r"`[^`]*`", lambda m: " " * len(m.group(0)), text)
            # An item of the information panel quoted by its name, in English: *uniform lookups last frame*
            text = re.sub(r"\*[ -~]+?\*", lambda m: " " * len(m.group(0)) if m.group(0).isascii() else m.group(0), text)
        yield number, text


def is_ascii_word(variant):
    return variant.isascii()


def occurrences(text, variant):
    """The (start, end) of each occurrence; an ASCII variant only as a whole word."""
    if is_ascii_word(variant):
        pattern = (r"(?<![A-Za-z0-9_])" if variant[0].isalnum() else "") + re.escape(variant) + \
                  (r"(?![A-Za-z0-9_])" if variant[-1].isalnum() else "")
        return [(m.start(), m.end()) for m in re.finditer(pattern, text)]
    return [(m.start(), m.end()) for m in re.finditer(re.escape(variant), text)]


def found_in(path, name, rows, markdown):
    found = []
    terms = [japanese for _line, _english, japanese, _scope, _variants in rows]
    for number, text in prose_lines(path):
        covered = [span for term in terms for span in occurrences(text, term)]
        for _line, _english, japanese, _scope, variants in rows:
            for variant in variants:
                if is_ascii_word(variant) and not markdown:
                    continue
                for start, end in occurrences(text, variant):
                    if any(s <= start and end <= e and (s, e) != (start, end) for s, e in covered):
                        continue  # part of a term that holds here
                    found.append(f'{name}:{number}: "{variant}" is written "{japanese}" in this project '
                                 f"({GLOSSARY})")
                    break
    return found


def lesson_number(folder):
    match = re.match(r"(\d\d)_", folder.name)
    return int(match.group(1)) if match else None


def problems(root):
    """(the lines to print, number of lesson.ja.md files, number of terms); TableError if unusable."""
    terms = read_terms(root / GLOSSARY)
    files = sorted((root / "lessons").glob("*/lesson.ja.md"))
    checked = []  # (path, scope key)
    for folder in sorted(path for path in (root / "lessons").glob("*") if path.is_dir()):
        number = lesson_number(folder)
        if number is None:
            continue
        for path in sorted(folder.iterdir()):
            if path.is_file() and (path.name == "lesson.ja.md" or ".ja." in path.name):
                checked.append((path, number))
    checked += [(root / name, APP) for name in APP_FILES if (root / name).is_file()]
    found = []
    for path, key in checked:
        rows = [term for term in terms if key in term[3]]
        found += found_in(path, path.relative_to(root).as_posix(), rows, path.suffix == ".md")
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
