#!/usr/bin/env python3
"""Checks the relative links and images of the documentation (the docs-links test).

    check-doc-links.py [SOURCE_DIR]

Reads README.md and every .md file under docs/ (SOURCE_DIR defaults to this script's
parent folder). Each Markdown link [text](target) and image ![alt](target) outside code
spans, code blocks and HTML comments whose target is relative (no scheme such as https:)
must name a file or folder that exists, relative to the page; a #fragment must name a
heading of the target page (or of the page itself), spelled as GitHub spells heading
anchors. Prints every broken link with its page and line, and exits 1 when there is one.
"""
import os
import re
import sys

LINK = re.compile(r"!?\[(?:[^\[\]]|\[[^\]]*\])*\]\(([^()\s]+)(?:\s+\"[^\"]*\")?\)")
FENCE = re.compile(r"^\s*(`{3,}|~{3,})")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")


def prose_lines(text, keep_code_spans=False):
    """(line number, line) of the lines outside fenced code blocks and HTML comments, with
    inline code spans blanked (kept with keep_code_spans, for headings)."""
    fence = None
    in_comment = False
    for number, line in enumerate(text.split("\n"), 1):
        match = FENCE.match(line)
        if fence:
            if match and match.group(1)[0] == fence[0] and len(match.group(1)) >= len(fence):
                fence = None
            continue
        if match:
            fence = match.group(1)
            continue
        if in_comment:
            if "-->" in line:
                in_comment = False
                line = line.split("-->", 1)[1]
            else:
                continue
        line = re.sub(r"<!--.*?-->", "", line)
        if "<!--" in line:
            line = line.split("<!--", 1)[0]
            in_comment = True
        if keep_code_spans:
            yield number, line
            continue
        # Code spans: a run of backticks up to the same run.
        line = re.sub(r"(`+)(?:(?!\1).)+?\1", lambda m: " " * len(m.group(0)), line)
        yield number, line


def slug(heading):
    """The anchor GitHub gives a heading: lower case, punctuation dropped (letters, digits,
    spaces, hyphens and underscores kept), spaces turned into hyphens."""
    text = re.sub(r"`", "", heading)
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", text)  # a link's text
    text = re.sub(r"[*_~]{1,2}(?=\S)|(?<=\S)[*_~]{1,2}", "", text)  # emphasis marks
    text = re.sub(r"[^\w\- ]", "", text.strip().lower())
    return text.replace(" ", "-")


def anchors(path, cache={}):
    if path not in cache:
        seen = {}
        found = set()
        with open(path, encoding="utf-8") as f:
            for _, line in prose_lines(f.read(), keep_code_spans=True):
                match = HEADING.match(line)
                if not match:
                    continue
                base = slug(match.group(2))
                count = seen.get(base, 0)
                seen[base] = count + 1
                found.add(base if count == 0 else "%s-%d" % (base, count))
        cache[path] = found
    return cache[path]


def pages(root):
    yield os.path.join(root, "README.md")
    for folder, dirs, files in os.walk(os.path.join(root, "docs")):
        dirs.sort()
        for name in sorted(files):
            if name.endswith(".md"):
                yield os.path.join(folder, name)


def main():
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), ".."))
    broken = []
    links = 0
    files = 0
    for page in pages(root):
        files += 1
        with open(page, encoding="utf-8") as f:
            text = f.read()
        for number, line in prose_lines(text):
            for match in LINK.finditer(line):
                target = match.group(1)
                if target.startswith("<") and target.endswith(">"):
                    target = target[1:-1]
                if re.match(r"^[a-zA-Z][a-zA-Z0-9+.-]*:", target):
                    continue  # https:, mailto:, ...
                links += 1
                where = "%s:%d: %s" % (os.path.relpath(page, root), number, target)
                path, _, fragment = target.partition("#")
                resolved = os.path.normpath(os.path.join(os.path.dirname(page), path)) if path else page
                if path.startswith("/"):
                    broken.append(where + " (absolute path: use a path relative to the page)")
                elif not os.path.exists(resolved):
                    broken.append(where + " (no such file or folder)")
                elif fragment and resolved.endswith(".md") and fragment not in anchors(resolved):
                    broken.append(where + " (no heading '#%s' in %s)" % (fragment, os.path.relpath(resolved, root)))
                elif fragment and not resolved.endswith(".md"):
                    broken.append(where + " (a #fragment on a file that is not a Markdown page)")
    for line in broken:
        print("broken link: " + line)
    print("docs-links: %d pages, %d relative links and images, %d broken" % (files, links, len(broken)))
    return 1 if broken else 0


if __name__ == "__main__":
    sys.exit(main())
