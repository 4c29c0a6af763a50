#!/usr/bin/env python3
"""The gallery: every picture the guide shows (docs/images/), made from the built examples.

    xvfb-run -a /usr/bin/python3 scripts/gallery.py [--build DIR] [--meshes DIR] [--out DIR]
                                                    [--only NAME ...] [--smoke]
    /usr/bin/python3 scripts/gallery.py --check-docs [--write]

Renders each picture of PICTURES below with the command-line program (build/bin/medial-axis)
or, for the simplification pictures, with the Python package (vtkMedialScene), and writes it
to --out (default docs/images/). Pictures of the shared meshes (../shared/data/meshes, or
--meshes) are skipped, and said so, when those are absent. Rendering needs X: run under
`xvfb-run -a`. Prints, for each picture, the command and what --stats said.

--smoke is the docs-gallery test: the same commands with fewer samples (2,000) and a coarser
envelope, written into --out (the build tree); then every picture that was to be made must be
a PNG of the expected size that is not blank (at least 2% of its pixels differ from the
background, and it has at least 16 colours), and the docs must pass --check-docs.

--check-docs checks the pages against PICTURES: every picture a page shows is made here (or
is one of the EXTERNAL ones, which say how they were made), every picture made here is shown
by the pages it names and lies in docs/images/, and the table of docs/building.md (between
<!-- gallery:begin --> and <!-- gallery:end -->) is this script's; --write rewrites that table.
"""
import glob
import json
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
TABLE_PAGE = os.path.join("docs", "building.md")
BEGIN, END = "<!-- gallery:begin -->", "<!-- gallery:end -->"
SMOKE_SAMPLES = "2000"


class Picture:
    """A picture: its file, size, the pages that show it, and how it is made: `cli`, the
    command line's arguments ({out} the picture, {meshes} the mesh folder, {scratch} a
    temporary folder), after `prepare` (a function of the scratch folder and the mesh folder),
    or `python` (a function of the output path, the mesh folder and the smoke flag)."""

    def __init__(self, name, size, pages, cli=None, python=None, prepare=None, meshes=(), description=None,
                 tools=None):
        self.name, self.size, self.pages = name, size, pages
        self.cli, self.python, self.prepare = cli, python, prepare
        self.meshes, self.description = meshes, description
        self.tools = tools  # a function of the build folder: what is missing to make it

    def command(self):
        if self.cli:
            words = ["medial-axis"] + [w.replace("{out}", self.name).replace("{meshes}/", "")
                                       .replace("{scratch}/", "") for w in self.cli]
            return "`%s`" % " ".join(words)
        return self.description


def medialaxis():
    import medialaxis as module
    return module


def noisy_horse(scratch, meshes):
    """horse.ply with Gaussian noise of 0.1% of the diagonal per coordinate (seed 7)."""
    import numpy as np
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOPLY import vtkPLYReader
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
    reader = vtkPLYReader()
    reader.SetFileName(os.path.join(meshes, "horse.ply"))
    reader.Update()
    horse = reader.GetOutput()
    points = vtk_to_numpy(horse.GetPoints().GetData())
    points += np.random.default_rng(7).normal(0.0, 0.001 * horse.GetLength(), points.shape)
    horse.GetPoints().Modified()
    writer = vtkXMLPolyDataWriter()
    writer.SetFileName(os.path.join(scratch, "noisy-horse.vtp"))
    writer.SetInputData(horse)
    writer.Write()


