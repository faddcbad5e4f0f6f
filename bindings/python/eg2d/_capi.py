"""The C API of include/eg2d.h for ctypes: one prototype per function, under
the C name and in the C argument order (the test bindings_cover_api checks
that every EG2D_API function is here, with its number of arguments, and is
called by the package).
"""
import ctypes
from ctypes import POINTER, c_char_p, c_double, c_int, c_void_p

from . import _library

grid_p = c_void_p  # eg2d_grid *
double_p = POINTER(c_double)
int_p = POINTER(c_int)
monitor_fn = ctypes.CFUNCTYPE(c_int, c_void_p, c_int, c_double)
curve_p = c_void_p  # eg2d_curve *
curve_fn = ctypes.CFUNCTYPE(None, c_void_p, c_double, double_p, double_p)

PROTOTYPES = {
    # errors and version
    "eg2d_status_string": (c_char_p, [c_int]),
    "eg2d_last_error": (c_char_p, [grid_p]),
    "eg2d_version": (None, [int_p, int_p, int_p]),
    # creating a grid
    "eg2d_create": (c_int, [c_int, c_int, POINTER(grid_p)]),
    "eg2d_destroy": (None, [grid_p]),
    "eg2d_set_topology": (c_int, [grid_p, c_int]),
    "eg2d_get_topology": (c_int, [grid_p, int_p]),
    # boundary and initial grid
    "eg2d_set_side": (c_int, [grid_p, c_int, double_p, double_p]),
    "eg2d_set_boundary": (c_int, [grid_p, double_p, double_p]),
    "eg2d_initialize": (c_int, [grid_p, c_int]),
    "eg2d_set_coordinates": (c_int, [grid_p, double_p, double_p]),
    # system, solver and run settings
    "eg2d_set_system": (c_int, [grid_p, c_int]),
    "eg2d_set_solver": (c_int, [grid_p, c_int]),
    "eg2d_get_solver": (c_int, [grid_p, int_p]),
    "eg2d_solver_name": (c_char_p, [c_int]),
    "eg2d_set_relaxation": (c_int, [grid_p, c_double]),
    "eg2d_set_tolerance": (c_int, [grid_p, c_double]),
    "eg2d_set_max_iterations": (c_int, [grid_p, c_int]),
    "eg2d_set_parameter": (c_int, [grid_p, c_int, c_double]),
    "eg2d_get_parameter": (c_int, [grid_p, c_int, double_p]),
    "eg2d_parameter_bounds": (c_int, [c_int, double_p, double_p, double_p]),
    "eg2d_set_af_cycle": (c_int, [grid_p, c_double, c_double, c_int]),
    "eg2d_set_af_time_rule": (c_int, [grid_p, c_double, c_double]),
    # running
    "eg2d_set_monitor": (c_int, [grid_p, monitor_fn, c_void_p]),
    "eg2d_iterate": (c_int, [grid_p, c_int, double_p]),
    "eg2d_solve": (c_int, [grid_p]),
    # grid control
    "eg2d_add_line_source": (c_int, [grid_p, c_int, c_double, c_double, c_double]),
    "eg2d_add_point_source": (c_int, [grid_p, c_double, c_double, c_double, c_double]),
    "eg2d_clear_sources": (c_int, [grid_p]),
    "eg2d_set_source_arrays": (c_int, [grid_p, double_p, double_p]),
    "eg2d_set_orthogonality": (c_int, [grid_p, c_int]),
    "eg2d_set_wall_spacing": (c_int, [grid_p, c_int, c_double]),
    "eg2d_set_parameter_grid": (c_int, [grid_p, double_p, double_p]),
    "eg2d_clustering_map": (c_int, [c_int, c_double, c_double, c_double, c_int, double_p]),
    "eg2d_tensor_parameter_grid": (c_int, [c_int, c_int, double_p, double_p, double_p, double_p]),
    "eg2d_set_weight": (c_int, [grid_p, double_p]),
    # curves and distributions
    "eg2d_curve_polyline": (c_int, [c_int, double_p, double_p, POINTER(curve_p)]),
    "eg2d_curve_spline": (c_int, [c_int, double_p, double_p, POINTER(curve_p)]),
    "eg2d_curve_function": (c_int, [curve_fn, c_void_p, POINTER(curve_p)]),
    "eg2d_curve_naca4": (c_int, [c_char_p, c_int, POINTER(curve_p)]),
    "eg2d_curve_read_airfoil": (c_int, [c_char_p, POINTER(curve_p)]),
    "eg2d_curve_destroy": (None, [curve_p]),
    "eg2d_curve_length": (c_int, [curve_p, double_p]),
    "eg2d_curve_evaluate": (c_int, [curve_p, c_double, double_p, double_p]),
    "eg2d_distribution": (c_int, [c_int, c_int, c_double, c_double, double_p]),
    "eg2d_curve_points": (c_int, [curve_p, c_int, c_int, c_double, c_double, double_p, double_p]),
    "eg2d_set_side_curve": (c_int, [grid_p, c_int, curve_p, c_int, c_double, c_double, c_int]),
    "eg2d_first_cell_height": (c_int, [c_double, c_double, c_double, double_p]),
    # queries
    "eg2d_get_size": (c_int, [grid_p, int_p, int_p]),
    "eg2d_get_coordinates": (c_int, [grid_p, double_p, double_p]),
    "eg2d_get_residual": (c_int, [grid_p, double_p]),
    "eg2d_get_iterations": (c_int, [grid_p, int_p]),
    "eg2d_get_quality": (c_int, [grid_p, c_int, double_p]),
    "eg2d_get_cell_quality": (c_int, [grid_p, c_int, double_p]),
    "eg2d_get_run_info": (c_int, [grid_p, c_int, int_p]),
    "eg2d_get_run_event": (c_int, [grid_p, c_int, int_p, c_char_p, c_int]),
    # files (paths as bytes: os.fsencode)
    "eg2d_write": (c_int, [grid_p, c_char_p, c_int]),
    "eg2d_read_plot3d": (c_int, [c_char_p, c_int, int_p, int_p, int_p, int_p, double_p, double_p]),
    "eg2d_read_plot3d_into": (c_int, [c_char_p, c_int, c_int, int_p, int_p, int_p, int_p, double_p, double_p]),
    "eg2d_read_points": (c_int, [c_char_p, c_int, int_p, double_p, double_p]),
    "eg2d_set_side_from_file": (c_int, [grid_p, c_int, c_char_p]),
}


def _bind():
    lib = _library.load()
    for name, (restype, argtypes) in PROTOTYPES.items():
        fn = getattr(lib, name)  # AttributeError: the library is older than this package
        fn.restype = restype
        fn.argtypes = argtypes
    return lib


lib = _bind()
