"""The C API of include/eg2d.h for ctypes: the loaded library with every
prototype of _prototypes.py (generated from the header by
tools/gen_bindings.py: one entry per function, under the C name and in the C
argument order) set on it. The test bindings_cover_api checks that every
EG2D_API function is called by the package.
"""
from . import _library
from ._prototypes import PROTOTYPES, curve_fn, monitor_fn  # noqa: F401 (the callback types, for the wrappers)


def _bind():
    lib = _library.load()
    for name, (restype, argtypes) in PROTOTYPES.items():
        fn = getattr(lib, name)  # AttributeError: the library is older than this package
        fn.restype = restype
        fn.argtypes = argtypes
    return lib


lib = _bind()