def tall_jack(scratch, meshes):
    """The demo shape stood on its long arm along +z and stretched to about 2 x 2 x 7.6:
    (x, y, z) -> (-z, y, 2x), which keeps it oriented outwards."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    ma = medialaxis()
    shape = ma.vtkMedialShapeSource()
    shape.Update()
    jack = shape.GetOutput()
    points = vtk_to_numpy(jack.GetPoints().GetData())
    x, z = points[:, 0].copy(), points[:, 2].copy()
    points[:, 0], points[:, 2] = -z, 2.0 * x
    jack.GetPoints().Modified()
    writer = ma.vtkMedialFileWriter()
    writer.SetInputData(jack)
    writer.SetFileName(os.path.join(scratch, "jack-z-up.ply"))
    if not writer.Write():
        raise RuntimeError("cannot write jack-z-up.ply")


def medial_mesh(path, smoke, cache={}):
    """A shared mesh and its medial mesh (vtkMedialMeshFilter at the sampler's defaults, or
    2,000 samples in the smoke run), computed once for the pictures that share them."""
    if (path, smoke) not in cache:
        ma = medialaxis()
        reader = ma.vtkMedialFileReader()
        reader.SetFileName(path)
        reader.Update()
        surface = reader.GetOutput()
        sampler = ma.vtkMedialAxisSampler()
        sampler.SetInputData(surface)
        if smoke:
            sampler.SetNumberOfSamples(int(SMOKE_SAMPLES))
        mesh = ma.vtkMedialMeshFilter()
        mesh.SetInputData(surface)
        mesh.SetBallsConnection(sampler.GetOutputPort())
        mesh.Update()
        cache[(path, smoke)] = (surface, mesh.GetOutput())
    return cache[(path, smoke)]


def simplification_picture(mesh_name, k):
    """A picture of a shared mesh's medial mesh (simplified to k balls, or not with k None)
    inside the translucent original, and its envelope beside it."""

    def make(out, meshes, smoke):
        ma = medialaxis()
        surface, medial = medial_mesh(os.path.join(meshes, mesh_name), smoke)
        if k:
            simplify = ma.vtkMedialSimplifyFilter()
            simplify.SetInputData(medial)
            simplify.SetSurfaceData(surface)
            simplify.SetMethodToQuadric()
            simplify.SetNumberOfBalls(k)
            simplify.Update()
            medial = simplify.GetOutput()
        union = ma.vtkMedialBallUnion()
        union.SetInputData(medial)
        union.SetPrimitivesToMedialMesh()
        resolution = 64 if smoke else 128
        union.SetSampleDimensions(resolution, resolution, resolution)
        union.Update()
        scene = ma.vtkMedialScene()
        scene.SetSurface(surface)
        scene.SetMedial(medial)
        scene.SetReconstruction(union.GetOutput())
        scene.SetWindowSize(1000, 380)
        scene.SetPointSize(4)
        if not scene.WritePNG(out):
            raise RuntimeError("cannot write " + out)
        return "%d balls" % medial.GetNumberOfPoints()

    what = "simplified to %d balls (quadric), " % k if k else ""
    make.description = ("`scripts/gallery.py`: the medial mesh of `%s` (`vtkMedialMeshFilter`, 10,000 samples), "
                        "%sin the translucent original, and its envelope beside it (`vtkMedialBallUnion`, "
                        "128³), drawn by `vtkMedialScene` at 1000 × 380" % (mesh_name, what))
    return make


def thin_regions_picture(mesh_name, below):
    """A shared mesh twice, its cells thinner than `below` in red: by the tangent ball alone
    (TangentThickness, left) and by Thickness (right), from one vtkMedialThickness run."""

    def make(out, meshes, smoke):
        import vtk
        ma = medialaxis()
        reader = ma.vtkMedialFileReader()
        reader.SetFileName(os.path.join(meshes, mesh_name))
        thickness = ma.vtkMedialThickness()
        thickness.SetInputConnection(reader.GetOutputPort())
        thickness.SetThinThreshold(below)
        thickness.Update()
        surface = thickness.GetOutput()
        window = vtk.vtkRenderWindow()
        window.SetOffScreenRendering(1)
        window.SetSize(1000, 420)
        lookup = vtk.vtkLookupTable()
        lookup.SetNumberOfTableValues(2)
        lookup.SetTableValue(0, 0.85, 0.15, 0.1, 1.0)  # thinner than `below`
        lookup.SetTableValue(1, 0.8, 0.8, 0.8, 1.0)
        lookup.SetTableRange(0.0, 2.0 * below)
        lookup.Build()
        camera = None
        thin = []
        for i, name in enumerate(["TangentThickness", "Thickness"]):
            values = surface.GetCellData().GetArray(name)
            cells = sum(1 for c in range(values.GetNumberOfTuples()) if values.GetValue(c) < below)
            thin.append(cells)
            copy = vtk.vtkPolyData()
            copy.ShallowCopy(surface)
            copy.GetCellData().SetActiveScalars(name)
            mapper = vtk.vtkPolyDataMapper()
            mapper.SetInputData(copy)
            mapper.SetScalarModeToUseCellData()
            mapper.SetLookupTable(lookup)
            mapper.UseLookupTableScalarRangeOn()
            actor = vtk.vtkActor()
            actor.SetMapper(mapper)
            renderer = vtk.vtkRenderer()
            renderer.SetViewport(0.5 * i, 0.0, 0.5 * (i + 1), 1.0)
            renderer.SetBackground(1.0, 1.0, 1.0)
            renderer.AddActor(actor)
            label = vtk.vtkTextActor()
            label.SetInput("%s < %g: %d cells" % (name, below, cells))
            label.GetTextProperty().SetColor(0.1, 0.1, 0.1)
            label.GetTextProperty().SetFontSize(18)
            label.SetPosition(10, 10)
            renderer.AddActor2D(label)
            if camera is None:
                renderer.ResetCamera()
                renderer.GetActiveCamera().Elevation(35)
                renderer.GetActiveCamera().Azimuth(-30)
                renderer.ResetCamera()
                renderer.GetActiveCamera().Zoom(1.3)
                camera = renderer.GetActiveCamera()
            else:
                renderer.SetActiveCamera(camera)
            window.AddRenderer(renderer)
        window.Render()
        grab = vtk.vtkWindowToImageFilter()
        grab.SetInput(window)
        grab.Update()
        writer = vtk.vtkPNGWriter()
        writer.SetFileName(out)
        writer.SetInputConnection(grab.GetOutputPort())
        writer.Write()
        return "thinner than %g: %d cells by the tangent ball, %d by Thickness" % (below, thin[0], thin[1])

    make.description = ("`scripts/gallery.py`: `%s` through `vtkMedialThickness` (defaults), its cells thinner than "
                        "%g in red, by `TangentThickness` (left) and `Thickness` (right), at 1000 × 420"
                        % (mesh_name, below))
    return make


def web_page_tools(build):
    """What the page's screenshot needs: the viewer's node modules (playwright-core) from
    the build, node and Debian's Chromium."""
    missing = []
    if not os.path.isdir(os.path.join(build, "Rendering", "Web", "viewer", "node_modules", "playwright-core")):
        missing.append("the web viewer's node modules (build/Rendering/Web/viewer/node_modules)")
    if not shutil.which("node"):
        missing.append("node")
    if not os.path.exists("/usr/bin/chromium"):
        missing.append("/usr/bin/chromium")
    return missing


