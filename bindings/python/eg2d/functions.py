"""The calls of the C API that need no grid."""
from ctypes import byref, c_double, c_int

from ._capi import lib
from .errors import error_for


def _text(b):
    return b.decode("utf-8", "replace") if b is not None else None


def status_string(status):
    """The English name of a status ("EG2D_ERR_BOUNDARY: inconsistent boundary")."""
    return _text(lib.eg2d_status_string(int(status)))


def last_error():
    """This thread's last failure of a call that had no grid (eg2d_last_error(NULL))."""
    return _text(lib.eg2d_last_error(None))


def version():
    """The library's version at run time, (major, minor, patch)."""
    major, minor, patch = c_int(), c_int(), c_int()
    lib.eg2d_version(byref(major), byref(minor), byref(patch))
    return major.value, minor.value, patch.value


def solver_name(solver):
    """A solver's short name ("psor"), or None if the library has no such solver."""
    return _text(lib.eg2d_solver_name(int(solver)))


def parameter_bounds(param):
    """(lower, upper, default) of a generic parameter EG2D_PARAM_*."""
    lower, upper, default = c_double(), c_double(), c_double()
    status = lib.eg2d_parameter_bounds(int(param), byref(lower), byref(upper), byref(default))
    if status:
        raise error_for(status, last_error())
    return lower.value, upper.value, default.value
