"""medialaxis with numpy arrays: functions from a mesh to named arrays.

Each function takes a mesh as numpy arrays (``vertices`` (n, 3) or (n, 2), ``triangles``
(m, 3)), or a ``vtkPolyData``, runs the same VTK filters as the command line and
returns a :class:`Result`: named numpy arrays (``result.centres``, ``result["radii"]``),
figures (``result.info``) and the VTK output itself (``result.data``). Keyword
arguments mirror the command-line flags (``samples`` is ``-n``, ``min_angle`` is
``--min-angle``, ...), with the same defaults.

    import medialaxis
    vertices, triangles = medialaxis.demo_shape("jack")
    balls = medialaxis.medial_axis(vertices, triangles, samples=5000)
    mesh = medialaxis.medial_mesh(vertices, triangles, balls=balls)
    wall = medialaxis.thickness(vertices, triangles)

Bad arrays (wrong shape or type, indices out of range, NaN) raise ValueError; a filter's
error raises RuntimeError with its message.
"""
import numbers
import warnings

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray, vtk_to_numpy
from vtkmodules.util.misc import calldata_type
from vtkmodules.vtkCommonCore import VTK_STRING, vtkCommand, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData

from .vtkMedialAxisPlanar import vtkMedialJunctionFilter
from .vtkMedialAxisReconstruction import vtkMedialBallUnion
from .vtkMedialAxisRepair import vtkMedialRepairFilter
from .vtkMedialAxisRenderingWeb import vtkMedialHTMLWriter
from .vtkMedialAxisSampling import vtkMedialAxisSampler
from .vtkMedialAxisSources import vtkMedialShapeSource
from .vtkMedialAxisStructure import vtkMedialMeshFilter, vtkMedialPruneFilter, vtkMedialThickness

__all__ = ["Result", "demo_shape", "to_polydata", "medial_axis", "medial_mesh", "thickness", "junction_graph",
           "reconstruct", "write_html"]

METHODS = {"one-pass": vtkMedialAxisSampler.ONE_PASS, "bisection": vtkMedialAxisSampler.BISECTION,
           "shrinking-ball": vtkMedialAxisSampler.SHRINKING_BALL}
STRATEGIES = {"random": vtkMedialAxisSampler.RANDOM, "closest-neighbor": vtkMedialAxisSampler.CLOSEST_NEIGHBOR,
              "face-distance": vtkMedialAxisSampler.FACE_DISTANCE}
REPAIRS = {"auto": vtkMedialRepairFilter.AUTO, "none": vtkMedialRepairFilter.NONE, "wrap": vtkMedialRepairFilter.WRAP}
TYPES_3D = ("rim", "sheet", "seam", "junction")
TYPES_2D = ("end", "regular", "junction")


class Result:
    """Named numpy arrays of one result.

    ``result.name`` or ``result["name"]`` gives an array; ``result.keys()`` lists them;
    ``result.info`` holds the figures (counts, Euler characteristic, ...); ``result.data``
    is the filter's vtkPolyData, for VTK pipelines and write_html.
    """

    def __init__(self, data, arrays, info=None, planar=False):
        self.data = data
        self.info = dict(info or {})
        self.planar = planar
        self._arrays = dict(arrays)

    def keys(self):
        return list(self._arrays)

    def __getitem__(self, name):
        return self._arrays[name]

    def __getattr__(self, name):
        arrays = self.__dict__.get("_arrays", {})
        if name in arrays:
            return arrays[name]
        raise AttributeError(f"no array '{name}' (arrays: {', '.join(arrays)})")

    def __contains__(self, name):
        return name in self._arrays

    def __repr__(self):
        rows = [f"  {name}: {a.dtype}{list(a.shape)}" if isinstance(a, np.ndarray) else f"  {name}: {len(a)} items"
                for name, a in self._arrays.items()]
        info = ", ".join(f"{k}={v:.6g}" if isinstance(v, float) else f"{k}={v}" for k, v in self.info.items())
        return "Result(\n" + "\n".join(rows) + (f"\n  info: {info}" if info else "") + "\n)"


# ---------------------------------------------------------------------------------------
# Input checks and conversions.