def web_page_picture(out, meshes, smoke, build, scratch):
    """The horse's page (medial-axis --html with its medial mesh) as headless Chromium shows
    it, controls included (Rendering/Web/Testing/Browser/open-page.js --page-shot)."""
    page = os.path.join(scratch, "horse.html")
    if not os.path.exists(os.path.join(scratch, "horse.ply")):
        os.symlink(os.path.join(meshes, "horse.ply"), os.path.join(scratch, "horse.ply"))
    # Run where the files are: the page shows its command line.
    command = [os.path.join(build, "bin", "medial-axis"), "horse.ply", "--medial-mesh", "horse-mesh.vtp",
               "--html", "horse.html", "--quiet"]
    if smoke:
        command += ["-n", SMOKE_SAMPLES]
    subprocess.run(command, check=True, cwd=scratch)
    modules = os.path.join(build, "Rendering", "Web", "viewer", "node_modules")
    shot = subprocess.run(["node", os.path.join(ROOT, "Rendering", "Web", "Testing", "Browser", "open-page.js"), modules,
                           "/usr/bin/chromium", page, os.path.join(scratch, "horse-view.png"), "--plain",
                           "--page-shot", out], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    try:
        report = json.loads(shot.stdout)
    except ValueError:
        report = {}
    if shot.returncode != 0 or report.get("status") != "ready" or report.get("consoleErrors"):
        raise RuntimeError("the page did not open cleanly in Chromium:\n" + shot.stdout)
    return "%d bytes of page" % os.path.getsize(page)


web_page_picture.description = ("`medial-axis horse.ply --medial-mesh horse-mesh.vtp --html horse.html`, then the "
                                "page as headless Chromium shows it at 1000 × 640, controls included "
                                "(`node Rendering/Web/Testing/Browser/open-page.js ... --plain --page-shot "
                                "web-page.png`)")


# Every picture the guide shows, in the order of the pages.
PICTURES = [
    Picture("medial-demo.png", (900, 640), ["README.md"],
            cli=["demo:jack", "-n", "20k", "--view", "iso", "--render", "{out}"]),
    Picture("cli-view-iso.png", (900, 640), ["docs/cli.md"], prepare=tall_jack,
            cli=["{scratch}/jack-z-up.ply", "-n", "20k", "--view", "iso", "--render", "{out}"]),
    Picture("cli-view-auto.png", (900, 640), ["docs/cli.md"], prepare=tall_jack,
            cli=["{scratch}/jack-z-up.ply", "-n", "20k", "--render", "{out}"]),
    Picture("junctions-frame.png", (900, 700), ["docs/how-it-works/graph-2d.md"],
            cli=["demo:frame", "--junctions", "{scratch}/frame.vtp", "--render", "{out}"]),
    Picture("horse-medial-mesh.png", (900, 640), ["docs/how-it-works/medial-mesh.md"], meshes=["horse.ply"],
            cli=["{meshes}/horse.ply", "--medial-mesh", "{scratch}/horse.ma", "--render", "{out}"]),
    Picture("prune-2d-before.png", (900, 700), ["docs/how-it-works/pruning.md"],
            cli=["demo:trefoil", "--junctions", "{scratch}/trefoil.vtp", "--render", "{out}"]),
    Picture("prune-2d-after.png", (900, 700), ["docs/how-it-works/pruning.md"],
            cli=["demo:trefoil", "--prune", "--junctions", "{scratch}/trefoil.vtp", "--render", "{out}"]),
    Picture("prune-3d-before.png", (900, 640), ["docs/how-it-works/pruning.md"], meshes=["horse.ply"],
            prepare=noisy_horse,
            cli=["{scratch}/noisy-horse.vtp", "--medial-mesh", "{scratch}/m.vtp", "--render", "{out}"]),
    Picture("prune-3d-after.png", (900, 640), ["docs/how-it-works/pruning.md"], meshes=["horse.ply"],
            prepare=noisy_horse,
            cli=["{scratch}/noisy-horse.vtp", "--prune", "--medial-mesh", "{scratch}/m.vtp", "--render", "{out}"]),
    Picture("prune-3d-denoised.png", (900, 640), ["docs/how-it-works/pruning.md"], meshes=["horse.ply"],
            prepare=noisy_horse,
            cli=["{scratch}/noisy-horse.vtp", "--denoise", "--prune", "--medial-mesh", "{scratch}/m.vtp",
                 "--render", "{out}"]),
    Picture("fandisk-k500.png", (1000, 380), ["docs/how-it-works/simplification.md"], meshes=["fandisk.obj"],
            python=simplification_picture("fandisk.obj", 500)),
    Picture("horse-unsimplified.png", (1000, 380), ["docs/how-it-works/simplification.md"], meshes=["horse.ply"],
            python=simplification_picture("horse.ply", None)),
    Picture("horse-k100.png", (1000, 380), ["docs/how-it-works/simplification.md"], meshes=["horse.ply"],
            python=simplification_picture("horse.ply", 100)),
    Picture("jack-thickness.png", (900, 640), ["docs/how-it-works/thickness.md"],
            cli=["demo:jack", "--thickness", "{scratch}/jack-thickness.vtp", "--render", "{out}"]),
    Picture("fandisk-thin.png", (1000, 420), ["docs/how-it-works/thickness.md"], meshes=["fandisk.obj"],
            python=thin_regions_picture("fandisk.obj", 0.3)),
    Picture("web-page.png", (1000, 640), ["docs/web-page.md"], meshes=["horse.ply"], python=web_page_picture,
            tools=web_page_tools),
]
for picture in PICTURES:
    if picture.python:
        picture.description = picture.python.description

# Pictures of the guide that this script cannot make, and how they were made.
EXTERNAL = {
    "paraview-panel.png": ("docs/paraview.md", "a screenshot of ParaView 5.11's GUI under Xvfb with the plugin "
                           "loaded (`sh scripts/paraview.sh`): the Medial Thickness panel and a torus coloured "
                           "by its wall thickness; taken by hand"),
    "fandisk-thin-crop.png": ("docs/how-it-works/thickness.md", "the top of `fandisk.obj`'s fin, cells whose "
                              "`Thickness` is below 0.3 in red, from `medial-axis fandisk.obj -n 1 --thickness "
                              "OUT.vtp` of main 5ccd155 (left) and of the change for fading creases (right), "
                              "rendered side by side at 1000 × 420 with VTK; made by hand, as the left half needs "
                              "the older build"),
}

PREPARED = {tall_jack: "`jack-z-up.ply` is the demo shape stood on its long arm along +z and stretched to "
                       "2 × 2 × 7.6 (made by `scripts/gallery.py`)",
            noisy_horse: "`noisy-horse.vtp` is `horse.ply` with Gaussian noise of 0.1% of the diagonal per "
                         "coordinate, seed 7 (made by `scripts/gallery.py`)"}


def option(argv, name, default):
    return argv[argv.index(name) + 1] if name in argv else default


def make(picture, out_dir, build, meshes, scratch, smoke, prepared):
    out = os.path.join(out_dir, picture.name)
    if picture.prepare and picture.prepare not in prepared:
        picture.prepare(scratch, meshes)
        prepared.add(picture.prepare)
    if picture.python is web_page_picture:
        return picture.python(out, meshes, smoke, build, scratch)
    if picture.python:
        return picture.python(out, meshes, smoke)
    args = [w.replace("{out}", out).replace("{meshes}", meshes).replace("{scratch}", scratch) for w in picture.cli]
    if smoke:
        if "-n" in args:
            args[args.index("-n") + 1] = SMOKE_SAMPLES
        else:
            args += ["-n", SMOKE_SAMPLES]
    command = [os.path.join(build, "bin", "medial-axis")] + args + ["--stats", "--quiet"]
    result = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if result.returncode != 0:
        raise RuntimeError("%s failed:\n%s" % (" ".join(map(shlex.quote, command)), result.stdout))
    stats = result.stdout.strip().split("\n")[-1]
    keys = ("medial_points", "medial_vertices", "euler_characteristic", "junctions", "end_points", "pruned_branches",
            "kept_balls", "thickness_median")
    return ", ".join(m.group(0) for m in re.finditer(r'"(%s)": [^,}]+' % "|".join(keys), stats))


def check_picture(path, size):
    """Problems of a picture: missing, not a PNG of `size`, or blank."""
    if not os.path.exists(path):
        return ["%s was not made" % path]
    with open(path, "rb") as f:
        head = f.read(24)
    if head[:8] != b"\x89PNG\r\n\x1a\n":
        return ["%s is not a PNG" % path]
    width, height = int.from_bytes(head[16:20], "big"), int.from_bytes(head[20:24], "big")
    if (width, height) != tuple(size):
        return ["%s is %d x %d, not %d x %d" % (path, width, height, size[0], size[1])]
    import numpy as np
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOImage import vtkPNGReader
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    pixels = vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())[:, :3]
    background = pixels[0]
    drawn = np.any(pixels != background, axis=1).mean()
    colours = len(np.unique(pixels.view(np.dtype((np.void, 3 * pixels.dtype.itemsize)))))
    if drawn < 0.02 or colours < 16:
        return ["%s looks blank: %.1f%% of the pixels drawn, %d colours" % (path, 100 * drawn, colours)]
    return []


