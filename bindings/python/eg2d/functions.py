"""The calls of the C API that need no grid."""
import os
from ctypes import POINTER, byref, c_char_p, c_double, c_int

import numpy as np

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


def _check(status):
    if status:
        raise error_for(status, last_error())


def list_entries(list_id):
    """[(id, name), ...] of a library list (LIST_SOLVERS, LIST_PARAMETERS, ...), in id order."""
    count = c_int()
    _check(lib.eg2d_list_count(int(list_id), byref(count)))
    out = []
    for k in range(count.value):
        ident, name = c_int(), c_char_p()
        _check(lib.eg2d_list_entry(int(list_id), k, byref(ident), byref(name)))
        out.append((ident.value, _text(name.value)))
    return out


def list_name(list_id, ident):
    """The name of an id in a library list, or None."""
    return _text(lib.eg2d_list_name(int(list_id), int(ident)))


def list_find(list_id, name):
    """The id named `name` in a library list; ArgumentError (listing the valid names) if none."""
    ident = c_int()
    _check(lib.eg2d_list_find(int(list_id), name.encode("utf-8"), byref(ident)))
    return ident.value


def parameter_info(param):
    """(kind, unit, summary) of a parameter: kind has the VALUE_* bits."""
    kind, unit, summary = c_int(), c_char_p(), c_char_p()
    _check(lib.eg2d_parameter_info(int(param), byref(kind), byref(unit), byref(summary)))
    return kind.value, _text(unit.value), _text(summary.value)


def format_info(fmt):
    """(kind, suffix) of a file format: kind WRITES_FILE or WRITES_DIRECTORY."""
    kind, suffix = c_int(), c_char_p()
    _check(lib.eg2d_format_info(int(fmt), byref(kind), byref(suffix)))
    return kind.value, _text(suffix.value)


def quality_cell_field(metric):
    """The name of a quality metric's per-cell field ("area"), or None for a summary-only metric."""
    return _text(lib.eg2d_quality_cell_field(int(metric)))


def _dp(a):
    return a.ctypes.data_as(POINTER(c_double))


def read_plot3d(path, block=0):
    """Grid `block` of a Plot3D file (any variant eg2d_read_plot3d detects):
    (x, y, format, nblocks) with x, y numpy (ni, nj) in Fortran order and
    format the EG2D_FORMAT_PLOT3D* id with its PLOT3D_* flags."""
    p = os.fsencode(path)
    fmt, nblocks, ni, nj = c_int(), c_int(), c_int(), c_int()
    _check(lib.eg2d_read_plot3d(p, int(block), byref(fmt), byref(nblocks), byref(ni), byref(nj), None, None))
    x = np.empty((ni.value, nj.value), order="F")
    y = np.empty_like(x, order="F")
    _check(lib.eg2d_read_plot3d_into(p, int(block), x.size, None, None, None, None, _dp(x), _dp(y)))
    return x, y, fmt.value, nblocks.value


def read_points(path):
    """The points of a point file ("x y" per line, '#' comments): (x, y) numpy arrays."""
    p = os.fsencode(path)
    n = c_int()
    _check(lib.eg2d_read_points(p, 0, byref(n), None, None))
    x, y = np.empty(n.value), np.empty(n.value)
    _check(lib.eg2d_read_points(p, n.value, None, _dp(x), _dp(y)))
    return x, y


def distribution(distribution, n, p1=0.0, p2=0.0):
    """n points of a DIST_* distribution on [0, 1] (numpy array)."""
    s = np.empty(int(n))
    _check(lib.eg2d_distribution(int(distribution), int(n), float(p1), float(p2), _dp(s)))
    return s


def distribution_parameter(distribution, n, first_spacing, p2=0.0):
    """The p1 of a DIST_* distribution whose first spacing (a fraction of 1) is first_spacing with n points."""
    p1 = c_double()
    _check(lib.eg2d_distribution_parameter(int(distribution), int(n), float(first_spacing), float(p2), byref(p1)))
    return p1.value


def first_cell_height(yplus, reynolds, chord=1.0):
    """The wall spacing for a target y+ at a chord Reynolds number (flat-plate estimate)."""
    h = c_double()
    _check(lib.eg2d_first_cell_height(float(yplus), float(reynolds), float(chord), byref(h)))
    return h.value


def clustering_map(kind, a, n, b=0.0, strength=0.0):
    """Khattri's (2006) clustering map CLUSTER_* of [0, 1] sampled at n points (numpy array)."""
    u = np.empty(int(n))
    _check(lib.eg2d_clustering_map(int(kind), float(a), float(b), float(strength), int(n), _dp(u)))
    return u


def tensor_parameter_grid(u, v):
    """(s, t): numpy (len(u), len(v)) Fortran-order arrays, s[i, j] = u[i], t[i, j] = v[j]."""
    u = np.ascontiguousarray(u, dtype=np.float64)
    v = np.ascontiguousarray(v, dtype=np.float64)
    s = np.empty((len(u), len(v)), order="F")
    t = np.empty((len(u), len(v)), order="F")
    _check(lib.eg2d_tensor_parameter_grid(len(u), len(v), _dp(u), _dp(v), _dp(s), _dp(t)))
    return s, t
