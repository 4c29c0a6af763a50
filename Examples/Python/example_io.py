"""Files in and out for the examples, the same as `medial-axis` reads and writes.

open_input(path, demo) reads any surface format the command line reads (.vtp .vtk .ply
.stl .obj .off, picked by vtkMedialFileReader from the extension) and refuses any
other; without a path it returns `demo`. check_output(path, content) refuses, before
any work, a name whose extension vtkMedialFileWriter has no writer for; write(data,
path, content) writes by that extension. Mistakes end the example with a one-line
"error:" message and exit code 1.
"""
import sys

import medialaxis

Reader = medialaxis.vtkMedialFileReader
Writer = medialaxis.vtkMedialFileWriter
SURFACE, BALLS = Writer.SURFACE, Writer.BALLS


def fail(message):
    print(f"{sys.argv[0]}: error: {message}", file=sys.stderr)
    sys.exit(1)


def open_input(path, demo):
    """A source of the surface in `path`, or `demo` when path is None."""
    if path is None:
        return demo
    if not Reader.CanReadExtension(path, Reader.SURFACE):
        fail(f"cannot read '{path}': the readable formats are {Reader.GetExtensions(Reader.SURFACE)}")
    reader = Reader()
    reader.SetFileName(path)
    errors = []

    def on_error(caller, event, text):
        errors.append(str(text).strip().splitlines()[-1])

    on_error.CallDataType = "string0"
    reader.AddObserver("ErrorEvent", on_error)
    reader.Update()
    if errors or reader.GetOutput().GetNumberOfPoints() == 0:
        fail(f"cannot read '{path}': " + (errors[0] if errors else "no points"))
    return reader


def check_output(path, content):
    """Ends the example unless `path`'s extension has a writer for `content`."""
    if path is not None and not Writer.CanWriteExtension(path, content):
        fail(f"cannot write '{path}': the formats are {Writer.GetExtensions(content)}")


def write(data, path, content):
    """Writes `data` in the format `path`'s extension names."""
    writer = Writer()
    writer.SetInputData(data)
    writer.SetContent(content)
    writer.SetFileName(path)
    if not writer.Write():
        fail(f"cannot write '{path}'")