def _real_array(values, name, columns):
    try:
        a = np.asarray(values)
    except Exception as error:  # ragged lists
        raise ValueError(f"{name} must be a numeric array: {error}") from None
    if a.dtype == object or not (np.issubdtype(a.dtype, np.integer) or np.issubdtype(a.dtype, np.floating)):
        raise ValueError(f"{name} must hold real numbers, got dtype {a.dtype}")
    if a.ndim != 2 or a.shape[1] not in columns or a.shape[0] == 0:
        raise ValueError(f"{name} must have shape (n, {' or '.join(map(str, columns))}) with n > 0, got {a.shape}")
    a = a.astype(np.float64)
    if not np.isfinite(a).all():
        raise ValueError(f"{name} holds NaN or infinite values")
    return a


def _index_array(values, name, width, count):
    a = np.asarray(values)
    if not np.issubdtype(a.dtype, np.integer):
        raise ValueError(f"{name} must be an integer array (vertex indices), got dtype {a.dtype}")
    if a.ndim != 2 or a.shape[1] != width or a.shape[0] == 0:
        raise ValueError(f"{name} must have shape (m, {width}) with m > 0, got {a.shape}")
    if a.min() < 0 or a.max() >= count:
        raise ValueError(f"{name} holds indices outside [0, {count}): {a.min()} .. {a.max()}")
    return a.astype(np.int64)


def _points(xyz):
    points = vtkPoints()
    points.SetDataTypeToDouble()
    xyz = np.ascontiguousarray(xyz if xyz.shape[1] == 3 else np.column_stack([xyz, np.zeros(len(xyz))]))
    points.SetData(numpy_to_vtk(xyz, deep=True))
    return points


def _cells(rows):
    """A vtkCellArray from a list of index sequences (any lengths)."""
    offsets = np.zeros(len(rows) + 1, dtype=np.int64)
    offsets[1:] = np.cumsum([len(r) for r in rows])
    cells = vtkCellArray()
    cells.SetData(numpy_to_vtkIdTypeArray(offsets, deep=True),
                  numpy_to_vtkIdTypeArray(np.concatenate([np.asarray(r, dtype=np.int64) for r in rows]), deep=True))
    return cells


def to_polydata(vertices, triangles=None, *, lines=None):
    """A vtkPolyData of ``vertices`` (n, 3) or (n, 2) (z = 0) and ``triangles`` (m, 3)
    vertex indices, or closed ``lines`` (a list of index sequences). A vtkPolyData is
    returned as it is."""
    if isinstance(vertices, vtkPolyData):
        if triangles is not None or lines is not None:
            raise ValueError("give either a vtkPolyData or vertices with triangles, not both")
        return vertices
    if isinstance(vertices, Result):
        return vertices.data
    xyz = _real_array(vertices, "vertices", (2, 3))
    data = vtkPolyData()
    data.SetPoints(_points(xyz))
    if triangles is not None:
        data.SetPolys(_cells(_index_array(triangles, "triangles", 3, len(xyz))))
    if lines is not None:
        data.SetLines(_cells(lines))
    if triangles is None and lines is None:
        raise ValueError("give triangles (m, 3) with the vertices")
    return data


def _surface(vertices, triangles):
    data = to_polydata(vertices, triangles)
    if data.GetNumberOfPolys() == 0 and data.GetNumberOfLines() == 0:
        raise ValueError("the surface has no triangles")
    planar = isinstance(vertices, np.ndarray) and vertices.ndim == 2 and vertices.shape[1] == 2
    return data, planar


def _polygons(polygons):
    """Planar loops: a list of (k, 2) or (k, 3) arrays of loop points (outer boundaries and
    holes alike), as closed polylines."""
    if isinstance(polygons, vtkPolyData):
        return polygons, False
    if isinstance(polygons, np.ndarray) and polygons.ndim == 2:
        polygons = [polygons]
    loops = [_real_array(loop, f"polygons[{i}]", (2, 3)) for i, loop in enumerate(polygons)]
    if not loops:
        raise ValueError("polygons is empty: give a list of (k, 2) loops")
    for i, loop in enumerate(loops):
        if len(loop) < 3:
            raise ValueError(f"polygons[{i}] has {len(loop)} points; a loop needs 3 or more")
    columns = {loop.shape[1] for loop in loops}
    if len(columns) > 1:
        raise ValueError("polygons mixes (k, 2) and (k, 3) loops")
    xyz = np.concatenate(loops)
    starts = np.cumsum([0] + [len(loop) for loop in loops])
    rows = [list(range(s, e)) + [s] for s, e in zip(starts[:-1], starts[1:])]
    data = vtkPolyData()
    data.SetPoints(_points(xyz))
    data.SetLines(_cells(rows))
    return data, columns == {2}


