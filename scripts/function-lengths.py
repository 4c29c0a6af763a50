#!/usr/bin/env python3
"""List C++ function lengths (lines from the signature to the closing brace).

A brace counter, good enough for this code base: comments, strings and
character literals are blanked first, then every `{` met at namespace or class
scope whose header holds a `)` opens a function body. Lambdas and local
structs count toward the function that holds them.

    scripts/function-lengths.py [--top N] [--min LINES] [paths...]

Paths default to Filters/ Readers/ Examples/ Testing/; folders are searched
for .h/.cxx files (build folders are skipped).
"""
import argparse
import os
import re
import sys


def blank_comments_and_strings(text):
    """Replace comments and literals with spaces, keeping newlines."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == 'R' and text.startswith('R"', i):
            m = re.match(r'R"([^(]*)\(', text[i:])
            end = ')' + m.group(1) + '"'
            j = text.find(end, i)
            j = n if j < 0 else j + len(end)
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c in "\"'":
            # A digit separator (1'000) is not a literal.
            if c == "'" and i > 0 and text[i - 1].isalnum():
                out.append(" ")
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            j = min(j + 1, n)
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == "#" and (i == 0 or text[i - 1] == "\n"):
            j = i
            while True:  # preprocessor lines, with continuations
                k = text.find("\n", j)
                if k < 0:
                    k = n
                    break
                if text[k - 1] != "\\":
                    break
                j = k + 1
            out.append(re.sub(r"[^\n]", " ", text[i:k]))
            i = k
        else:
            out.append(c)
            i += 1
    return "".join(out)


NAME = re.compile(r"((?:[A-Za-z_]\w*\s*::\s*)*~?(?:operator\s*[^\s(]+|[A-Za-z_]\w*))\s*\(")
CONTAINER = re.compile(r"\b(namespace|class|struct|union|extern)\b")


def functions(path):
    text = blank_comments_and_strings(open(path, encoding="utf-8", errors="replace").read())
    results = []
    stack = []  # (kind, name, start line)
    header_start = 0
    line = 1
    for i, c in enumerate(text):
        if c == "\n":
            line += 1
        if c not in "{};":
            continue
        in_function = any(kind == "function" for kind, _, _ in stack)
        if c == "{":
            if in_function:
                stack.append(("block", None, line))
            else:
                header = text[header_start:i]
                if ")" in header and not re.search(r"\b(enum)\b", header) and not (
                    CONTAINER.search(header) and header.rfind(")") < CONTAINER.search(header).start()):
                    m = NAME.search(header)
                    name = re.sub(r"\s+", "", m.group(1)) if m else "?"
                    first = line - header[header.find(m.group(1)) if m else 0:].count("\n") if m else line
                    stack.append(("function", name, first))
                elif CONTAINER.search(header):
                    m = re.search(r"\b(?:class|struct|union)\s+(?:\w+\s+)?([A-Za-z_]\w*)\s*(?::[^:]|$|final)", header.strip() + " ")
                    stack.append(("container", m.group(1) if m else None, line))
                else:
                    stack.append(("other", None, line))
            header_start = i + 1
        elif c == "}":
            if stack:
                kind, name, start = stack.pop()
                if kind == "function":
                    owners = [n for k, n, _ in stack if k == "container" and n]
                    qualified = "::".join(owners + [name]) if owners and "::" not in name else name
                    results.append((line - start + 1, path, qualified, start))
            header_start = i + 1
        else:  # ';'
            if not in_function:
                header_start = i + 1
    return results


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("paths", nargs="*", default=["Filters", "Readers", "Examples", "Testing"])
    parser.add_argument("--top", type=int, default=10)
    parser.add_argument("--min", type=int, default=0)
    args = parser.parse_args()
    files = []
    for p in args.paths:
        if os.path.isdir(p):
            for root, dirs, names in os.walk(p):
                dirs[:] = [d for d in dirs if not d.startswith("build")]
                files += [os.path.join(root, f) for f in names if f.endswith((".h", ".cxx"))]
        else:
            files.append(p)
    rows = []
    for f in sorted(files):
        rows += functions(f)
    rows.sort(key=lambda r: (-r[0], r[1], r[3]))
    rows = [r for r in rows if r[0] >= args.min]
    if args.top > 0:
        rows = rows[: args.top]
    for length, path, name, start in rows:
        print(f"{length:5d}  {path}:{start}  {name}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
