#!/usr/bin/env python3
"""Adds a "tested by" column (the last one) to the Markdown tables of a doc, from a mapping of
each row's first cell to the tests that exercise it (issue 20's acceptance: docs/rib-support.md
and docs/shading-language.md "gain a column 'tested by'").

    add_tested_by.py [--mapping tested_by.json [--mapping more.json]...] [--dry-run] DOC...

The mapping is {"docs/rib-support.md": {"Sphere": "render_golden: quadric_sphere.rib", ...},
...}; a DOC is matched to its entry by its path's tail (docs/rib-support.md) or its file name,
so copies elsewhere work too. With several mappings a later one's rows replace an earlier
one's (tested_by.branches.json after tested_by.json: the rows that branches changed).

A table gets the column when it already has one, when the mapping names one of its rows, or
when its header's first cell is one of --headers (Request, function, statement by default, so
that a table added on a branch shows up). In such a table the header gets "tested by", the
separator row "---", and each row the mapping's text for its first cell; a row the mapping
does not name keeps what its cell already says, or gets "?" so that whoever merges sees it
(check_tested_by.py fails on "?"). Running it again updates the column in place: it is never
doubled. Lines outside tables, and the other cells, stay byte for byte as they were.

Reported, for the merger: rows that got "?", rows whose other cells name a test that their
"tested by" cell does not (the row's text changed on a branch after the mapping was made), two
rows with the same first cell, and table rows outside any table (a table split by a blank line
or a conflict marker: its later rows would get no column)."""

import argparse
import json
import os
import re
import sys

COLUMN = "tested by"
MISSING = "?"
DEFAULT_HEADERS = ("request", "function", "statement")
SEPARATOR = re.compile(r"^\s*\|?\s*:?-{3,}:?\s*(\|\s*:?-{3,}:?\s*)*\|?\s*$")
FENCE = re.compile(r"^\s*(```|~~~)")


def split_cells(line):
    """The cells of a table row, split on the pipes not escaped with a backslash (as GitHub
    splits them, also inside code spans), without the outer pipes. Returns (cells, spans): the
    cells' text unstripped, and each cell's (start, end) in the line."""
    pipes = [i for i, c in enumerate(line) if c == "|" and (i == 0 or line[i - 1] != "\\")]
    start, end = len(line) - len(line.lstrip()), len(line.rstrip())
    lead = bool(pipes) and pipes[0] == start
    trail = bool(pipes) and pipes[-1] == end - 1 and (len(pipes) > 1 or not lead)
    delimiters = ([] if lead else [start - 1]) + pipes + ([] if trail else [end])
    spans = [(a + 1, b) for a, b in zip(delimiters, delimiters[1:])]
    return [line[a:b] for a, b in spans], spans


def first_cell(line):
    return split_cells(line)[0][0].strip()


def find_tables(lines):
    """Yields (header_index, separator_index, [row indices]) for every pipe table outside
    fenced code blocks."""
    in_fence = False
    i = 0
    while i < len(lines):
        if FENCE.match(lines[i]):
            in_fence = not in_fence
            i += 1
            continue
        if (not in_fence and lines[i].lstrip().startswith("|") and i + 1 < len(lines)
                and SEPARATOR.match(lines[i + 1]) and "-" in lines[i + 1]):
            rows = []
            j = i + 2
            while j < len(lines) and lines[j].lstrip().startswith("|"):
                rows.append(j)
                j += 1
            yield i, i + 1, rows
            i = j
        else:
            i += 1


def orphan_runs(lines):
    """(first, last) line indices of each run of lines that look like table rows but belong to
    no table (outside fences): a table split by a blank line or a conflict marker, whose later
    rows would get no column."""
    in_tables = set()
    for header, separator, rows in find_tables(lines):
        in_tables.update([header, separator, *rows])
    in_fence, out = False, []
    for i, line in enumerate(lines):
        if FENCE.match(line):
            in_fence = not in_fence
        elif not in_fence and line.lstrip().startswith("|") and i not in in_tables:
            if out and out[-1][1] == i - 1:
                out[-1] = (out[-1][0], i)
            else:
                out.append((i, i))
    return out


def orphan_message(first, last):
    where = f"line {first + 1}" if first == last else f"lines {first + 1}-{last + 1}"
    return (f"{where}: {last - first + 1} table row(s) outside any table (is the table split, "
            f"by a blank line or a conflict marker?)")


def column_index(header_line):
    """The index of the "tested by" cell in a header row, or None."""
    cells, _ = split_cells(header_line)
    for k, cell in enumerate(cells):
        if cell.strip().lower() == COLUMN:
            return k
    return None


