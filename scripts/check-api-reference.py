#!/usr/bin/env python3
"""The docs-api-reference test: the API reference builds without a single Doxygen warning.

    check-api-reference.py DOXYGEN DOXYFILE WORK_DIR HEADER...

Runs DOXYGEN with the build's DOXYFILE (the one `cmake --build build --target docs` uses),
writing into WORK_DIR and its warnings into WORK_DIR/warnings.log, and fails when that log
is not empty: an undocumented public class, method, enum or constant, a comment naming a
parameter the function does not have, a reference that does not resolve (in a header or in
one of the guide's pages, which the reference includes). It also fails
when one of the HEADERs (the installed headers) declares members with a VTK macro
(vtkSet...Macro, vtkGet...Macro, vtkBooleanMacro, vtkTypeMacro, ...) that the Doxyfile's
PREDEFINED does not expand: Doxygen would show such a line as a strange member instead of
the methods it declares.
"""
import os
import re
import shutil
import subprocess
import sys

DECLARING_MACRO = re.compile(r"^\s*(vtk(?:Set|Get|Boolean|Type|AbstractType|BaseType)\w*Macro)\s*\(", re.M)


def predefined_macros(doxyfile_text):
    """Names of the function-like macros that the Doxyfile's PREDEFINED defines."""
    match = re.search(r"^PREDEFINED\s*=(.*?)(?=^\S)", doxyfile_text, re.M | re.S)
    return set(re.findall(r"\"?(\w+)\([^)]*\)=", match.group(1) if match else ""))


def main(argv):
    if len(argv) < 5:
        sys.exit(__doc__)
    doxygen, doxyfile, work = argv[1:4]
    headers = argv[4:]
    config = open(doxyfile, encoding="utf-8").read()

    problems = []
    known = predefined_macros(config)
    for header in headers:
        text = open(header, encoding="utf-8").read()
        for match in DECLARING_MACRO.finditer(text):
            if match.group(1) not in known:
                line = text.count("\n", 0, match.start()) + 1
                problems.append(f"{header}:{line}: {match.group(1)} is not expanded by the Doxyfile's "
                                "PREDEFINED (docs/Doxyfile.in): add it there")

    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    log = os.path.join(work, "warnings.log")
    overrides = f'\nOUTPUT_DIRECTORY = "{work}"\nWARN_LOGFILE = "{log}"\nWARN_AS_ERROR = NO\n'
    run = subprocess.run([doxygen, "-"], input=config + overrides, text=True, cwd=work,
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    print(run.stdout, end="")
    warnings = open(log, encoding="utf-8").read().strip() if os.path.exists(log) else ""
    if run.returncode != 0:
        problems.append(f"doxygen exited with {run.returncode}")
    if warnings:
        problems += warnings.split("\n")
    if problems:
        print("\n".join(problems))
        print(f"FAIL: {len(problems)} problem(s) in the API reference: document each member named above, or fix "
              "the guide page Doxygen could not read (docs/building.md#the-api-reference)")
        return 1
    print(f"API reference: {len(headers)} headers, no warning ({os.path.join(work, 'html', 'index.html')})")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
