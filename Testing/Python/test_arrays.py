#!/usr/bin/env python3
"""medialaxis.arrays, the numpy-level functions, against closed forms and bad input.

 - medial_axis on a sphere of radius 1 (numpy arrays): every ball centred near the origin
   with a radius near 1; the same balls from a vtkPolyData and from int32 triangles;
   reconstruct of those balls is a sphere of radius about 1.
 - thickness of a 3 x 2 x 1 box: 1 (the slab) at every vertex, edges and corners
   included, where the tangent ball alone (tangent_thickness) is 0; nothing thinner than
   0.5, all of it thinner than 1.01.
 - medial_mesh of the demo shape: one component with Euler characteristic 1 (a ball's),
   faces and edges indexing its vertices, the four type names.
 - junction_graph of the L-shape (3 junctions, 5 end points) and of the square frame
   (junctions at (+-sqrt 2, +-sqrt 2) with radius 2 - sqrt 2), from numpy loops.
 - 2D medial_axis from (n, 2) vertices gives (k, 2) centres inside the L.
 - Bad input: wrong shapes and dtypes, NaN, indices out of range, unknown names and
   out-of-range numbers each raise ValueError with a message that names the argument.
"""
import math
import warnings

import numpy as np

import medialaxis
from checks import check, finish

# Sphere: balls at the centre with radius ~1 (facets of resolution 4 are ~0.07 long).
vertices, triangles = medialaxis.demo_shape("sphere", radius=1.0, resolution=4)
check(vertices.shape == (2562, 3) and vertices.dtype == np.float64, f"sphere vertices {vertices.shape} {vertices.dtype}")
check(triangles.shape == (5120, 3) and np.issubdtype(triangles.dtype, np.integer), f"sphere triangles {triangles.shape}")
balls = medialaxis.medial_axis(vertices, triangles, samples=2000, seed=7, threads=2)
check(sorted(balls.keys())[:3] == ["centres", "contacts", "radii"], f"medial_axis arrays: {balls.keys()}")
check(balls.centres.shape == (2000, 3) and balls.radii.shape == (2000,), f"2000 balls {balls.centres.shape}")
# Each ball is tangent at its surface point, along the inward normal: |c| + r = 1, up to
# the facets' sagitta (edges ~0.07 long: ~6e-4) and the 1e-4 protrusion shrink.
tangency = np.abs(np.linalg.norm(balls.centres, axis=1) + balls.radii - 1.0).max()
check(tangency < 2e-3, f"sphere: |centre| + radius = 1 within 2e-3 ({tangency:.2e})")
# With the 45 degree rule a ball stops at the first contact whose normal turns 45 degrees:
# on the faceted sphere that is short of the whole sphere (radius 1), but not far.
check(0.85 < balls.radii.min() and balls.radii.max() <= 1.0 and np.median(balls.radii) > 0.93,
      f"sphere: radii {balls.radii.min():.3f} .. {balls.radii.max():.3f}, median {np.median(balls.radii):.3f}")
check(balls.info["discarded"] == 0, "closed sphere: no discarded samples")
same = medialaxis.medial_axis(medialaxis.to_polydata(vertices, triangles.astype(np.int32)), samples=2000, seed=7,
                              threads=1)
check(np.array_equal(same.centres, balls.centres) and np.array_equal(same.radii, balls.radii),
      "the same balls from a vtkPolyData of int32 triangles, on 1 thread")
union = medialaxis.reconstruct(balls, resolution=48, threads=2)
distance = np.linalg.norm(union.vertices, axis=1)
check(union.triangles.shape[1] == 3 and abs(distance - 1.0).max() < 0.05,
      f"reconstruct: the union of the sphere's balls lies within 0.05 of the sphere ({distance.min():.3f} .. {distance.max():.3f})")
union2 = medialaxis.reconstruct(balls.centres, balls.radii, resolution=48, threads=2)
check(np.array_equal(union2.vertices, union.vertices), "reconstruct from (centres, radii) arrays equals from the Result")

# Box 3 x 2 x 1: the slab is 1 thick.
box_v, box_t = medialaxis.demo_shape("box", box_lengths=(3.0, 2.0, 1.0), resolution=8)
wall = medialaxis.thickness(box_v, box_t, threads=2, below=0.5)
check(wall.thickness.shape == (len(box_v),) and wall.medial_centres.shape == (len(box_v), 3),
      f"thickness per vertex {wall.thickness.shape}")
check(np.abs(wall.thickness - 1.0).max() < 1e-6,
      f"box: thickness {wall.thickness.min():.8f} to {wall.thickness.max():.8f}, the slab's 1 everywhere")