def _count(value, name, lo, hi):
    if isinstance(value, bool) or not isinstance(value, numbers.Integral) or not lo <= value <= hi:
        raise ValueError(f"{name} must be a whole number in [{lo}, {hi}], got {value!r}")
    return int(value)


def _number(value, name, lo, hi):
    if isinstance(value, bool) or not isinstance(value, numbers.Real) or not lo <= value <= hi:
        raise ValueError(f"{name} must be a number in [{lo}, {hi}], got {value!r}")
    return float(value)


def _choice(value, name, table):
    if value not in table:
        raise ValueError(f"unknown {name} {value!r} ({', '.join(table)})")
    return table[value]


def _message(text):
    """A VTK message without its "ERROR: In file, line n" and "vtkClass (0x...): " lead."""
    text = text.strip().splitlines()[-1] if text and text.strip() else ""
    return text.split("): ", 1)[1] if "): " in text else text


def _watch(obj, errors, warnings_too=False):
    """Collects obj's error (and warning) messages into `errors` (observed, they are not
    printed); returns the observer tags."""
    @calldata_type(VTK_STRING)
    def on_error(caller, event, text):
        errors.append(("error", caller.GetClassName(), _message(text)))

    @calldata_type(VTK_STRING)
    def on_warning(caller, event, text):
        errors.append(("warning", caller.GetClassName(), _message(text)))
    tags = [obj.AddObserver(vtkCommand.ErrorEvent, on_error)]
    if warnings_too:
        tags.append(obj.AddObserver(vtkCommand.WarningEvent, on_warning))
    return tags


def _run(algorithm, inner=()):
    """Updates a filter; its warnings (and those of `inner` objects it runs) become Python
    RuntimeWarnings, its first error a RuntimeError."""
    messages = []
    watched = [algorithm, algorithm.GetExecutive(), *inner]
    tags = [(obj, _watch(obj, messages, warnings_too=True)) for obj in watched]
    try:
        algorithm.Update()
    finally:
        for obj, ids in tags:
            for tag in ids:
                obj.RemoveObserver(tag)
    for kind, name, text in messages:
        if kind == "warning":
            warnings.warn(f"{name}: {text}", RuntimeWarning, stacklevel=3)
    errors = [(name, text) for kind, name, text in messages if kind == "error"]
    if errors:
        raise RuntimeError(f"{errors[0][0]}: {errors[0][1]}")
    return algorithm.GetOutput()


def _array(data, name, cells=False):
    source = data.GetCellData() if cells else data.GetPointData()
    a = source.GetArray(name)
    return None if a is None else vtk_to_numpy(a).copy()


def _field(data, name):
    a = data.GetFieldData().GetArray(name)
    return None if a is None else a.GetTuple1(0)


def _xyz(data, planar):
    if data.GetNumberOfPoints() == 0:
        return np.zeros((0, 2 if planar else 3))
    xyz = vtk_to_numpy(data.GetPoints().GetData()).astype(np.float64)
    return xyz[:, :2].copy() if planar else xyz.copy()


def _cell_rows(cells):
    """The cells of a vtkCellArray as a list of index arrays, or an (m, k) array when all
    have k points."""
    offsets = vtk_to_numpy(cells.GetOffsetsArray()).astype(np.int64)
    ids = vtk_to_numpy(cells.GetConnectivityArray()).astype(np.int64)
    sizes = np.diff(offsets)
    if len(sizes) and (sizes == sizes[0]).all():
        return ids.reshape(-1, sizes[0]) if len(ids) else np.zeros((0, 2), dtype=np.int64)
    return [ids[a:b] for a, b in zip(offsets[:-1], offsets[1:])]


# ---------------------------------------------------------------------------------------
# The functions.

