#!/usr/bin/env python3
"""The command line as a user relies on it (issue 17), checked from the files it
writes and what it prints:

 1. Ball formats: balls written with -o as .ma, .ply, .vtp, .vtk and .csv and read
    back with --balls give the same file again byte for byte (.ma, .ply) and the
    same centres and radii (all); .ma -> .ply -> .ma round-trips exactly.
 2. --balls with a hand-written Q-MAT-style .ma (header, v/e/f records, an extra
    column, a comment): --reconstruct writes each surface format its name says,
    and the surface is the union of the file's balls (bounds within two voxels).
 3. Flags: --flag=value, -n=VALUE, 10k and 1.5k, --version; a run that writes
    nothing and a switch given a value are refused before any work.
 4. Progress: without a terminal one line per finished stage (reading, preparation,
    sampling, reconstruction, thickness, writing); --quiet prints nothing on stderr;
    on a terminal (a pty) the bar is redrawn in place and a warning gets a line of
    its own.
 5. The picture: --size WxH gives a PNG of that size, --view and --zoom change the
    picture, bad values are refused.

Arguments: MEDIAL_AXIS SCRATCH_DIR. Exits 0 on success, 1 on failure.
"""
import json
import os
import pty
import re
import subprocess
import sys

from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOGeometry import vtkOBJReader, vtkSTLReader
from vtkmodules.vtkIOLegacy import vtkPolyDataReader
from vtkmodules.vtkIOPLY import vtkPLYReader
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLPolyDataWriter

from checks import check, finish

cli, temp = sys.argv[1], sys.argv[2]
os.makedirs(temp, exist_ok=True)
def run(*args, code=0):
    result = subprocess.run([cli, *args], capture_output=True, text=True)
    check(result.returncode == code, f"medial-axis {' '.join(args)}: exit {result.returncode}, expected {code}"
          + ("" if result.returncode == code else "\n" + result.stderr))
    return result


def path(name):
    return os.path.join(temp, name)


def same_bytes(a, b):
    with open(a, "rb") as fa, open(b, "rb") as fb:
        return fa.read() == fb.read()


def read_ma(name):
    """Centres and radii of a .ma file, as text tokens (exact)."""
    with open(name) as f:
        return [line.split()[1:5] for line in f if line.startswith("v ")]


# 1. Ball formats. closest-neighbor gives links, so the files hold edges too.
run("-n", "1500", "--strategy", "closest-neighbor", "--seed", "7", "-o", path("a.ma"), "--quiet")
with open(path("a.ma")) as f:
    header = f.readline().split()
check(int(header[1]) > 0, f"a.ma holds the links as edges ({header})")
for ext in ("ma", "ply", "vtp", "vtk", "csv"):
    run("--balls", path("a.ma"), "-o", path(f"b.{ext}"), "--quiet")
    run("--balls", path(f"b.{ext}"), "-o", path(f"c.{ext}"), "--quiet")
    run("--balls", path(f"c.{ext}"), "-o", path(f"d-from-{ext}.ma"), "--quiet")
    if ext in ("ma", "ply"):
        check(same_bytes(path(f"b.{ext}"), path(f"c.{ext}")), f".{ext} written, read with --balls, written again: same bytes")
    same = read_ma(path(f"d-from-{ext}.ma")) == read_ma(path("a.ma"))
    check(same, f".ma -> .{ext} -> .{ext} -> .ma keeps every centre and radius exactly")
check(same_bytes(path("a.ma"), path("d-from-ply.ma")), ".ma -> .ply -> .ply -> .ma gives the same .ma file")
check(open(path("b.ply"), "rb").read(4) == b"ply\n", "-o b.ply writes PLY")
with open(path("b.ply"), "rb") as f:
    check(b"property double radius" in f.read(400), "the PLY vertices have a radius property")

# 2. A hand-written Q-MAT-style .ma: two balls joined by an edge, two smaller ones
# making faces with them (centres not in one plane, so the union is a surface).
qmat = path("qmat.ma")
with open(qmat, "w") as f:
    f.write("4 3 2\n"
            "v 0 0 0 1.0\n"
            "v 1.5 0 0 1.0 0.25\n"          # an extra column, as some tools write
            "# a comment line\n"
            "v 0.75 0.5 0 0.5\n"
            "v 0.75 0 0.5 0.5\n"
            "e 0 1\n"
            "e 1 2\n"
            "e 1 3\n"
            "f 0 1 2\n"
            "f 0 1 3\n")
