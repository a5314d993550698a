#!/usr/bin/env python3
"""The interpreter tests no language itself: it asks its language object
(src/interpreter/language.hpp, docs/architecture.md "The language objects").

Fails when a file of src/interpreter/ other than language.{hpp,cpp} names an
identifier `ngc` or `grbl` (the booleans the language objects replaced) or
compares the dialect's language (`Language::k...`, `sw.language` other than
in the one `make_language` call), comments and string literals left out.

Usage: language_objects.py SOURCE_ROOT
"""
import pathlib
import re
import sys

LANGUAGE_FILES = {"language.hpp", "language.cpp"}
BOOLEAN = re.compile(r"\b(ngc|grbl)\b")
LANGUAGE_TEST = re.compile(r"\bLanguage::k\w+|\bsw\.language\b")
THE_CHOICE = "make_language(dialect.sw.language)"


def code_only(text):
    """The text with comments and string / character literals blanked."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            i = n if j < 0 else j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            i = n if j < 0 else j + 2
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            out.append(c + c)
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


def findings(name, text):
    found = []
    for number, line in enumerate(code_only(text).splitlines(), 1):
        if BOOLEAN.search(line):
            found.append(f"{name}:{number}: a language boolean: {line.strip()}")
        if LANGUAGE_TEST.search(line.replace(THE_CHOICE, "")):
            found.append(f"{name}:{number}: a test of the language: {line.strip()}")
    return found


def main():
    # The check itself: a boolean test and a comparison are found, the same
    # words in a comment or a string are not.
    bad = 'if (ngc || grbl) x(); // ngc\nif (dialect.sw.language == config::Language::kGrbl) y();\n'
    good = 'f(".ngc"); // ngc || grbl\nlang = make_language(dialect.sw.language);\n'
    if len(findings("bad", bad)) != 2 or findings("good", good):
        print("language_objects.py: the check does not tell the sample cases apart")
        return 1
    root = pathlib.Path(sys.argv[1]) / "src" / "interpreter"
    found = []
    for path in sorted(root.glob("*.[ch]pp")):
        if path.name not in LANGUAGE_FILES:
            found += findings(f"src/interpreter/{path.name}", path.read_text())
    for f in found:
        print(f)
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