def table():
    rows = ["| picture | shown in | made by |", "|---|---|---|"]
    list_dir = os.path.dirname(os.path.join(ROOT, TABLE_PAGE))
    for picture in PICTURES:
        pages = ", ".join("[%s](%s)" % (os.path.basename(p), os.path.relpath(os.path.join(ROOT, p), list_dir))
                          for p in picture.pages)
        how = picture.command()
        if picture.prepare:
            how += "; " + PREPARED[picture.prepare]
        if picture.meshes:
            how += "; needs the shared meshes"
        rows.append("| [`%s`](images/%s) | %s | %s |" % (picture.name, picture.name, pages, how))
    for name, (page, how) in sorted(EXTERNAL.items()):
        rows.append("| [`%s`](images/%s) | [%s](%s) | not by the gallery: %s |"
                    % (name, name, os.path.basename(page), os.path.relpath(os.path.join(ROOT, page), list_dir), how))
    return "\n".join(rows)


def check_docs(write):
    problems = []
    shown = {}
    for page in [os.path.join(ROOT, "README.md")] + sorted(glob.glob(os.path.join(ROOT, "docs", "**", "*.md"),
                                                                     recursive=True)):
        for name in re.findall(r"!\[[^\]]*\]\(([^)\s]*images/[^)\s]+\.png)\)", open(page, encoding="utf-8").read()):
            shown.setdefault(os.path.basename(name), set()).add(os.path.relpath(page, ROOT))
    made = {p.name: p for p in PICTURES}
    for name, pages in sorted(shown.items()):
        if name not in made and name not in EXTERNAL:
            problems.append("%s shows %s, which scripts/gallery.py does not make: add it to PICTURES"
                            % (", ".join(sorted(pages)), name))
    for picture in PICTURES:
        for page in picture.pages:
            if page not in shown.get(picture.name, ()):
                problems.append("%s does not show %s, which PICTURES says it does" % (page, picture.name))
    for name in list(made) + list(EXTERNAL):
        if not os.path.exists(os.path.join(ROOT, "docs", "images", name)):
            problems.append("docs/images/%s is missing (run scripts/gallery.py)" % name)
    for path in sorted(glob.glob(os.path.join(ROOT, "docs", "images", "*.png"))):
        if os.path.basename(path) not in made and os.path.basename(path) not in EXTERNAL:
            problems.append("docs/images/%s is made by nothing and shown nowhere" % os.path.basename(path))

    path = os.path.join(ROOT, TABLE_PAGE)
    text = open(path, encoding="utf-8").read()
    if BEGIN not in text or END not in text:
        problems.append("%s has no %s ... %s block" % (TABLE_PAGE, BEGIN, END))
    else:
        head, rest = text.split(BEGIN, 1)
        current, tail = rest.split(END, 1)
        if write:
            with open(path, "w", encoding="utf-8") as f:
                f.write(head + BEGIN + "\n" + table() + "\n" + END + tail)
            print("wrote the gallery's table to " + TABLE_PAGE)
        elif current.strip() != table():
            problems.append("the gallery's table in %s is not current (rewrite it: python3 scripts/gallery.py "
                            "--check-docs --write)" % TABLE_PAGE)
    return problems