def demo_shape(name="jack", **parameters):
    """A generated shape as numpy arrays ``(vertices, triangles)`` (vtkMedialShapeSource):
    "jack" (the demo), "sphere", "box", "capsule", "torus", "hollow-sphere", "rings"; planar
    ones ("l-shape", "rectangle", "frame", "star", "ellipse", "trefoil") as
    ``(vertices (n, 2), loops)``, a list of index arrays. Keyword arguments set the source's
    parameters: radius, length, resolution, box_lengths, tube_radius, inner_radius, genus."""
    shapes = {"jack": "Jack", "sphere": "Sphere", "box": "Box", "capsule": "Capsule", "torus": "Torus",
              "hollow-sphere": "HollowSphere", "rings": "Rings", "l-shape": "LShape", "rectangle": "Rectangle",
              "frame": "SquareFrame", "star": "Star", "ellipse": "Ellipse", "trefoil": "Trefoil"}
    source = vtkMedialShapeSource()
    getattr(source, "SetShapeTo" + _choice(name, "shape", shapes))()
    setters = {"radius": "SetRadius", "length": "SetLength", "resolution": "SetResolution",
               "box_lengths": "SetBoxLengths", "tube_radius": "SetTubeRadius", "inner_radius": "SetInnerRadius",
               "genus": "SetGenus"}
    for key, value in parameters.items():
        setter = _choice(key, "parameter", setters)
        getattr(source, setter)(*(value if isinstance(value, (tuple, list)) else (value,)))
    data = _run(source)
    xyz = vtk_to_numpy(data.GetPoints().GetData()).astype(np.float64)
    polys = _cell_rows(data.GetPolys())
    if name in ("l-shape", "rectangle", "frame", "star", "ellipse", "trefoil"):
        return xyz[:, :2].copy(), list(polys)
    return xyz, polys


def medial_axis(vertices, triangles=None, *, samples=10000, seed=1, threads=0, method="one-pass",
                strategy="random", coverage=0.0, tolerance=1e-6, min_angle=45.0, max_protrusion=1e-4, repair="auto"):
    """The medial balls of a closed triangle mesh, or of a planar region (vertices (n, 2),
    or a flat mesh), by vtkMedialAxisSampler: one maximal inscribed ball per surface sample.

    Parameters mirror the command line: samples (-n), seed, threads (0: all cores),
    method ("one-pass", "bisection", "shrinking-ball"), strategy ("random",
    "closest-neighbor", "face-distance"), coverage, tolerance, min_angle (degrees),
    max_protrusion (relative to the diagonal), repair ("auto": a surface that is not a
    valid solid is repaired first, one RuntimeWarning per step; "none"; "wrap"; see
    docs/repair.md).

    Returns a Result with centres (k, 3) (k, 2 for 2D vertices), radii (k,),
    surface_points and contacts (k, 3 or 2: where each ball touches the surface),
    separation_angles (degrees), source_cells, and links (l, 2) when the strategy links
    balls; info: requested, discarded, capped, mean_iterations.
    """
    data, planar = _surface(vertices, triangles)
    sampler = vtkMedialAxisSampler()
    sampler.SetInputData(data)
    sampler.SetNumberOfSamples(_count(samples, "samples", 1, 10**15))
    sampler.SetRandomSeed(_count(seed, "seed", 0, 9 * 10**15))
    sampler.SetNumberOfThreads(_count(threads, "threads", 0, 4096))
    sampler.SetMethod(_choice(method, "method", METHODS))
    sampler.SetSamplingStrategy(_choice(strategy, "strategy", STRATEGIES))
    sampler.SetCoverageTolerance(_number(coverage, "coverage", 0.0, 1.0))
    sampler.SetTolerance(_number(tolerance, "tolerance", 1e-15, 0.1))
    sampler.SetMinimumSeparationAngle(_number(min_angle, "min_angle", 0.0, 179.0))
    sampler.SetMaximumProtrusion(_number(max_protrusion, "max_protrusion", 0.0, 1.0))
    sampler.SetRepairMode(_choice(repair, "repair", REPAIRS))
    out = vtkPolyData()
    out.DeepCopy(_run(sampler))
    arrays = {"centres": _xyz(out, planar), "radii": _array(out, "Radius")}
    for key, name in (("surface_points", "SurfacePoint"), ("contacts", "ContactPoint")):
        a = _array(out, name)
        if a is not None:
            arrays[key] = a[:, :2].copy() if planar else a
    for key, name in (("separation_angles", "SeparationAngle"), ("source_cells", "SourceCellId")):
        a = _array(out, name)
        if a is not None:
            arrays[key] = a
    if out.GetNumberOfLines() > 0:
        arrays["links"] = np.asarray(_cell_rows(out.GetLines()))
    info = {"requested": sampler.GetNumberOfSamples(), "discarded": sampler.GetDiscardedSamples(),
            "capped": sampler.GetCappedSamples(), "mean_iterations": sampler.GetMeanIterations()}
    return Result(out, arrays, info, planar)


