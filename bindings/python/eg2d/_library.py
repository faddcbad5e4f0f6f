"""Finds and loads libeg2d.

Order: the environment variable EG2D_LIBRARY (a path to libeg2d.so.1); the
library directory recorded at install time (_location.py, relative to this
package); the system loader (libeg2d.so.1 on the default search path).
"""
import ctypes
import os

_SONAME = "libeg2d.so.1"


def _candidates():
    env = os.environ.get("EG2D_LIBRARY")
    if env:
        yield env
        return
    try:
        from . import _location  # written by `cmake --install`
    except ImportError:
        pass
    else:
        here = os.path.dirname(os.path.abspath(__file__))
        yield os.path.normpath(os.path.join(here, _location.LIBDIR_RELATIVE, _SONAME))
    yield _SONAME


def load():
    """The loaded library; OSError naming every place tried if none loads."""
    tried = []
    for path in _candidates():
        try:
            return ctypes.CDLL(path)
        except OSError as e:
            tried.append(f"{path}: {e}")
    raise OSError("eg2d: cannot load the library (set EG2D_LIBRARY to libeg2d.so.1): "
                  + "; ".join(tried))
