"""medialaxis: medial axis transform filters for VTK pipelines."""
from .vtkMedialAxisFilters import *  # noqa: F401,F403
