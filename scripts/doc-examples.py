#!/usr/bin/env python3
"""The documentation's runnable examples: list them, run a page's, check their list.

    doc-examples.py list SOURCE_DIR
    doc-examples.py run SOURCE_DIR PAGE WORK_DIR --build BUILD_DIR --pythonpath DIR
                        [--python PYTHON] [--prefix INSTALL_PREFIX] [--cmake CMAKE]
    doc-examples.py check-list SOURCE_DIR [--write] [--registered TEST...]
    doc-examples.py install BUILD_DIR PREFIX [--cmake CMAKE]

A code block of README.md or of a page under docs/ is run by the test suite when the word
after its language is `runnable` (the convention of docs/index.md):

    ```sh runnable          shell commands, run with `sh -e`
    ```python runnable      a Python script
    ```cpp runnable         a whole C++ program (with main)
    ```cpp runnable-fragment
                            C++ statements, run as the body of main() after every
                            installed medialaxis header and the usual VTK ones are included

`run` runs one page's blocks in their order in WORK_DIR (emptied first), a scratch folder
where `build` points at BUILD_DIR and `Examples` at the source tree's examples, so the blocks
say `build/bin/medial-axis` as a reader would, and later blocks may read what earlier ones
wrote. The C++ blocks are compiled first, against INSTALL_PREFIX (the build installed there
by the doc-examples-install test) with find_package(medialaxis); the folder also holds
`mesh.ply`, a closed surface (the demo shape), for fragments that read a file. Python runs
under PYTHON with PYTHONPATH=DIR. DISPLAY is unset: a block that renders says `xvfb-run -a`
itself. A block fails when it exits non-zero or prints a VTK error ("ERR| " or "ERROR: In ").

`check-list` compares the list of examples in docs/building.md (between
<!-- doc-examples:begin --> and <!-- doc-examples:end -->) with the pages, and with the
tests CMake registered (--registered: a page whose test is missing needs CMake re-run);
`--write` rewrites the list. `install` installs BUILD_DIR into PREFIX, emptied first.
"""
import glob
import os
import re
import shutil
import subprocess
import sys
import time

FENCE = re.compile(r"^(`{3,})(\w+)[ \t]*([^\n`]*)$")
LIST_PAGE = os.path.join("docs", "building.md")
BEGIN, END = "<!-- doc-examples:begin -->", "<!-- doc-examples:end -->"
VTK_ERROR = re.compile(r"^ERROR: In |\bERR\| ", re.M)  # VTK 9.1 logs errors as "ERR| "


def pages(root):
    found = [os.path.join(root, "README.md")]
    found += sorted(glob.glob(os.path.join(root, "docs", "**", "*.md"), recursive=True))
    return found


def blocks(page):
    """[(line, language, kind, code)] of the page's runnable blocks, kind 'runnable' or
    'runnable-fragment'."""
    found = []
    lines = open(page, encoding="utf-8").read().split("\n")
    index = 0
    while index < len(lines):
        match = FENCE.match(lines[index])
        if not match:
            index += 1
            continue
        fence, language, words = match.group(1), match.group(2), match.group(3).split()
        end = index + 1
        while end < len(lines) and not lines[end].startswith(fence):
            end += 1
        kinds = [w for w in words if w.startswith("runnable")]
        if kinds:
            found.append((index + 1, language, kinds[0], "\n".join(lines[index + 1:end]) + "\n"))
        index = end + 1
    return found


def test_name(root, page):
    relative = os.path.relpath(page, root)
    if relative.startswith("docs" + os.sep):
        relative = relative[len("docs" + os.sep):]
    return "doc-example-" + re.sub(r"[^a-z0-9]+", "-", os.path.splitext(relative)[0].lower()).strip("-")


def describe(block):
    _, language, kind, code = block
    if language == "sh":
        commands = [l for l in code.split("\n") if l.strip() and not l.strip().startswith("#")]
        return "sh (%d command%s)" % (len(commands), "" if len(commands) == 1 else "s")
    if language == "cpp":
        return "C++ fragment" if kind == "runnable-fragment" else "C++ program"
    return {"python": "Python"}.get(language, language)


def runnable_pages(root):
    return [(page, blocks(page)) for page in pages(root) if blocks(page)]


def command_list(args):
    root = os.path.abspath(args[0])
    for page, found in runnable_pages(root):
        print("%s\t%s\t%s" % (test_name(root, page), os.path.relpath(page, root), ", ".join(map(describe, found))))
    return 0


