#!/usr/bin/env python3
"""Doxygen's input filter for the guide's pages (docs/Doxyfile.in, FILTER_PATTERNS *.md).

    doxygen-guide-filter.py SOURCE_DIR PAGE

Prints PAGE as Doxygen should read it, line for line (so that warnings keep their line
numbers). The pages are written for GitHub: links like `pruning.md#measures` and images
like `../images/x.png` are relative to the page. Doxygen 1.9 gives headings no anchors of
its own and keeps the HTML pages in one folder, so:
  - every heading below the page title gets an explicit id {#LABEL}, LABEL made of the
    page's path and the heading's GitHub anchor (docs/how-it-works/pruning.md#measures:
    md_docs_how_it_works_pruning__measures);
  - a link to a heading of a page ([text](pruning.md#measures), [text](#measures))
    becomes [text](@ref LABEL); links to whole pages Doxygen resolves itself;
  - an image's path becomes its file name, which Doxygen finds in IMAGE_PATH
    (docs/images/) and copies beside the HTML.
"""
import importlib.util
import os
import re
import sys

here = os.path.dirname(os.path.abspath(__file__))
spec = importlib.util.spec_from_file_location("check_doc_links", os.path.join(here, "check-doc-links.py"))
links = importlib.util.module_from_spec(spec)
spec.loader.exec_module(links)


def page_key(root, path):
    """Doxygen's page name for a Markdown file: md_ and its path, punctuation as _."""
    relative = os.path.splitext(os.path.relpath(path, root))[0]
    return "md_" + re.sub(r"[^A-Za-z0-9]", "_", relative)


def label(root, path, fragment):
    return page_key(root, path) + "__" + re.sub(r"[^A-Za-z0-9]", "_", fragment)


def main(argv):
    root, page = os.path.abspath(argv[1]), os.path.abspath(argv[2])
    text = open(page, encoding="utf-8").read()
    lines = text.split("\n")
    prose = dict(links.prose_lines(text, keep_code_spans=True))
    blanked = dict(links.prose_lines(text))  # code spans blanked: no links found in them
    seen = {}
    for number, line in prose.items():
        out = line
        heading = links.HEADING.match(line)
        if heading and len(heading.group(1)) > 1:
            base = links.slug(heading.group(2))
            count = seen.get(base, 0)
            seen[base] = count + 1
            fragment = base if count == 0 else "%s-%d" % (base, count)
            out = "%s {#%s}" % (line.rstrip(), label(root, page, fragment))
        elif heading:
            seen[links.slug(heading.group(2))] = 1

        def rewrite(match):
            whole, target = match.group(0), match.group(1)
            if re.match(r"^[a-zA-Z][a-zA-Z0-9+.-]*:", target):
                return whole
            path, _, fragment = target.partition("#")
            if whole.startswith("!"):
                return whole.replace("(" + target, "(" + os.path.basename(path), 1)
            resolved = os.path.normpath(os.path.join(os.path.dirname(page), path)) if path else page
            if fragment and resolved.endswith(".md"):
                return whole.replace("(" + target, "(@ref " + label(root, resolved, fragment), 1)
            return whole

        for match in reversed(list(links.LINK.finditer(blanked[number]))):
            original = re.match(links.LINK.pattern, line[match.start():match.end()])
            out = out[:match.start()] + rewrite(original) + out[match.end():]
        lines[number - 1] = out
    sys.stdout.write("\n".join(lines))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