def main(argv):
    if "--check-docs" in argv:
        problems = check_docs("--write" in argv)
        for problem in problems:
            print("FAIL " + problem)
        print("gallery: %d pictures made by scripts/gallery.py, %d not; %d problem(s) in the docs"
              % (len(PICTURES), len(EXTERNAL), len(problems)))
        return 1 if problems else 0

    build = os.path.abspath(option(argv, "--build", os.path.join(ROOT, "build")))
    meshes = os.path.abspath(option(argv, "--meshes", os.path.join(ROOT, "..", "shared", "data", "meshes")))
    out_dir = os.path.abspath(option(argv, "--out", os.path.join(ROOT, "docs", "images")))
    smoke = "--smoke" in argv
    only = argv[argv.index("--only") + 1:] if "--only" in argv else None
    sys.path.insert(0, os.path.join(build, "lib", "python3", "dist-packages"))
    os.makedirs(out_dir, exist_ok=True)

    made, skipped, problems = [], [], []
    prepared = set()
    with tempfile.TemporaryDirectory() as scratch:
        for picture in PICTURES:
            if only is not None and picture.name not in only:
                continue
            missing = [m for m in picture.meshes if not os.path.exists(os.path.join(meshes, m))]
            if missing:
                skipped.append(picture.name)
                print("skipped %s: needs %s from %s" % (picture.name, ", ".join(missing), meshes))
                continue
            missing = picture.tools(build) if picture.tools else []
            if missing:
                skipped.append(picture.name)
                print("skipped %s: needs %s" % (picture.name, ", ".join(missing)))
                continue
            start = time.time()
            try:
                figures = make(picture, out_dir, build, meshes, scratch, smoke, prepared)
            except Exception as error:  # report every picture, then fail
                problems.append("%s: %s" % (picture.name, error))
                continue
            made.append(picture)
            print("%s (%.1f s): %s%s" % (picture.name, time.time() - start, picture.command() or picture.name,
                                         ": " + figures if figures else ""))
    if smoke:
        for picture in made:
            problems += check_picture(os.path.join(out_dir, picture.name), picture.size)
        problems += check_docs(False)
    for problem in problems:
        print("FAIL " + problem)
    print("gallery: %d pictures in %s, %d skipped (no shared meshes or tools), %d problem(s)"
          % (len(made), out_dir, len(skipped), len(problems)))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
