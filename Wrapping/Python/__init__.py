"""medialaxis: medial axis transform filters, measures, readers, writers and pictures for VTK pipelines."""
from .vtkMedialAxisRepair import *  # noqa: F401,F403
from .vtkMedialAxisSampling import *  # noqa: F401,F403
from .vtkMedialAxisPlanar import *  # noqa: F401,F403
from .vtkMedialAxisStructure import *  # noqa: F401,F403
from .vtkMedialAxisReconstruction import *  # noqa: F401,F403
from .vtkMedialAxisStructure import *  # noqa: F401,F403
from .vtkMedialAxisSources import *  # noqa: F401,F403
from .vtkMedialAxisReaders import *  # noqa: F401,F403
from .vtkMedialAxisRendering import *  # noqa: F401,F403
