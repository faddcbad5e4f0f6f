"""eg2d: elliptic generation of boundary-fitted quadrilateral grids.

A ctypes + numpy package over libeg2d (include/eg2d.h is the manual): the
classes Grid, Curve and Blocks (a set of blocks), the grid-less calls (status_string, last_error, version,
solver_name, parameter_bounds, read_plot3d, read_points), the constants under their C names without the
EG2D_ prefix, and exceptions carrying the status and the library's message.
The library is found via $EG2D_LIBRARY, the install location, or the system
loader (see _library.py).

Threads (the rules of eg2d.h's "Threads", which hold for the package):
 - different Grid/Curve objects may be used from different threads at the
   same time: the library has no global mutable state, nor has the package;
 - one object, one call at a time: no call is locked inside, the queries
   included (get_residual caches, every failure writes the handle's error
   text); share a Grid between threads only behind your own threading.Lock;
 - an object may move between threads (no thread affinity) when the hand-over
   is synchronised (a lock, a join, a queue.Queue);
 - the grid-less calls (version, status_string, solver_name,
   parameter_bounds) are safe from any thread; last_error() is the calling
   thread's, Grid.last_error the grid's (read right after the failure);
 - the monitor runs on the thread of iterate/solve, inside that call: it may
   query its own grid (get_*), never change or close it.
The library is loaded with ctypes.CDLL, so every call releases the GIL for
its duration (and a monitor callback takes it back while it runs): solves of
different grids on different threads really run in parallel, and the GIL
gives no protection to a Grid shared between threads: lock it yourself.
"""
from .constants import *  # noqa: F401,F403
from .errors import (ArgumentError, BoundaryError, DivergedError, Error, FileError, FoldedError,  # noqa: F401
                     InternalError, NotConvergedError, OutOfMemoryError, StateError, StoppedByMonitor,
                     UnsupportedError, error_for)
from .functions import (last_error, parameter_bounds, read_plot3d, read_points, solver_name,  # noqa: F401
                        status_string, version)
from .functions import (format_info, list_entries, list_find, list_name, parameter_info,  # noqa: F401
                        quality_cell_field)
from .curve import Curve  # noqa: F401
from .functions import clustering_map, distribution, distribution_parameter, first_cell_height, tensor_parameter_grid  # noqa: F401,E501
from .grid import Grid  # noqa: F401
from .blocks import Blocks  # noqa: F401

__version__ = "%d.%d.%d" % (VERSION_MAJOR, VERSION_MINOR, VERSION_PATCH)  # noqa: F405
