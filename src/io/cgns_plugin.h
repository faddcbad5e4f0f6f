/* The interface between libeg2d and its optional CGNS plugin
 * (libeg2d_cgns.so, linked with libcgns). libeg2d dlopen()s the plugin when
 * EG2D_FORMAT_CGNS is asked for, so that libeg2d never depends on libcgns.
 * Plain C, versioned by EG2D_CGNS_PLUGIN_ABI: a plugin whose
 * eg2d_cgns_plugin_abi() differs is not used. */
#ifndef EG2D_CGNS_PLUGIN_H
#define EG2D_CGNS_PLUGIN_H
#include <stddef.h>

#define EG2D_CGNS_PLUGIN_ABI 1
#define EG2D_CGNS_PLUGIN_NAME "libeg2d_cgns.so"

/* Writes one base (cell and physical dimension 2) with one structured zone
 * "eg2d" of ni x nj nodes (x, y in Fortran order) and, when nfields > 0, a
 * FlowSolution "Quality" at cell centres with the named (ni-1)*(nj-1)
 * arrays. Returns 0, or nonzero with a message in message[message_size]. */
typedef int (*eg2d_cgns_write_fn)(const char *path, int ni, int nj, const double *x, const double *y, int nfields,
                                  const char *const *names, const double *const *values, char *message,
                                  size_t message_size);
typedef int (*eg2d_cgns_abi_fn)(void);

#endif