stats = run("--balls", qmat, "--reconstruct", path("qmat.vtp"), "--resolution", "64", "--stats", "--quiet")
check('"medial_points": 4' in stats.stdout and '"radius_max": 1' in stats.stdout, "--balls reads the .ma: " + stats.stdout.strip())
readers = {"vtp": vtkXMLPolyDataReader, "stl": vtkSTLReader, "ply": vtkPLYReader, "obj": vtkOBJReader,
           "vtk": vtkPolyDataReader}
for ext, reader_class in readers.items():
    out = path(f"qmat.{ext}")
    run("--balls", qmat, "--reconstruct", out, "--resolution", "64", "--quiet")
    reader = reader_class()
    reader.SetFileName(out)
    reader.Update()
    surface = reader.GetOutput()
    b = surface.GetBounds()
    voxel = 4.5 / 63
    expected = (-1.0, 2.5, -1.0, 1.0, -1.0, 1.0)
    near = all(abs(b[k] - expected[k]) < 2 * voxel for k in range(6))
    check(surface.GetNumberOfPolys() > 100 and near,
          f"--reconstruct qmat.{ext}: {surface.GetNumberOfPolys()} triangles, bounds {[round(v, 3) for v in b]}")
with open(path("qmat.vtp"), "rb") as f:
    # Appended raw binary: VTK leaves out the XML declaration, the file starts at VTKFile.
    check(b'<VTKFile type="PolyData"' in f.read(100), "--reconstruct OUT.vtp writes VTK XML")
run("--balls", path("missing.ma"), "--stats", code=1)
bad = run("--balls", path("qmat.vtp"), "--stats", code=1)
check("no one-component point array 'Radius'" in bad.stderr, "--balls of a surface file: " + bad.stderr.strip())
# Three balls lie in a plane: their union is curves, which an .stl cannot hold.
with open(path("flat.ma"), "w") as f:
    f.write("3 0 0\nv 0 0 0 1\nv 1.5 0 0 1\nv 0.75 0.5 0 0.5\n")
flat = run("--balls", path("flat.ma"), "--reconstruct", path("flat.stl"), code=1)
check("holds triangles only" in flat.stderr and not os.path.exists(path("flat.stl")),
      "planar balls to .stl are refused: " + flat.stderr.strip().split("\n")[-1])
run("--balls", path("flat.ma"), "--reconstruct", path("flat.vtp"), "--quiet")

# 3. Flags as people type them.
for args in (["--samples=10k", "--threads=2"], ["-n=10k"], ["-n", "10k"], ["-n", "1e4"]):
    out = run(*args, "--stats", "--quiet")
    check('"samples": 10000, "medial_points": 10000' in out.stdout, f"{' '.join(args)}: 10000 samples")
out = run("-n", "1.5k", "--stats", "--quiet", "--seed=3")
check('"samples": 1500' in out.stdout, "-n 1.5k: 1500 samples")
out = run("-n", "0.002M", "--stats", "--quiet")
check('"samples": 2000' in out.stdout, "-n 0.002M: 2000 samples (the M suffix, cheaply)")
version = run("--version")
check(re.match(r"^medial-axis [0-9]+\.[0-9]+\.[0-9]+ \(VTK [0-9.]+\)$", version.stdout.strip()) is not None,
      "--version: " + version.stdout.strip())
nothing = run("-n", "5000000", code=1)
check("nothing to write" in nothing.stderr and "Sampling" not in nothing.stderr,
      "a run that writes nothing is refused before any work: " + nothing.stderr.strip())
check("takes no value" in run("--stats=yes", code=1).stderr, "--stats=yes is refused")
check("expects a whole number" in run("-n", "10q", "--stats", code=1).stderr, "-n 10q is refused")
# --stats is JSON whatever the input's name holds (quotes, a backslash, a tab, <, &).
odd = path('odd "name" \\ \t <b>&.ma')
run("-n", "500", "-o", odd, "--quiet")
out = run("--balls", odd, "--stats", "--quiet")
try:
    odd_stats = json.loads(out.stdout)
except ValueError as error:
    odd_stats = {"error": str(error)}
check(odd_stats.get("balls") == odd, "--stats quotes the input's name as JSON: " + out.stdout.strip()[:160])