def _balls_data(balls, name="balls"):
    if isinstance(balls, Result):
        return balls.data
    if isinstance(balls, vtkPolyData):
        return balls
    raise ValueError(f"{name} must be a Result (of medial_axis, medial_mesh, ...) or a vtkPolyData, "
                     f"got {type(balls).__name__}")


def medial_mesh(vertices, triangles=None, *, balls=None, samples=10000, seed=1, threads=0, min_angle=45.0,
                max_protrusion=1e-4, prune=False, prune_threshold=None, repair="auto"):
    """The medial mesh of a closed triangle mesh (vtkMedialMeshFilter): the balls joined
    by edges and triangles through the regular triangulation, with the solid's topology.

    balls: a Result of medial_axis (or a vtkPolyData) to join instead of sampling anew
    with samples, seed, min_angle, max_protrusion. threads as the command line.
    prune / prune_threshold: the mesh's branches pruned by the scale axis measure
    (vtkMedialPruneFilter; threshold default 1/3, a scale of 1.5). repair as medial_axis.

    Returns a Result with centres (k, 3), radii (k,), types (k,) (MedialPointType: 0 rim,
    1 sheet, 2 seam, 3 junction; type_names gives the names), governors (k,), edges (e, 2)
    (the 1D parts), faces (f, 3); info: euler_characteristic, components, the solid's
    solid_euler_characteristic and solid_components, and per type counts.
    """
    data, _ = _surface(vertices, triangles)
    mesh = vtkMedialMeshFilter()
    mesh.SetInputData(data)
    mesh.SetNumberOfThreads(_count(threads, "threads", 0, 4096))
    mesh.SetRepairMode(_choice(repair, "repair", REPAIRS))
    mesh.GetClassifier().SetMinimumSeparationAngle(_number(min_angle, "min_angle", 0.0, 179.0))
    if balls is not None:
        mesh.SetBallsData(_balls_data(balls))
    else:
        sampler = mesh.GetSampler()
        sampler.SetNumberOfSamples(_count(samples, "samples", 1, 10**15))
        sampler.SetRandomSeed(_count(seed, "seed", 0, 9 * 10**15))
        sampler.SetNumberOfThreads(_count(threads, "threads", 0, 4096))
        sampler.SetMinimumSeparationAngle(_number(min_angle, "min_angle", 0.0, 179.0))
        sampler.SetMaximumProtrusion(_number(max_protrusion, "max_protrusion", 0.0, 1.0))
    out = vtkPolyData()
    out.DeepCopy(_run(mesh, inner=(mesh.GetSampler(), mesh.GetClassifier())))
    info = {"euler_characteristic": mesh.GetEulerCharacteristic(), "components": mesh.GetNumberOfComponents(),
            "solid_euler_characteristic": mesh.GetSolidEulerCharacteristic(),
            "solid_components": mesh.GetSolidComponents()}
    if prune or prune_threshold is not None:
        pruner = vtkMedialPruneFilter()
        pruner.SetInputData(out)
        pruner.SetMeasureToScaleAxis()
        pruner.SetThreshold(_number(1.0 / 3.0 if prune_threshold is None else prune_threshold,
                                    "prune_threshold", 0.0, 1.0))
        pruned = vtkPolyData()
        pruned.DeepCopy(_run(pruner))
        out = pruned
        info["pruned_branches"] = pruner.GetNumberOfPrunedBranches()
    types = _array(out, "MedialPointType")
    arrays = {"centres": _xyz(out, False), "radii": _array(out, "Radius"), "types": types,
              "governors": _array(out, "GovernorCount"),
              "edges": np.asarray(_cell_rows(out.GetLines())).reshape(-1, 2) if out.GetNumberOfLines()
              else np.zeros((0, 2), dtype=np.int64),
              "faces": np.asarray(_cell_rows(out.GetPolys())).reshape(-1, 3) if out.GetNumberOfPolys()
              else np.zeros((0, 3), dtype=np.int64)}
    arrays["type_names"] = np.array(TYPES_3D)[types.astype(int)] if types is not None else np.array([])
    for code, name in enumerate(TYPES_3D):
        info[name + "s"] = int((types == code).sum()) if types is not None else 0
    return Result(out, arrays, info)


