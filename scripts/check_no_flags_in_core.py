#!/usr/bin/env python3
"""Fails if a string literal in core/ or gpu/ names a command-line flag ("--directions").

core/ and gpu/ receive typed settings; an error names the quantity (ts::QuantityError) and the
command line maps it to the flag the user typed (app/options/quantity_flags.cpp). Comments may
name flags (they say why); string literals, which reach the user, may not.

Usage: check_no_flags_in_core.py SOURCE_ROOT   (exit 0: none; 1: each offence listed)
"""
import pathlib
import re
import sys

FLAG = re.compile(r"(?<![A-Za-z0-9-])--[A-Za-z][A-Za-z0-9-]*")
SUFFIXES = {".cpp", ".hpp", ".h", ".inc", ".comp", ".glsl"}


def string_literals(text):
    """(line, literal body) for every string literal outside comments (raw strings included)."""
    out, i, line, n = [], 0, 1, len(text)
    while i < n:
        c = text[i]
        if c == "\n":
            line += 1
            i += 1
        elif text.startswith("//", i):
            while i < n and text[i] != "\n":
                i += 1
        elif text.startswith("/*", i):
            end = text.find("*/", i + 2)
            end = n if end < 0 else end + 2
            line += text.count("\n", i, end)
            i = end
        elif text.startswith('R"', i) and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            open_paren = text.find("(", i)
            delim = text[i + 2:open_paren]
            end = text.find(")" + delim + '"', open_paren)
            end = n if end < 0 else end + len(delim) + 2
            out.append((line, text[open_paren + 1:end]))
            line += text.count("\n", i, end)
            i = end
        elif c == "'":  # a character literal ('"' must not open a string)
            j = i + 1
            while j < n and text[j] != "'":
                j += 2 if text[j] == "\\" else 1
            i = j + 1
        elif c == '"':
            j = i + 1
            while j < n and text[j] != '"' and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            out.append((line, text[i + 1:j]))
            i = j + 1
        else:
            i += 1
    return out


def offences(text):
    return [(line, body) for line, body in string_literals(text) if FLAG.search(body)]


def self_test():
    # The detector itself must catch what it is for, or this check could never fail.
    assert offences('throw InputError("--directions: at least 4");')
    assert offences('f(R"(use --cpu)");')
    assert offences('x = "a" "--b";')
    assert not offences('// "--directions" in a comment\n/* "--x" */ int a = 0;')
    assert not offences("char c = '\"'; // --x\nint b;")
    assert not offences('printf("%d -- %d", 1, 2); y = "a--b";')


def main():
    self_test()
    root = pathlib.Path(sys.argv[1])
    found = []
    for folder in ("core", "gpu"):
        for path in sorted((root / folder).rglob("*")):
            if path.suffix in SUFFIXES and path.is_file():
                for line, body in offences(path.read_text(errors="replace")):
                    found.append(f"{path.relative_to(root)}:{line}: \"{body}\"")
    for f in found:
        print(f)
    if found:
        print(f"{len(found)} string literal(s) in core/ or gpu/ name a command-line flag: name the quantity "
              "(ts::QuantityError) and map it to the flag in app/options/quantity_flags.cpp")
        return 1
    print("no flag named in core/ or gpu/ string literals")
    return 0


if __name__ == "__main__":
    sys.exit(main())
