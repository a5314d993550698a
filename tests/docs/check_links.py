#!/usr/bin/env python3
"""Checks the relative links of the project's Markdown files: every linked file
exists, and every #section names a heading of the linked page (GitHub's rule:
lower case, punctuation dropped, spaces to '-', '-1', '-2' for repeats).

Usage: check_links.py [REPO_ROOT]   (exit 1 and one line per broken link)
"""
import glob
import os
import re
import sys

LINK = re.compile(r"\]\(([^)\s]+)\)")


def anchors(path):
    found, seen, in_code = set(), {}, False
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.startswith("```"):
                in_code = not in_code
            if in_code:
                continue
            m = re.match(r"#+\s+(.*)", line)
            if not m:
                continue
            slug = re.sub(r"[^\w\- ]", "", m.group(1).strip().lower()).replace(" ", "-")
            n = seen.get(slug, 0)
            seen[slug] = n + 1
            found.add(slug if n == 0 else f"{slug}-{n}")
    return found


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..")
    os.chdir(root)
    pages = ["README.md"] + sorted(glob.glob("docs/*.md") + glob.glob("bench/*.md")
                                   + glob.glob("examples/**/*.md", recursive=True)
                                   + glob.glob("tests/**/*.md", recursive=True))
    broken = 0
    for page in pages:
        with open(page, encoding="utf-8") as f:
            text = f.read()
        for m in LINK.finditer(text):
            target = m.group(1)
            if re.match(r"[a-z]+:", target):
                continue
            path, _, section = target.partition("#")
            linked = os.path.normpath(os.path.join(os.path.dirname(page), path)) if path else page
            line = text.count("\n", 0, m.start()) + 1
            if not os.path.exists(linked):
                print(f"{page}:{line}: {target}: no such file")
                broken += 1
            elif section and linked.endswith(".md") and section not in anchors(linked):
                print(f"{page}:{line}: {target}: no such section in {linked}")
                broken += 1
    print(f"{len(pages)} pages, {broken} broken links")
    return 1 if broken else 0


if __name__ == "__main__":
    sys.exit(main())
