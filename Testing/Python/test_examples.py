#!/usr/bin/env python3
"""The Python examples do what they say (issue 17):

 1. Each example reads .obj, .ply, .stl and .off input (and .vtp, .vtk) and gives the
    answer of the shape in the file (twice the size of the example's default shape); an unknown input extension and an
    unknown output extension are refused with exit 1 and nothing written.
 2. Each example writes the format its output name says (read back by VTK's reader
    for that format).
 3. medial_axis_png.py draws the same picture as `medial-axis MESH --render`.

Arguments: EXAMPLES_DIR MEDIAL_AXIS SCRATCH_DIR (PYTHONPATH must reach medialaxis).
Exits 0 on success, 1 on failure.
"""
import os
import re
import subprocess
import sys

import numpy as np

import medialaxis
from checks import check, finish
from vtkmodules.vtkCommonCore import vtkIdList
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOGeometry import vtkOBJReader, vtkSTLReader
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkIOLegacy import vtkPolyDataReader
from vtkmodules.vtkIOPLY import vtkPLYReader
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

examples, cli, temp = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(temp, exist_ok=True)
def path(name):
    return os.path.join(temp, name)


def run(script, *args, code=0):
    result = subprocess.run([sys.executable, os.path.join(examples, script), *args], capture_output=True, text=True)
    check(result.returncode == code, f"{script} {' '.join(os.path.basename(a) for a in args)}: exit "
          f"{result.returncode}, expected {code}" + ("" if result.returncode == code else "\n" + result.stderr))
    return result


def shape(setter, scale=1.0):
    """A generated shape, scaled: the examples' own default shapes are not scaled, so
    the answers tell whether the file was read."""
    source = medialaxis.vtkMedialShapeSource()
    getattr(source, setter)()
    transform = vtkTransform()
    transform.Scale(scale, scale, scale)
    scaled = vtkTransformPolyDataFilter()
    scaled.SetTransform(transform)
    scaled.SetInputConnection(source.GetOutputPort())
    scaled.Update()
    return scaled.GetOutput()


def write_off(data, name):
    """OFF by hand: no VTK writer has it."""
    points = vtk_to_numpy(data.GetPoints().GetData())
    polys = data.GetPolys()
    cells = []
    ids = vtkIdList()
    polys.InitTraversal()
    while polys.GetNextCell(ids):
        cells.append([ids.GetId(k) for k in range(ids.GetNumberOfIds())])
    with open(name, "w") as f:
        f.write(f"OFF\n{len(points)} {len(cells)} 0\n")
        for p in points:
            f.write(f"{p[0]!r} {p[1]!r} {p[2]!r}\n")
        for c in cells:
            f.write(f"{len(c)} " + " ".join(map(str, c)) + "\n")


def write_all(data, stem, extensions):
    """`data` as stem.EXT for every extension; returns the file names."""
    names = []
    for ext in extensions:
        name = path(f"{stem}.{ext}")
        if ext == "off":
            write_off(data, name)
        else:
            writer = medialaxis.vtkMedialFileWriter()
            writer.SetInputData(data)
            writer.SetFileName(name)
            check(writer.Write() == 1, f"wrote {os.path.basename(name)}")
        names.append(name)
    return names


SURFACE_READERS = {"vtp": vtkXMLPolyDataReader, "vtk": vtkPolyDataReader, "stl": vtkSTLReader,
                   "ply": vtkPLYReader, "obj": vtkOBJReader}


def read_back(name):
    reader = SURFACE_READERS[name.rsplit(".", 1)[1]]()
    reader.SetFileName(name)
    reader.Update()
    return reader.GetOutput()


def balls_back(name):
    reader = medialaxis.vtkMedialFileReader()
    reader.SetContentToBalls()
    reader.SetFileName(name)
    reader.Update()
    return reader.GetOutput()


formats = ["obj", "ply", "stl", "off", "vtp", "vtk"]
box_files = write_all(shape("SetShapeToBox", 2.0), "box", formats)  # 6 x 4 x 2


def check_ball_outputs(script, stem, extensions):
    """`script` on box.obj writes OUT in each ball format, read back with its radii."""
    for ext in extensions:
        out = path(f"{stem}.{ext}")
        run(script, path("box.obj"), out)
        balls = balls_back(out)
        check(balls.GetNumberOfPoints() > 4 and balls.GetPointData().GetArray("Radius") is not None,
              f"{script} OUT.{ext}: {balls.GetNumberOfPoints()} points with Radius read back as .{ext}")


# structure_3d.py: the four junction vertices of a box twice the default one's size
# (6 x 4 x 2) from every format; OUT in each ball format.
junction = r"4 junction vertices\njunction \(-2\.000000, -1\.000000, \+0\.000000\)  radius 1\.000000  governors 4"
for name in box_files:
    out = path(f"box-exact-from-{name.rsplit('.', 1)[1]}.ma")
    result = run("structure_3d.py", name, out)
    check(re.search(junction, result.stdout) is not None, f"structure_3d.py {os.path.basename(name)}: the 4 junctions")
check_ball_outputs("structure_3d.py", "box-exact", ("vtp", "vtk", "ply", "ma", "csv"))

# medial_mesh.py: the medial mesh of the 6 x 4 x 2 box (largest ball radius 1; the
# example's own default shape is the jack) from every format, one component with the
# solid's Euler characteristic 1; OUT in each ball format.
mesh_topology = r"Euler characteristic 1, 1 component\(s\); the solid's 1 and 1"
for name in box_files:
    ext = name.rsplit(".", 1)[1]
    out = path(f"box-mesh-from-{ext}.ma")
    result = run("medial_mesh.py", name, out)
    check(re.search(mesh_topology, result.stdout) is not None, f"medial_mesh.py {os.path.basename(name)}: {result.stdout}")
    radius = balls_back(out).GetPointData().GetArray("Radius").GetRange()[1]
    check(0.99 <= radius <= 1.0 + 1e-9, f"medial_mesh.py {os.path.basename(name)}: largest radius {radius}, 1 expected")
