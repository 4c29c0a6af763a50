#!/usr/bin/env python3
"""The browser test: medial-axis --html pages for a 3D and a 2D result, opened in headless
Chromium (open-page.js), offline, one from a file and one from a web server on 127.0.0.1.

Checks: the page loads with no console error and fetches nothing; its layers and
controls are the ones its run made (counts as in its manifest); toggles, the radius
filter, the thickness threshold and picking with the mouse work; a screenshot of its view
matches the baseline image within the tolerance of VTK's image tests (vtkTesting), and
the same comparison fails against a wrong baseline.

Arguments: MEDIAL_AXIS NODE NODE_MODULES CHROMIUM BASELINE_DIR SCRATCH
Exit 0 when every check passes, 1 on a failure, 125 (skipped) without node, Chromium,
playwright-core or a viewer in this build.
"""
import json
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "..", "..", "Testing", "Python"))
from checks import check, finish  # noqa: E402

SKIP = 125
cli, node, modules, chromium, baselines, scratch = sys.argv[1:7]
here = os.path.dirname(os.path.abspath(__file__))
os.makedirs(scratch, exist_ok=True)


def skip(reason):
    print(f"skipped: {reason}")
    sys.exit(SKIP)


for what, where in (("node", node), ("Chromium", chromium)):
    if not where or not os.path.exists(where):
        skip(f"{what} is not installed ('{where}'); scripts/install-deps.sh installs it")
if not os.path.isdir(os.path.join(modules, "playwright-core")):
    skip(f"playwright-core is not in {modules} (the viewer's npm ci did not run: no npm at configure time?)")


def run(*args):
    done = subprocess.run([cli, *args], capture_output=True, text=True)
    if "this build has no web viewer" in done.stderr:
        skip(done.stderr.strip())
    failed = done.returncode != 0
    check(not failed, f"medial-axis {' '.join(args)} -> exit {done.returncode}" + (f": {done.stderr.strip()[-300:]}" if failed else ""))
    return done.stdout


def open_page(page, shot, *options):
    start = time.monotonic()
    done = subprocess.run([node, os.path.join(here, "open-page.js"), modules, chromium, page, shot, *options],
                          capture_output=True, text=True, timeout=300)
    report = json.loads(done.stdout) if done.stdout.strip() else {"failure": done.stderr[-2000:]}
    report["wallSeconds"] = time.monotonic() - start
    return report


def compare(shot, baseline):
    """vtkTesting's image comparison of a PNG file with a baseline, as the image tests do."""
    from vtkmodules.vtkIOImage import vtkPNGReader
    from vtkmodules.vtkTestingRendering import vtkTesting
    reader = vtkPNGReader()
    reader.SetFileName(shot)
    testing = vtkTesting()
    # vtkTesting writes its copy of the test image (and the difference) to -T under the
    # baseline's name: a folder of its own, not the screenshots'.
    temporary = os.path.join(scratch, "vtkTesting")
    os.makedirs(temporary, exist_ok=True)
    for arg in ("-V", baseline, "-T", temporary):
        testing.AddArgument(arg)
    return testing.RegressionTest(reader, 10) == vtkTesting.PASSED


def check_page(name, report, expected_layers, expected_controls):
    print(f"{name}: {report.get('bytes')} bytes, loaded in {report.get('loadMs')} ms "
          f"(Chromium start to ready {report['wallSeconds']:.1f} s), WebGL {report.get('webgl')}")
    if not check("failure" not in report, f"{name}: open-page.js ran ({report.get('failure', '')[:500]})"):
        return False
    check(report["status"] == "ready", f"{name}: the page is ready ({report.get('error')})")
    check(not report["consoleErrors"] and not report["pageErrors"],
          f"{name}: no console error ({report['consoleErrors'] + report['pageErrors']})")
    check(not report["requests"], f"{name}: nothing fetched but the page ({report['requests']})")
    if report["status"] != "ready":
        return False
    layers = report["layers"]
    check(set(expected_layers) <= set(layers), f"{name}: layers {sorted(layers)} hold {sorted(expected_layers)}")
    missing = [c for c in expected_controls if c not in report["controls"]]
    check(not missing, f"{name}: controls present (missing {missing})")
    for layer, spec in report["manifest"].items():
        drawn = layers.get("mesh-faces" if layer == "mesh" else ("graph-arcs" if layer == "graph" else layer), {})
        if layer in ("surface", "balls", "reconstruction"):
            check(drawn.get("points") == spec["points"],
                  f"{name}: {layer} drawn with its {spec['points']} points ({drawn.get('points')})")
    for what, passed in report["checks"].items():
        check(passed, f"{name}: {what}")
    print(f"{name}: picked {report.get('pickSurface')!r} / {report.get('pickMedial')!r}")
    return True