check(wall.tangent_thickness.shape == (len(box_v),) and wall.tangent_thickness.min() == 0.0
      and wall.tangent_thickness.max() <= 1.0 + 1e-9,
      f"box: the tangent ball alone {wall.tangent_thickness.min()} to {wall.tangent_thickness.max()} (0 on the edges)")
check(wall.info["thin_area_fraction"] == 0.0 and wall.info["thin_regions"] == 0,
      f"box: nothing thinner than 0.5 ({wall.info})")
thick = medialaxis.thickness(box_v, box_t, threads=2, below=1.01)
check(thick.info["thin_area_fraction"] == 1.0 and thick.info["thin_regions"] == 1,
      f"box: all of it thinner than 1.01 ({thick.info})")

# The demo shape's medial mesh: a genus-0 solid's medial mesh has chi 1, one component.
jack_v, jack_t = medialaxis.demo_shape("jack")
mesh = medialaxis.medial_mesh(jack_v, jack_t, samples=2000, threads=2)
check(mesh.info["euler_characteristic"] == 1 and mesh.info["components"] == 1,
      f"jack: medial mesh chi {mesh.info['euler_characteristic']}, {mesh.info['components']} component(s)")
n = len(mesh.centres)
check(mesh.faces.shape[1] == 3 and mesh.faces.max() < n and mesh.edges.shape[1] == 2 and (mesh.edges.max() < n if len(mesh.edges) else True),
      f"jack: {len(mesh.faces)} faces and {len(mesh.edges)} edges index its {n} vertices")
check(set(mesh.type_names) <= {"rim", "sheet", "seam", "junction"} and mesh.info["sheets"] > 0,
      f"jack: point types {dict((t, mesh.info[t + 's']) for t in ('rim', 'sheet', 'seam', 'junction'))}")

# 2D: the L-shape and the square frame from numpy loops.
l_vertices, l_loops = medialaxis.demo_shape("l-shape")
l_graph = medialaxis.junction_graph([l_vertices[loop] for loop in l_loops])
check((l_graph.info["junctions"], l_graph.info["end_points"]) == (3, 5),
      f"L-shape: {l_graph.info['junctions']} junctions, {l_graph.info['end_points']} end points (3, 5)")
check(l_graph.points.shape[1] == 2 and len(l_graph.arcs) == l_graph.info["arcs"] == len(l_graph.arc_types),
      f"L-shape: 2D points, {len(l_graph.arcs)} arcs with their types")
outer = np.array([[-2, -2], [2, -2], [2, 2], [-2, 2]], dtype=float)
frame = medialaxis.junction_graph([outer, 0.5 * outer[::-1]])
corners = frame.points[frame.junctions]
root2 = math.sqrt(2.0)
check(len(corners) == 4 and np.allclose(np.sort(np.abs(corners), axis=0), root2, atol=1e-9)
      and np.allclose(frame.radii[frame.junctions], 2 - root2, atol=1e-9),
      f"frame: 4 junctions at (+-sqrt 2, +-sqrt 2), radius 2 - sqrt 2 ({corners.round(6).tolist()})")
planar = medialaxis.medial_axis(medialaxis.to_polydata(l_vertices, lines=[list(l) + [l[0]] for l in l_loops]),
                                samples=300, threads=2)
check(planar.centres.shape == (300, 3) and np.abs(planar.centres[:, 2]).max() == 0.0, "2D balls of the L in z = 0")
inside = (planar.centres[:, 0] >= 0) & (planar.centres[:, 1] >= 0) & ((planar.centres[:, 0] <= 1) | (planar.centres[:, 1] <= 1))
check(inside.all(), "2D balls: every centre inside the L")
l_triangles = np.array([[0, 1, 2], [0, 2, 5]])  # two triangles of the L, for the 2D refusal below


def raises(call, needle, what):
    try:
        call()
    except ValueError as error:
        return check(needle in str(error), f"{what}: ValueError '{error}'")
    except Exception as error:  # noqa: BLE001
        return check(False, f"{what}: {type(error).__name__} '{error}' instead of ValueError")
    return check(False, f"{what}: no error")


raises(lambda: medialaxis.medial_axis(vertices[:, :1], triangles), "vertices must have shape (n, 2 or 3)",
       "vertices (n, 1)")
raises(lambda: medialaxis.medial_axis(vertices.reshape(-1), triangles), "vertices must have shape", "flat vertices")
raises(lambda: medialaxis.medial_axis(vertices.astype(complex), triangles), "vertices must hold real numbers",
       "complex vertices")