def thickness(vertices, triangles=None, *, min_angle=45.0, max_protrusion=1e-4, threads=0, below=None,
              surface_tolerance=0.25, repair="auto"):
    """The wall thickness of a closed triangle mesh at every vertex and triangle
    (vtkMedialThickness): the diameter of the largest inscribed ball touching there
    (within surface_tolerance times the local facet size; at a convex edge, the walls').

    min_angle, max_protrusion and threads as the command line; below: a thickness (in the
    mesh's units) under which the area is counted as thin (--thickness-below); repair as
    medial_axis (when the surface is repaired, the arrays are the repaired surface's, whose
    vertices are not the input's; repair="none" keeps the input's).

    Returns a Result with thickness (n,), medial_radius (n,), medial_centres (n, 3),
    tangent_thickness (n,), ray_thickness (n,) per vertex and cell_thickness (m,) per
    triangle; info: thin_area_fraction and thin_regions (with below).
    """
    data, planar = _surface(vertices, triangles)
    if planar:
        raise ValueError("thickness needs a 3D surface: vertices (n, 3)")
    wall = vtkMedialThickness()
    wall.SetInputData(data)
    wall.SetMinimumSeparationAngle(_number(min_angle, "min_angle", 0.0, 179.0))
    wall.SetMaximumProtrusion(_number(max_protrusion, "max_protrusion", 0.0, 1.0))
    wall.SetNumberOfThreads(_count(threads, "threads", 0, 4096))
    wall.SetSurfaceTolerance(_number(surface_tolerance, "surface_tolerance", 0.0, 10.0))
    wall.SetRepairMode(_choice(repair, "repair", REPAIRS))
    if below is not None:
        wall.SetThinThreshold(_number(below, "below", 1e-300, 1e300))
    out = vtkPolyData()
    out.DeepCopy(_run(wall))
    arrays = {"thickness": _array(out, "Thickness"), "medial_radius": _array(out, "MedialRadius"),
              "medial_centres": _array(out, "MedialCentre"), "tangent_thickness": _array(out, "TangentThickness"),
              "ray_thickness": _array(out, "RayThickness")}
    cell = _array(out, "Thickness", cells=True)
    if cell is not None:
        arrays["cell_thickness"] = cell
    info = {"thin_area_fraction": wall.GetThinAreaFraction(), "thin_regions": wall.GetThinRegionCount()} \
        if below is not None else {}
    return Result(out, arrays, info)


def junction_graph(polygons, *, threads=0, prune=False, prune_threshold=None):
    """The exact medial graph of planar polygons with holes (vtkMedialJunctionFilter).

    polygons: a list of loops, each a (k, 2) (or (k, 3), in any plane) array of points;
    outer boundaries and holes alike (nesting decides which is which). A flat triangle
    mesh given as vtkPolyData works too. prune / prune_threshold: insignificant branches
    removed, keeping the topology (tubularity, default 0.05), as --prune.

    Returns a Result with points (k, 2), radii (k,), types (k,) (MedialPointType: 0 end,
    1 regular, 2 junction), governors (k,), arcs (a list of index arrays, one polyline
    per arc), arc_types (0 linear, 1 parabolic), polygon_ids, and junctions and
    end_points (indices); info: junctions, end_points, arcs, polygons.
    """
    data, planar = _polygons(polygons)
    graph = vtkMedialJunctionFilter()
    graph.SetInputData(data)
    graph.SetNumberOfThreads(_count(threads, "threads", 0, 4096))
    out = vtkPolyData()
    out.DeepCopy(_run(graph))
    info = {"polygons": graph.GetNumberOfPolygons()}
    if prune or prune_threshold is not None:
        pruner = vtkMedialPruneFilter()
        pruner.SetInputData(out)
        if prune_threshold is not None:
            pruner.SetThreshold(_number(prune_threshold, "prune_threshold", 0.0, 1.0))
        pruned = vtkPolyData()
        pruned.DeepCopy(_run(pruner))
        out = pruned
        info["pruned_branches"] = pruner.GetNumberOfPrunedBranches()
    types = _array(out, "MedialPointType")
    arcs = _cell_rows(out.GetLines()) if out.GetNumberOfLines() else []
    arrays = {"points": _xyz(out, planar), "radii": _array(out, "Radius"), "types": types,
              "governors": _array(out, "GovernorCount"), "arcs": list(arcs),
              "arc_types": _array(out, "ArcType", cells=True), "polygon_ids": _array(out, "PolygonId", cells=True),
              "junctions": np.flatnonzero(types == 2), "end_points": np.flatnonzero(types == 0)}
    info.update({"junctions": len(arrays["junctions"]), "end_points": len(arrays["end_points"]),
                 "arcs": out.GetNumberOfLines()})
    return Result(out, arrays, info, planar)