check_ball_outputs("medial_mesh.py", "box-mesh", ("vtp", "ply", "csv"))

# junction_graph.py: a square frame (a hole) in every format that holds polygons, a
# triangle in STL (triangles only).
# The frame is twice the default one's size: junctions at (+-2 sqrt 2, +-2 sqrt 2), radius 4 - 2 sqrt 2.
frame_junction = r"junction \(-2\.828427, -2\.828427\)  radius 1\.171573  governors 3.*4 end points, 8 linear and 8 parabolic arcs"
for name in write_all(shape("SetShapeToSquareFrame", 2.0), "frame", ["obj", "ply", "off", "vtp", "vtk"]):
    result = run("junction_graph.py", name, path("frame-graph.vtk"))
    check(re.search(frame_junction, result.stdout, re.S) is not None, f"junction_graph.py {os.path.basename(name)}")
with open(path("triangle.stl"), "w") as f:
    f.write("solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 4 0 0\nvertex 0 3 0\nendloop\n"
            "endfacet\nendsolid t\n")
result = run("junction_graph.py", path("triangle.stl"), path("triangle-graph.ma"))
check("1 end points" not in result.stdout and re.search(r"^junction .* governors 3$", result.stdout, re.M) is not None
      and "3 end points" in result.stdout, "junction_graph.py triangle.stl: one junction, 3 end points")
with open(path("triangle-graph.ma")) as f:
    check(f.readline().split()[0] == "4", "junction_graph.py OUT.ma writes the .ma format")

# reconstruct.py: the jack from every format, the same figures; OUT in each surface format.
jack = shape("SetShapeToJack", 2.0)
figures = {}
for name in write_all(jack, "jack", ["obj", "ply", "stl", "off"]):
    ext = name.rsplit(".", 1)[1]
    out = path(f"jack-rebuilt-from-{ext}.{ext if ext != 'off' else 'vtp'}")
    result = run("reconstruct.py", name, out)
    figures[ext] = re.search(r"reconstruction to original: max ([0-9.]+)%", result.stdout)
    rebuilt = read_back(out)
    width = rebuilt.GetBounds()[1] - rebuilt.GetBounds()[0]
    check(figures[ext] is not None and float(figures[ext].group(1)) < 0.5 and rebuilt.GetNumberOfPolys() > 1000
          and abs(width - 2 * 3.797) < 0.05,
          f"reconstruct.py {os.path.basename(name)}: {result.stdout.splitlines()[0] if result.stdout else ''}; "
          f"{os.path.basename(out)} read back with {rebuilt.GetNumberOfPolys()} triangles, {width:.3f} wide (the input 7.595)")
with open(path("jack-rebuilt-from-stl.stl"), "rb") as f:
    check(b"<VTKFile" not in f.read(100), "reconstruct.py OUT.stl is not VTK XML")
with open(path("jack-rebuilt-from-off.vtp"), "rb") as f:
    # Appended raw binary: VTK leaves out the XML declaration, the file starts at VTKFile.
    check(b'<VTKFile type="PolyData"' in f.read(100), "reconstruct.py OUT.vtp is VTK XML")

# Refusals: an unknown input extension, an unknown output extension; nothing written.
with open(path("notes.txt"), "w") as f:
    f.write("not a mesh\n")
for script, args in (("reconstruct.py", [path("notes.txt")]), ("structure_3d.py", [path("notes.txt")]),
                     ("junction_graph.py", [path("notes.txt")]), ("medial_mesh.py", [path("notes.txt")]),
                     ("medial_mesh.py", [path("box.obj"), path("out.stl")]),
                     ("medial_axis_png.py", [path("notes.txt"), path("notes.png")]),
                     ("reconstruct.py", [path("box.obj"), path("out.xyz")]),
                     ("structure_3d.py", [path("box.obj"), path("out.stl")]),
                     ("junction_graph.py", [path("frame.obj"), path("out.obj")]),
                     ("medial_axis_png.py", [path("box.obj"), path("out.jpg")])):
    result = run(script, *args, code=1)
    check("error:" in result.stderr and (args[-1].endswith(".txt") or not os.path.exists(args[-1])),
          f"{script} refuses {os.path.basename(args[-1])}: {result.stderr.strip()}")

# medial_axis_png.py: every format, and the same picture as the command line.
for name in [path("jack.obj"), path("jack.ply"), path("jack.stl"), path("jack.off")]:
    out = path(f"png-from-{name.rsplit('.', 1)[1]}.png")
    result = run("medial_axis_png.py", name, out)
    check(os.path.exists(out) and "10000 medial points" in result.stdout, f"medial_axis_png.py {os.path.basename(name)}")
cli_png = path("cli.png")
subprocess.run([cli, path("jack.obj"), "--render", cli_png, "--quiet"], check=False)


def pixels(name):
    reader = vtkPNGReader()
    reader.SetFileName(name)
    reader.Update()
    image = reader.GetOutput()
    return image.GetDimensions(), vtk_to_numpy(image.GetPointData().GetScalars()).astype(int)


(size_a, a), (size_b, b) = pixels(cli_png), pixels(path("png-from-obj.png"))
differing = np.count_nonzero(np.abs(a - b).max(axis=1) > 8) if size_a == size_b else -1
check(size_a == size_b and differing <= 0.001 * len(a),
      f"medial_axis_png.py and medial-axis --render: sizes {size_a[:2]} and {size_b[:2]}, {differing} pixels differ")

finish()