raises(lambda: medialaxis.medial_axis(np.array([["a", "b", "c"]]), triangles), "vertices must hold real numbers",
       "string vertices")
raises(lambda: medialaxis.medial_axis(vertices, triangles.astype(float)), "triangles must be an integer array",
       "float triangles")
raises(lambda: medialaxis.medial_axis(vertices, triangles[:, :2]), "triangles must have shape (m, 3)", "triangles (m, 2)")
raises(lambda: medialaxis.medial_axis(vertices, triangles + len(vertices)), "indices outside [0, 2562)",
       "indices out of range")
raises(lambda: medialaxis.medial_axis(vertices, -triangles - 1), "indices outside", "negative indices")
nan = vertices.copy()
nan[3, 1] = np.nan
raises(lambda: medialaxis.medial_axis(nan, triangles), "NaN", "NaN vertex")
raises(lambda: medialaxis.medial_axis(np.zeros((0, 3)), triangles), "n > 0", "no vertices")
raises(lambda: medialaxis.medial_axis(vertices), "give triangles", "vertices alone")
raises(lambda: medialaxis.medial_axis(vertices, triangles, samples=0), "samples must be a whole number", "samples 0")
raises(lambda: medialaxis.medial_axis(vertices, triangles, samples=2.5), "samples must be a whole number", "samples 2.5")
raises(lambda: medialaxis.medial_axis(vertices, triangles, method="magic"), "unknown method 'magic'", "unknown method")
raises(lambda: medialaxis.medial_axis(vertices, triangles, strategy="nearest"), "unknown strategy", "unknown strategy")
raises(lambda: medialaxis.medial_axis(vertices, triangles, min_angle=200), "min_angle must be a number in [0.0, 179.0]",
       "min_angle 200")
raises(lambda: medialaxis.thickness(l_vertices, l_triangles), "thickness needs a 3D surface", "2D thickness")
raises(lambda: medialaxis.thickness(box_v, box_t, surface_tolerance=-1.0), "surface_tolerance must be a number",
       "negative surface_tolerance")
raises(lambda: medialaxis.junction_graph([]), "polygons is empty", "no loops")
raises(lambda: medialaxis.junction_graph([outer[:2]]), "a loop needs 3 or more", "a 2-point loop")
raises(lambda: medialaxis.reconstruct(balls.centres, balls.radii[:-1]), "2000 centres but 1999 radii", "radii count")
raises(lambda: medialaxis.reconstruct(balls.centres, -balls.radii), "radii must be positive", "negative radii")
raises(lambda: medialaxis.medial_mesh(vertices, triangles, balls="x"), "balls must be a Result", "balls not a Result")
raises(lambda: medialaxis.write_html(None, (vertices, triangles), mesh=[1]), "mesh must be a Result", "write_html mesh a list")
raises(lambda: medialaxis.demo_shape("cube"), "unknown shape 'cube'", "unknown shape")

# A filter's error is a RuntimeError with its message, its warnings RuntimeWarnings.
flat = np.column_stack([l_vertices, np.zeros(len(l_vertices))])
fan = np.array([[0, 1, 2], [0, 2, 3], [0, 3, 4], [0, 4, 5]])
try:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        medialaxis.medial_mesh(flat, fan, samples=100, threads=2)
    check(False, "medial_mesh of a flat L raised nothing")
except RuntimeError as error:
    check(str(error).startswith("vtkMedialMeshFilter: Cannot build the medial mesh: the surface is flat") and
          "bounds no volume" in str(error), f"flat surface: RuntimeError '{error}'")
with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    open_balls = medialaxis.medial_axis(vertices, triangles[:-10], samples=200, threads=2, repair="none")
check(any(issubclass(w.category, RuntimeWarning) and "open (10 boundary edges)" in str(w.message) for w in caught),
      f"open sphere: RuntimeWarning {[str(w.message)[:80] for w in caught]}")
# Repaired by default: the hole filled, one warning per step, no sample discarded.
with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    repaired_balls = medialaxis.medial_axis(vertices, triangles[:-10], samples=200, threads=2)
check(any("Repair: holes: 1 hole filled" in str(w.message) for w in caught) and repaired_balls.info["discarded"] == 0,
      f"open sphere repaired: {[str(w.message)[:80] for w in caught]}, {repaired_balls.info}")
raises(lambda: medialaxis.medial_axis(vertices, triangles, repair="fix"), "unknown repair 'fix'", "unknown repair")
finish()