def reconstruct(centres, radii=None, *, resolution=128, threads=0):
    """The boundary of the union of balls (disks for (k, 2) centres), by vtkMedialBallUnion
    on a grid of ``resolution`` points per axis (--resolution).

    centres: (k, 3) or (k, 2) array, with radii (k,); or a Result of medial_axis,
    medial_mesh or junction_graph (its radii are used).

    Returns a Result with vertices (n, 3) and triangles (m, 3) (3D), or vertices (n, 2)
    and lines (a list of index arrays, 2D); info: voxel_size.
    """
    if isinstance(centres, Result):
        if radii is not None:
            raise ValueError("give radii only with a centres array")
        balls = centres.data
        planar = centres.planar
    else:
        xyz = _real_array(centres, "centres", (2, 3))
        if radii is None:
            raise ValueError("give radii (k,) with the centres")
        r = _real_array(np.asarray(radii).reshape(-1, 1), "radii", (1,)).ravel()
        if len(r) != len(xyz):
            raise ValueError(f"{len(xyz)} centres but {len(r)} radii")
        if (r <= 0).any():
            raise ValueError("radii must be positive")
        planar = xyz.shape[1] == 2
        balls = vtkPolyData()
        balls.SetPoints(_points(xyz))
        radius = numpy_to_vtk(np.ascontiguousarray(r), deep=True)
        radius.SetName("Radius")
        balls.GetPointData().AddArray(radius)
    union = vtkMedialBallUnion()
    union.SetInputData(balls)
    n = _count(resolution, "resolution", 8, 2048)
    union.SetSampleDimensions(n, n, n)
    union.SetNumberOfThreads(_count(threads, "threads", 0, 4096))
    out = vtkPolyData()
    out.DeepCopy(_run(union))
    arrays = {"vertices": _xyz(out, planar)}
    if out.GetNumberOfPolys():
        arrays["triangles"] = np.asarray(_cell_rows(out.GetPolys()))
    if out.GetNumberOfLines():
        arrays["lines"] = list(_cell_rows(out.GetLines()))
    return Result(out, arrays, {"voxel_size": union.GetVoxelSize()}, planar)


def write_html(path, surface=None, *, balls=None, mesh=None, graph=None, reconstruction=None, wall=None,
               title="medialaxis", max_balls=100000):
    """One self-contained web page of results (vtkMedialHTMLWriter), as medial-axis --html.

    surface: (vertices, triangles), planar loops (a list of (k, 2) arrays) or a
    vtkPolyData; balls, mesh, graph, reconstruction: Results of the functions above (or
    vtkPolyData); wall: a Result of thickness, shown as the surface coloured by thickness.
    path None returns the page as a string; otherwise it is written and its size in
    bytes returned.
    """
    if not vtkMedialHTMLWriter.HasViewer():
        raise RuntimeError("this build has no web viewer: " + vtkMedialHTMLWriter.GetViewerStatus())
    writer = vtkMedialHTMLWriter()
    if wall is not None:
        writer.SetSurface(_balls_data(wall, "wall"))
    elif surface is not None:
        if isinstance(surface, tuple):
            writer.SetSurface(_surface(*surface)[0])
        elif isinstance(surface, list):
            writer.SetSurface(_polygons(surface)[0])
        else:
            writer.SetSurface(to_polydata(surface))
    for setter, name, value in (("SetBalls", "balls", balls), ("SetMedialMesh", "mesh", mesh),
                                ("SetGraph", "graph", graph), ("SetReconstruction", "reconstruction", reconstruction)):
        if value is not None:
            getattr(writer, setter)(_balls_data(value, name))
    writer.SetTitle(str(title))
    writer.SetMaximumNumberOfBalls(_count(max_balls, "max_balls", 1, 10**12))
    errors = []
    _watch(writer, errors)
    if path is None:
        writer.WriteToOutputStringOn()
    else:
        writer.SetFileName(str(path))
    if not writer.Write() or errors:
        raise RuntimeError("vtkMedialHTMLWriter: " + (errors[0][2] if errors else "failed"))
    return writer.GetOutputString() if path is None else writer.GetNumberOfBytes()
