#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""The documentation against itself and the files it names: every relative
link in README.md and docs/ reaches a file (and, with '#', a heading of
it), and every number README.md states as a result is written in the same
words in docs/, where the command that remakes it is given."""
import glob
import os
import re
import sys

import checks
from checks import check
from foamCase import ROOT

LINK = re.compile(r"\]\(([^)\s]+)\)")
NUMBER = re.compile(r"[−+]?\d[\d,]*(?:\.\d+)?(?:e[−-]?\d+)?(?: %)?")


def markdown_files():
    return [os.path.join(ROOT, "README.md"), os.path.join(ROOT, "tests", "README.md")] + \
        sorted(glob.glob(os.path.join(ROOT, "docs", "**", "*.md"), recursive=True))


def anchor(heading):
    """the anchor a heading gets: lower case, punctuation dropped, spaces as hyphens"""
    text = re.sub(r"[^\w\- ]", "", heading.strip().lower())
    return text.replace(" ", "-")


def anchors(path):
    with open(path) as f:
        return {anchor(m.group(1)) for m in re.finditer(r"^#+\s+(.*)$", f.read(), re.M)}


def test_links():
    print("relative links in README.md and docs/ reach a file and a heading")
    n_links = 0
    for md in markdown_files():
        text = open(md).read()
        # code blocks hold no links
        text = re.sub(r"```.*?```", "", text, flags=re.S)
        for target in LINK.findall(text):
            if re.match(r"[a-z]+:", target):
                continue
            n_links += 1
            path, _, frag = target.partition("#")
            where = os.path.normpath(os.path.join(os.path.dirname(md), path)) if path else md
            name = "%s: %s" % (os.path.relpath(md, ROOT), target)
            if not os.path.exists(where):
                check(name + " exists", False, "(no %s)" % os.path.relpath(where, ROOT))
                continue
            if frag:
                check(name + " names a heading", frag in anchors(where),
                      "" if frag in anchors(where) else "(headings: %s)" % sorted(anchors(where))[:8])
    check("links found (the check sees them)", n_links > 30, "(%d)" % n_links)


def test_readme_results_in_docs():
    print("each number in README's results is in docs/ in the same words")
    readme = open(os.path.join(ROOT, "README.md")).read()
    section = re.search(r"^## Results\n(.*?)^## ", readme, re.S | re.M)
    check("README has a Results section", section is not None)
    if not section:
        return
    docs = " ".join(open(p).read() for p in glob.glob(os.path.join(ROOT, "docs", "**", "*.md"),
                                                        recursive=True))
    docs = re.sub(r"\s+", " ", docs)
    numbers = [n for n in NUMBER.findall(section.group(1)) if n not in ("2", "3", "4")]
    check("numbers found in README's results (the check sees them)", len(numbers) >= 5,
          "(%d)" % len(numbers))
    for n in numbers:
        check("README result '%s' is written in docs/" % n, n in docs)


def main():
    checks.run([test_links, test_readme_results_in_docs], sys.argv[1:])
    return checks.summary("docs")


if __name__ == "__main__":
    sys.exit(main())
