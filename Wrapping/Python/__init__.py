"""medialaxis: medial axis transform filters, measures, readers, writers and pictures for VTK pipelines.

The VTK classes (vtkMedialAxisSampler, vtkMedialMeshFilter, ...) are here, and the
numpy-level functions of medialaxis.arrays: medial_axis, medial_mesh, thickness,
junction_graph, reconstruct, write_html, demo_shape (see help(medialaxis.arrays)).
"""
from .vtkMedialAxisRepair import *  # noqa: F401,F403
from .vtkMedialAxisSampling import *  # noqa: F401,F403
from .vtkMedialAxisPlanar import *  # noqa: F401,F403
from .vtkMedialAxisStructure import *  # noqa: F401,F403
from .vtkMedialAxisReconstruction import *  # noqa: F401,F403
from .vtkMedialAxisSources import *  # noqa: F401,F403
from .vtkMedialAxisReaders import *  # noqa: F401,F403
from .vtkMedialAxisRendering import *  # noqa: F401,F403
from .vtkMedialAxisRenderingWeb import *  # noqa: F401,F403
from .arrays import (Result, demo_shape, junction_graph, medial_axis, medial_mesh,  # noqa: F401
                     reconstruct, thickness, to_polydata, write_html)
