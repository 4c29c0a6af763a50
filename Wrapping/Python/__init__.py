"""medialaxis: medial axis transform filters, readers and writers for VTK pipelines."""
from .vtkMedialAxisFilters import *  # noqa: F401,F403
from .vtkMedialAxisReaders import *  # noqa: F401,F403