# 4. Progress.
plain = run("-n", "2000", "--stats", "-o", path("p.vtp"))
stages = re.findall(r"^medial-axis: (.*): done \([0-9.]+ s\)$", plain.stderr, re.M)
print("stages:", stages)
check(stages[:4] == ["Preparing the surface", "Building the surface queries", "Drawing the samples", "Sampling"]
      and stages[-1].startswith("Writing"), "without a terminal, one line per finished stage")
# Every long stage of the program, a file read, the reconstruction and the thickness.
run("-n", "500", "-o", path("p.ply"), "--quiet")
plain = run("--balls", path("p.ply"), "--reconstruct", path("p-rebuilt.vtp"), "--resolution", "48")
stages = re.findall(r"^medial-axis: (.*): done \([0-9.]+ s\)$", plain.stderr, re.M)
print("stages:", stages)
check(stages[:1] == ["Reading the balls"] and "Filling the distance field" in stages
      and stages[-1].startswith("Writing"), "--balls and --reconstruct: reading, reconstruction and writing stages")
plain = run("-n", "300", "--thickness-below", "0.3")
stages = re.findall(r"^medial-axis: (.*): done \([0-9.]+ s\)$", plain.stderr, re.M)
check("Measuring the thickness at the vertices" in stages and "Measuring the thickness at the cells" in stages,
      "--thickness-below: the thickness stages " + str(stages))
quiet = run("-n", "2000", "--stats", "--quiet")
check(quiet.stderr == "" and quiet.stdout.startswith('{"input"'), "--quiet: nothing on stderr")

# An open sphere (a warning) under a pseudo-terminal.
sphere = vtkSphereSource()
sphere.SetThetaResolution(40)
sphere.SetPhiResolution(40)
sphere.SetEndPhi(170)
writer = vtkXMLPolyDataWriter()
writer.SetInputConnection(sphere.GetOutputPort())
writer.SetFileName(path("open.vtp"))
writer.Write()
pid, fd = pty.fork()
if pid == 0:
    # --repair none: the open surface's own warning (the repair's lines are warnings too).
    os.execv(cli, [cli, path("open.vtp"), "-n", "200k", "--threads", "2", "--stats", "--repair", "none"])
chunks = []
while True:
    try:
        data = os.read(fd, 65536)
    except OSError:
        break
    if not data:
        break
    chunks.append(data)
os.waitpid(pid, 0)
tty = b"".join(chunks).decode(errors="replace")
lines = tty.replace("\r\n", "\n").split("\n")
warning = [line for line in lines if "warning:" in line]
check("[##" in tty and "\r" in tty, "on a terminal the bar is drawn and redrawn in place")
check(len(warning) == 1 and re.search(r"(^|\r\x1b\[K)medial-axis: warning: Input surface is open", warning[0])
      is not None and "[#" not in warning[0].split("medial-axis: warning")[1],
      "the warning has a line of its own: " + repr(warning[0][:160] if warning else tty[-300:]))

# 5. The picture's flags: --size sets the PNG's size, --view and --zoom change the picture.
def png_size(name):
    with open(name, "rb") as f:
        header = f.read(24)
    return int.from_bytes(header[16:20], "big"), int.from_bytes(header[20:24], "big")


pictures = {}
for name, args in (("auto", []), ("plus-z", ["--view=+z"]), ("iso", ["--view", "iso"]), ("zoom", ["--zoom", "2"])):
    pictures[name] = path(f"view-{name}.png")
    run("-n", "300", "--quiet", "--render", pictures[name], "--size=320x200", *args)
    check(png_size(pictures[name]) == (320, 200), f"--size=320x200 {' '.join(args)}: {png_size(pictures[name])}")
for name in ("plus-z", "iso", "zoom"):
    check(not same_bytes(pictures["auto"], pictures[name]), f"--{name} draws another picture than the default")
run("-n", "300", "--quiet", "--render", path("view-default.png"))
check(png_size(path("view-default.png")) == (900, 640), "the default size is 900x640")
check("unknown --view 'up'" in run("--view", "up", "--stats", code=1).stderr, "--view up is refused")
check("--size expects WIDTHxHEIGHT" in run("--size", "10x10", "--stats", code=1).stderr, "--size 10x10 is refused")
check("--zoom expects a number" in run("--zoom", "0", "--stats", code=1).stderr, "--zoom 0 is refused")

finish()