def escape(text):
    return re.sub(r"(?<!\\)\|", r"\|", text)


def set_cell(line, index, text, pad=" "):
    """The row with cell `index` replaced by `text` between `pad`s (appended, after empty cells
    where the row is short)."""
    cells, spans = split_cells(line)
    cell = f"{pad}{text}{pad}"
    if index < len(cells):
        start, end = spans[index]
        return line[:start] + cell + line[end:]
    body = line.rstrip()
    if not body.endswith("|"):
        body += " |"
    return body + f"{pad}|" * (index - len(cells)) + f"{cell}|"


def doc_mapping(mapping, path):
    """The mapping's entry for `path`: the key that is the longest tail of the path."""
    norm = os.path.normpath(os.path.abspath(path)).replace(os.sep, "/")
    best = None
    for key in mapping:
        k = key.strip("/")
        if norm.endswith("/" + k) or os.path.basename(norm) == os.path.basename(k):
            if best is None or len(k) > len(best):
                best = key
    return mapping.get(best, {}) if best is not None else None


TEST_NAME = re.compile(r"\b(?:[A-Z]\w+\.[A-Z]\w+|\w+_(?:test|checks)\b|tests/[\w./-]+)")


def add_column(text, rows_mapping, headers=DEFAULT_HEADERS):
    """Returns (new text, report lines) for one doc's text."""
    lines = text.split("\n")
    report = []
    for header, separator, rows in find_tables(lines):
        index = column_index(lines[header])
        named = any(first_cell(lines[r]) in rows_mapping for r in rows)
        wanted = first_cell(lines[header]).lower() in headers
        if index is None and not (named or wanted):
            continue
        if index is None:
            index = len(split_cells(lines[header])[0])
        lines[header] = set_cell(lines[header], index, COLUMN)
        lines[separator] = set_cell(lines[separator], index, "---", pad="")
        seen = {}
        for r in rows:
            key = first_cell(lines[r])
            cells, _ = split_cells(lines[r])
            old = cells[index].strip() if index < len(cells) else ""
            if key in seen:
                report.append(f"line {r + 1}: '{key}' is also the first cell of line "
                              f"{seen[key] + 1}: both get the same entry")
            seen[key] = r
            if key in rows_mapping:
                value = escape(rows_mapping[key])
            elif old:
                value = old
            else:
                value = MISSING
                report.append(f"line {r + 1}: '{key}' is not in the mapping: '{MISSING}'")
            lines[r] = set_cell(lines[r], index, value)
            others = " ".join(c for k, c in enumerate(cells) if k != index and k > 0)
            mentioned = sorted({m for m in TEST_NAME.findall(others)
                                if os.path.basename(m.rstrip("/")).split(".")[0] not in value})
            if mentioned:
                report.append(f"line {r + 1}: '{key}' names {', '.join(mentioned)} in its text; "
                              f"its {COLUMN} cell says: {value}")
    report += [orphan_message(first, last) for first, last in orphan_runs(lines)]
    return "\n".join(lines), report


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("docs", nargs="+", metavar="DOC")
    parser.add_argument("--mapping", action="append",
                        help="a mapping (JSON); repeatable, later ones win (default: none, "
                             "the cells keep what they say)")
    parser.add_argument("--headers", default=",".join(DEFAULT_HEADERS),
                        help="header first cells whose tables always get the column")
    parser.add_argument("--dry-run", action="store_true", help="report, write nothing")
    args = parser.parse_args()
    mapping = {}
    for path in args.mapping or []:
        with open(path, encoding="utf-8") as f:
            for doc, rows in json.load(f).items():
                mapping.setdefault(doc, {}).update(rows)
    headers = tuple(h.strip().lower() for h in args.headers.split(",") if h.strip())
    status = 0
    for doc in args.docs:
        rows_mapping = doc_mapping(mapping, doc) if mapping else {}
        if rows_mapping is None:
            print(f"{doc}: no entry in the mapping (keys: {', '.join(mapping)})",
                  file=sys.stderr)
            status = 1
            continue
        with open(doc, encoding="utf-8") as f:
            text = f.read()
        new, report = add_column(text, rows_mapping, headers)
        for line in report:
            print(f"{doc}:{line}")
        if new == text:
            print(f"{doc}: unchanged")
        elif args.dry_run:
            print(f"{doc}: would change")
        else:
            with open(doc, "w", encoding="utf-8") as f:
                f.write(new)
            print(f"{doc}: updated")
    return status


if __name__ == "__main__":
    sys.exit(main())