def expected_list(root):
    rows = ["| test | page | blocks, in order |", "|---|---|---|"]
    list_dir = os.path.dirname(os.path.join(root, LIST_PAGE))
    for page, found in runnable_pages(root):
        link = os.path.relpath(page, list_dir)
        rows.append("| `%s` | [%s](%s) | %s |" % (test_name(root, page), os.path.relpath(page, root), link,
                                                  ", ".join(map(describe, found))))
    return "\n".join(rows)


def command_check_list(args):
    root = os.path.abspath(args[0])
    path = os.path.join(root, LIST_PAGE)
    text = open(path, encoding="utf-8").read()
    if BEGIN not in text or END not in text:
        print("FAIL %s: no %s ... %s block" % (LIST_PAGE, BEGIN, END))
        return 1
    head, rest = text.split(BEGIN, 1)
    current, tail = rest.split(END, 1)
    expected = expected_list(root)
    if "--write" in args[1:]:
        with open(path, "w", encoding="utf-8") as f:
            f.write(head + BEGIN + "\n" + expected + "\n" + END + tail)
        print("wrote the list of examples to " + LIST_PAGE)
        return 0
    if current.strip() != expected:
        print("FAIL the list of examples in %s is not current; the pages have:\n%s\n"
              "(rewrite it with: python3 scripts/doc-examples.py check-list . --write)" % (LIST_PAGE, expected))
        return 1
    if "--registered" in args:
        registered = set(args[args.index("--registered") + 1:])
        wanted = set(test_name(root, page) for page, _ in runnable_pages(root))
        if registered != wanted:
            print("FAIL the tests registered (%s) are not the pages' (%s): re-run cmake"
                  % (" ".join(sorted(registered)), " ".join(sorted(wanted))))
            return 1
    print("doc-examples-list: %d pages with runnable blocks, listed in %s" % (expected.count("\n") - 1, LIST_PAGE))
    return 0


def option(args, name, default=None):
    if name in args:
        return args[args.index(name) + 1]
    return default


CPP_FRAGMENT = """// Generated by scripts/doc-examples.py from {page}, line {line} (a cpp runnable-fragment):
// the fragment is the body of main(), after every installed medialaxis header.
{includes}
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <cstdio>
#include <iostream>

int main()
{{
{code}  return 0;
}}
"""

WRITE_MESH = """// The closed surface the C++ fragments may read: the demo shape, as mesh.ply.
#include "vtkMedialFileWriter.h"
#include "vtkMedialShapeSource.h"
#include "vtkNew.h"

int main()
{
  vtkNew<vtkMedialShapeSource> shape;
  vtkNew<vtkMedialFileWriter> writer;
  writer->SetInputConnection(shape->GetOutputPort());
  writer->SetFileName("mesh.ply");
  return writer->Write() ? 0 : 1;
}
"""


