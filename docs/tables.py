#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""Result tables in docs/ written from the committed results they show.

A table in a docs/*.md page between
    <!-- table: SOURCE [part=N] [rows=REGEX] [columns=a,b,...] -->
    <!-- end table -->
is SOURCE's: a markdown file's N-th table (default the first), or a CSV
file's rows (its columns, or those named); rows=REGEX keeps the header and
the rows the expression matches (Python re.search on the row's line).
SOURCE is relative to the project's top.

usage: docs/tables.py            check: print each table that differs from its
                                 source, exit 1 if any does
       docs/tables.py --write    rewrite the tables from their sources
"""
import csv
import glob
import os
import re
import shlex
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BLOCK = re.compile(r"(?ms)^<!-- table: (.*?) -->\n(.*?)^<!-- end table -->$")


def markdown_tables(text):
    """The tables of a markdown text, each a list of its lines."""
    tables, current = [], []
    for line in text.splitlines() + [""]:
        if line.startswith("|"):
            current.append(line)
        elif current:
            tables.append(current)
            current = []
    return tables


def render(spec):
    """The table's lines for a block's specification; ValueError names what is wrong."""
    words = shlex.split(spec)
    if not words:
        raise ValueError("no source named")
    source, options = words[0], dict(w.split("=", 1) for w in words[1:] if "=" in w)
    unknown = set(options) - {"part", "rows", "columns"} | {w for w in words[1:] if "=" not in w}
    if unknown:
        raise ValueError("unknown option(s) %s" % ", ".join(sorted(unknown)))
    path = os.path.join(ROOT, source)
    if not os.path.isfile(path):
        raise ValueError("no file %s" % source)
    if source.endswith(".csv"):
        with open(path, newline="") as f:
            records = list(csv.reader(f))
        header = records[0]
        names = options["columns"].split(",") if "columns" in options else header
        missing = [n for n in names if n not in header]
        if missing:
            raise ValueError("%s has no column(s) %s" % (source, ", ".join(missing)))
        index = [header.index(n) for n in names]
        lines = ["| " + " | ".join(names) + " |", "|---" * len(names) + "|"]
        lines += ["| " + " | ".join(r[i] for i in index) + " |" for r in records[1:] if r]
    else:
        tables = markdown_tables(open(path).read())
        part = int(options.get("part", 1))
        if not 1 <= part <= len(tables):
            raise ValueError("%s has %d table(s), not a table %d" % (source, len(tables), part))
        lines = tables[part - 1]
    if "rows" in options:
        lines = lines[:2] + [l for l in lines[2:] if re.search(options["rows"], l)]
    return lines


def pages():
    return sorted(glob.glob(os.path.join(ROOT, "docs", "**", "*.md"), recursive=True))


def process(write):
    """(blocks, problems): every block's table against its source."""
    blocks, problems = 0, []
    for page in pages():
        text = open(page).read()
        name = os.path.relpath(page, ROOT)

        def replace(m):
            nonlocal blocks
            blocks += 1
            try:
                wanted = "\n".join(render(m.group(1))) + "\n"
            except ValueError as e:
                problems.append("%s: table '%s': error: %s" % (name, m.group(1), e))
                return m.group(0)
            if m.group(2) != wanted:
                problems.append("%s: table '%s' differs from its source" % (name, m.group(1)))
            return "<!-- table: %s -->\n%s<!-- end table -->" % (m.group(1), wanted)

        updated = BLOCK.sub(replace, text)
        if write and updated != text:
            open(page, "w").write(updated)
    return blocks, problems


def main():
    write = "--write" in sys.argv[1:]
    if set(sys.argv[1:]) - {"--write"}:
        sys.exit(__doc__)
    blocks, problems = process(write)
    for p in problems:
        print(("rewritten: " if write and ": error: " not in p else "") + p)
    print("%d generated tables, %d %s" % (blocks, len(problems), "rewritten" if write else "differ"))
    sys.exit(1 if any(": error: " in p or not write for p in problems) else 0)


if __name__ == "__main__":
    main()
