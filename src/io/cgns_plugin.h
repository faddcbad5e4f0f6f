/* The interface between libeg2d and its optional CGNS plugin
 * (libeg2d_cgns.so, linked with libcgns). libeg2d dlopen()s the plugin when
 * EG2D_FORMAT_CGNS is asked for, so that libeg2d never depends on libcgns.
 * Plain C, versioned by EG2D_CGNS_PLUGIN_ABI: a plugin whose
 * eg2d_cgns_plugin_abi() differs is not used. */
#ifndef EG2D_CGNS_PLUGIN_H
#define EG2D_CGNS_PLUGIN_H
#include <stddef.h>

#define EG2D_CGNS_PLUGIN_ABI 3
#define EG2D_CGNS_PLUGIN_NAME "libeg2d_cgns.so"

/* A boundary condition: BC_t `name` (unique in the zone) of the type
 * EG2D_PATCH_* `type` on the nodes range[] = {i1, j1, i2, j2} (1-based),
 * in the family `family` (one Family_t per patch name, whose FamilyBC has
 * the same type). */
typedef struct {
    const char *name, *family;
    int type;
    int range[4];
} eg2d_cgns_patch;

/* A 1-to-1 connection: the zone's nodes range[] match the nodes donor[] of
 * the zone `donor_zone` (both {i1, j1, i2, j2}, 1-based; the zone itself
 * across a cut) with the index transform transform[] (CGNS's short form:
 * +-1, +-2). */
typedef struct {
    const char *name, *donor_zone;
    int range[4], donor[4], transform[2];
} eg2d_cgns_connection;

/* One structured zone of a file: its name, ni x nj nodes (x, y in Fortran
 * order), the named (ni-1)*(nj-1) cell fields, its boundary conditions and
 * its 1-to-1 connections. */
typedef struct {
    const char *name;
    int ni, nj;
    const double *x, *y;
    int nfields;
    const char *const *names;
    const double *const *values;
    int npatches;
    const eg2d_cgns_patch *patches;
    int nconnections;
    const eg2d_cgns_connection *connections;
} eg2d_cgns_zone;

/* Writes one base (cell and physical dimension 2) with one structured zone
 * "eg2d" of ni x nj nodes (x, y in Fortran order) and, when nfields > 0, a
 * FlowSolution "Quality" at cell centres with the named (ni-1)*(nj-1)
 * arrays; a ZoneBC with the patches and a ZoneGridConnectivity with the
 * connections. Returns 0, or nonzero with a message in message[message_size]. */
typedef int (*eg2d_cgns_write_fn)(const char *path, int ni, int nj, const double *x, const double *y, int nfields,
                                  const char *const *names, const double *const *values, int npatches,
                                  const eg2d_cgns_patch *patches, int nconnections,
                                  const eg2d_cgns_connection *connections, char *message, size_t message_size);
/* Writes one base with the zones in order (a set of blocks), the families
 * of every zone's patches once. Returns as eg2d_cgns_write_fn. */
typedef int (*eg2d_cgns_write_zones_fn)(const char *path, int nzones, const eg2d_cgns_zone *zones, char *message,
                                        size_t message_size);
typedef int (*eg2d_cgns_abi_fn)(void);

#endif