# 3D: the demo shape with every layer a run can make, opened from a file.
jack = os.path.join(scratch, "jack.html")
stats = json.loads(run("-n", "3000", "--threads", "2", "--seed", "3", "--medial-mesh", os.path.join(scratch, "jack-mesh.vtp"),
                       "--thickness", os.path.join(scratch, "jack-thickness.vtp"), "--reconstruct",
                       os.path.join(scratch, "jack-union.vtp"), "--resolution", "48", "--html", jack, "--stats"))
check(stats["html_bytes"] == os.path.getsize(jack), f"--stats html_bytes {stats['html_bytes']} is the file's size")
report3d = open_page(jack, os.path.join(scratch, "TestWebPage3D.png"))
ok3d = check_page("3D page (demo:jack, file)", report3d,
                  ["surface", "balls", "mesh-faces", "mesh-edges", "mesh-seams", "mesh-junctions", "reconstruction"],
                  ["surface-visible", "surface-opacity", "thickness-visible", "thickness-threshold", "balls-visible",
                   "balls-size", "balls-min", "balls-max", "mesh-faces", "mesh-edges", "mesh-seams", "mesh-junctions",
                   "reconstruction-visible", "reset-camera"])
if ok3d:
    check(report3d["layers"]["balls"]["points"] == 3000, "3D page: all 3000 balls (under the display limit)")

# Above the display limit the page thins the balls and says so: write_html (Python) with
# at most 1000 of the 3D run's 3000 balls.
import medialaxis  # noqa: E402
jack_surface = medialaxis.demo_shape("jack")
jack_balls = medialaxis.medial_axis(*jack_surface, samples=3000, seed=3, threads=2)
thinned = os.path.join(scratch, "jack-thinned.html")
size = medialaxis.write_html(thinned, jack_surface, balls=jack_balls, max_balls=1000, title="thinned")
check(size == os.path.getsize(thinned), f"write_html wrote {size} bytes")
report = open_page(thinned, os.path.join(scratch, "thinned.png"), "--plain")
if check(report.get("status") == "ready" and not report["consoleErrors"], "thinned page: ready, no console error"):
    check(report["layers"]["balls"]["points"] == 1000 and "one in every 3 (1,000)" in (report["decimation"] or ""),
          f"thinned page: 1000 balls drawn and said ({report['decimation']!r})")

# 2D: a triangulated L-shape (one polygon cut into triangles), from a web server: the
# outline is its 6 boundary edges, not the triangles.
from vtkmodules.vtkFiltersCore import vtkTriangleFilter  # noqa: E402
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter  # noqa: E402
shape = medialaxis.vtkMedialShapeSource()
shape.SetShapeToLShape()
triangles = vtkTriangleFilter()
triangles.SetInputConnection(shape.GetOutputPort())
region = os.path.join(scratch, "l-shape-triangles.vtp")
writer = vtkXMLPolyDataWriter()
writer.SetInputConnection(triangles.GetOutputPort())
writer.SetFileName(region)
writer.Write()
triangles.Update()
check(triangles.GetOutput().GetNumberOfPolys() >= 4, f"the L-shape cut into {triangles.GetOutput().GetNumberOfPolys()} triangles")
shape2d = os.path.join(scratch, "l-shape.html")
run(region, "-n", "400", "--threads", "2", "--html", shape2d, "--stats")
report2d = open_page(shape2d, os.path.join(scratch, "TestWebPage2D.png"), "--serve")
ok2d = check_page("2D page (triangulated L-shape, web server)", report2d,
                  ["surface", "balls", "graph-arcs", "graph-junctions", "graph-ends", "graph-disks"],
                  ["surface-visible", "balls-visible", "balls-min", "balls-max", "graph-arcs", "graph-nodes",
                   "graph-disks", "reset-camera"])
if ok2d:
    check(report2d["manifest"]["surface"]["outline"] and report2d["layers"]["surface"]["cells"] == 6,
          f"2D page: the outline is the L's 6 edges ({report2d['layers']['surface'].get('cells')} lines)")
    check(report2d["layers"]["graph-junctions"]["points"] == 3 and report2d["layers"]["graph-ends"]["points"] == 5,
          "2D page: the L-shape's 3 junctions and 5 end points")

# Screenshots against the baselines, and a wrong baseline must fail.
base3d = os.path.join(baselines, "TestWebPage3D.png")
base2d = os.path.join(baselines, "TestWebPage2D.png")
if ok3d:
    check(compare(os.path.join(scratch, "TestWebPage3D.png"), base3d), "3D view matches TestWebPage3D.png")
if ok2d:
    check(compare(os.path.join(scratch, "TestWebPage2D.png"), base2d), "2D view matches TestWebPage2D.png")
if ok3d and check(os.path.exists(base2d), "the 2D baseline exists (for the wrong-baseline check)"):
    check(not compare(os.path.join(scratch, "TestWebPage3D.png"), base2d), "3D view does not match the 2D baseline")
finish()