def run(command, cwd, env, what, echo=True):
    """Runs a command, echoing its output (only when it fails unless echo); returns
    (ok, seconds)."""
    start = time.time()
    result = subprocess.run(command, cwd=cwd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    seconds = time.time() - start
    ok = result.returncode == 0
    if echo or not ok:
        sys.stdout.write(result.stdout)
    if ok and VTK_ERROR.search(result.stdout):
        print("FAIL %s printed a VTK error (ERR| or ERROR: In)" % what)
        ok = False
    elif not ok:
        print("FAIL %s exited with %d" % (what, result.returncode))
    return ok, seconds


def build_cpp(root, page, found, work, prefix, cmake, env):
    """Compiles the page's C++ blocks (and the mesh writer) in one project; returns
    {line: executable} or None."""
    project = os.path.join(work, "cpp")
    os.makedirs(project)
    headers = sorted(os.path.basename(h) for h in glob.glob(os.path.join(prefix, "include", "medialaxis", "vtkMedial*.h")))
    includes = "\n".join('#include "%s"' % h for h in headers)
    lines = ["cmake_minimum_required(VERSION 3.16)", "project(doc_examples LANGUAGES CXX)",
             "find_package(medialaxis REQUIRED)", "add_executable(write-mesh write-mesh.cxx)",
             "target_link_libraries(write-mesh PRIVATE ${medialaxis_MODULES})"]
    with open(os.path.join(project, "write-mesh.cxx"), "w") as f:
        f.write(WRITE_MESH)
    targets = {}
    for line, language, kind, code in found:
        if language != "cpp":
            continue
        name = "block-line-%d" % line
        source = code
        if kind == "runnable-fragment":
            indented = "".join("  " + l + "\n" if l.strip() else "\n" for l in code.rstrip("\n").split("\n"))
            source = CPP_FRAGMENT.format(page=os.path.relpath(page, root), line=line, includes=includes, code=indented)
        with open(os.path.join(project, name + ".cxx"), "w") as f:
            f.write(source)
        lines += ["add_executable(%s %s.cxx)" % (name, name),
                  "target_link_libraries(%s PRIVATE ${medialaxis_MODULES})" % name]
        targets[line] = os.path.join(project, "build", name)
    with open(os.path.join(project, "CMakeLists.txt"), "w") as f:
        f.write("\n".join(lines) + "\n")
    generator = ["-G", "Ninja"] if shutil.which("ninja") else []
    ok, seconds = run([cmake, "-S", project, "-B", os.path.join(project, "build"), "-DCMAKE_BUILD_TYPE=Release",
                       "-DCMAKE_PREFIX_PATH=" + prefix] + generator, work, env, "configuring the C++ blocks", echo=False)
    if ok:
        ok, more = run([cmake, "--build", os.path.join(project, "build")], work, env, "compiling the C++ blocks",
                       echo=False)
        seconds += more
    print("-- C++ blocks configured and compiled in %.1f s" % seconds)
    if not ok:
        return None
    ok, _ = run([os.path.join(project, "build", "write-mesh")], work, env, "writing mesh.ply")
    return targets if ok else None


def command_run(args):
    root, page, work = os.path.abspath(args[0]), os.path.abspath(args[1]), os.path.abspath(args[2])
    build = os.path.abspath(option(args, "--build"))
    pythonpath = os.path.abspath(option(args, "--pythonpath", os.path.join(build, "lib", "python3", "dist-packages")))
    python = option(args, "--python", "/usr/bin/python3")
    prefix = option(args, "--prefix")
    cmake = option(args, "--cmake", "cmake")
    found = blocks(page)
    if not found:
        print("FAIL %s has no runnable block" % page)
        return 1

    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    os.symlink(build, os.path.join(work, "build"))
    os.symlink(os.path.join(root, "Examples"), os.path.join(work, "Examples"))
    env = dict(os.environ)
    env.pop("DISPLAY", None)
    env["PYTHONPATH"] = pythonpath + (os.pathsep + env["PYTHONPATH"] if env.get("PYTHONPATH") else "")

    executables = {}
    if any(language == "cpp" for _, language, _, _ in found):
        if not prefix or not os.path.isdir(prefix):
            print("FAIL %s has C++ blocks and no install prefix (%s): run the doc-examples-install test first"
                  % (page, prefix))
            return 1
        executables = build_cpp(root, page, found, work, os.path.abspath(prefix), cmake, env)
        if executables is None:
            return 1

    relative = os.path.relpath(page, root)
    for number, (line, language, kind, code) in enumerate(found, 1):
        what = "%s line %d (%s %s)" % (relative, line, language, kind)
        print("-- %s" % what)
        if language == "sh":
            script = os.path.join(work, "block-line-%d.sh" % line)
            with open(script, "w") as f:
                f.write(code)
            command = ["sh", "-e", "-x", script]
        elif language == "python":
            script = os.path.join(work, "block-line-%d.py" % line)
            with open(script, "w") as f:
                f.write(code)
            command = [python, script]
        elif language == "cpp":
            command = [executables[line]]
        else:
            print("FAIL %s: no way to run a %s block" % (what, language))
            return 1
        ok, seconds = run(command, work, env, what)
        print("-- %s: %s in %.1f s" % (what, "ok" if ok else "failed", seconds))
        if not ok:
            return 1
    print("%s: %d runnable blocks ran" % (relative, len(found)))
    return 0


def command_install(args):
    build, prefix = os.path.abspath(args[0]), os.path.abspath(args[1])
    shutil.rmtree(prefix, ignore_errors=True)
    ok, seconds = run([option(args, "--cmake", "cmake"), "--install", build, "--prefix", prefix], build, dict(os.environ),
                      "cmake --install", echo=False)
    print("installed %s into %s in %.1f s" % (build, prefix, seconds))
    return 0 if ok else 1


def main(argv):
    commands = {"list": command_list, "run": command_run, "check-list": command_check_list,
                "install": command_install}
    if len(argv) < 3 or argv[1] not in commands:
        sys.exit(__doc__)
    return commands[argv[1]](argv[2:])


if __name__ == "__main__":
    sys.exit(main(sys.argv))
