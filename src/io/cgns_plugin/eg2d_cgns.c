/* libeg2d_cgns.so: the optional CGNS writer of eg2d (see ../cgns_plugin.h).
 * A separate module so that only this file links libcgns. */
#include <cgnslib.h>
#include <stdio.h>
#include <string.h>

#include "io/cgns_plugin.h"

/* EG2D_PATCH_* (0 wall .. 4 symmetry) as CGNS boundary-condition types
 * (the SIDS' BCType_t). */
static BCType_t bc_type(int type) {
    switch (type) {
    case 0: return BCWall;
    case 1: return BCFarfield;
    case 2: return BCOutflow;
    case 3: return BCInflow;
    case 4: return BCSymmetryPlane;
    }
    return BCTypeUserDefined;
}

#if defined(__GNUC__)
#define PLUGIN_API __attribute__((visibility("default")))
#else
#define PLUGIN_API
#endif

PLUGIN_API int eg2d_cgns_plugin_abi(void) { return EG2D_CGNS_PLUGIN_ABI; }

static int failed(int fn, const char *what, char *message, size_t size) {
    snprintf(message, size, "libcgns: %s: %s", what, cg_get_error());
    if (fn >= 0) cg_close(fn);
    return 1;
}

/* One Family_t per patch name over every zone (a family's first BC names
 * it), so that a name split over stretches or blocks is one boundary for a
 * solver. */
static int write_families(int fn, int base, int nzones, const eg2d_cgns_zone *zones, char *message, size_t size) {
    int z, k, y, m, fam, fambc;
    for (z = 0; z < nzones; ++z)
        for (k = 0; k < zones[z].npatches; ++k) {
            const char *family = zones[z].patches[k].family;
            int seen = 0;
            for (y = 0; y <= z && !seen; ++y)
                for (m = 0; m < (y < z ? zones[y].npatches : k) && !seen; ++m)
                    seen = !strcmp(zones[y].patches[m].family, family);
            if (seen) continue;
            if (cg_family_write(fn, base, family, &fam) ||
                cg_fambc_write(fn, base, fam, "FamBC", bc_type(zones[z].patches[k].type), &fambc))
                return failed(fn, "cg_family_write", message, size);
        }
    return 0;
}

static int write_zone(int fn, int base, const eg2d_cgns_zone *z, char *message, size_t message_size) {
    int zone, coord, sol, field, k, m, bc, conn;
    cgsize_t size[6];
    size[0] = z->ni;
    size[1] = z->nj;
    size[2] = z->ni - 1;
    size[3] = z->nj - 1;
    size[4] = 0;
    size[5] = 0;
    if (cg_zone_write(fn, base, z->name, size, Structured, &zone))
        return failed(fn, "cg_zone_write", message, message_size);
    if (cg_coord_write(fn, base, zone, RealDouble, "CoordinateX", z->x, &coord) ||
        cg_coord_write(fn, base, zone, RealDouble, "CoordinateY", z->y, &coord))
        return failed(fn, "cg_coord_write", message, message_size);
    for (k = 1; k <= 2; ++k) {
        /* Exponents of (mass, length, time, temperature, angle): a length. */
        static const float length[5] = {0, 1, 0, 0, 0};
        if (cg_goto(fn, base, "Zone_t", zone, "GridCoordinates_t", 1, "DataArray_t", k, "end") ||
            cg_exponents_write(RealSingle, length))
            return failed(fn, "cg_exponents_write", message, message_size);
    }
    if (z->nfields > 0) {
        if (cg_sol_write(fn, base, zone, "Quality", CellCenter, &sol))
            return failed(fn, "cg_sol_write", message, message_size);
        for (k = 0; k < z->nfields; ++k)
            if (cg_field_write(fn, base, zone, sol, RealDouble, z->names[k], z->values[k], &field))
                return failed(fn, "cg_field_write", message, message_size);
    }
    for (k = 0; k < z->npatches; ++k) {
        cgsize_t range[4];
        for (m = 0; m < 4; ++m) range[m] = z->patches[k].range[m];
        if (cg_boco_write(fn, base, zone, z->patches[k].name, bc_type(z->patches[k].type), PointRange, 2, range, &bc))
            return failed(fn, "cg_boco_write", message, message_size);
        if (cg_goto(fn, base, "Zone_t", zone, "ZoneBC_t", 1, "BC_t", bc, "end") ||
            cg_famname_write(z->patches[k].family))
            return failed(fn, "cg_famname_write", message, message_size);
    }
    for (k = 0; k < z->nconnections; ++k) {
        cgsize_t range[4], donor[4];
        int transform[2];
        for (m = 0; m < 4; ++m) {
            range[m] = z->connections[k].range[m];
            donor[m] = z->connections[k].donor[m];
        }
        transform[0] = z->connections[k].transform[0];
        transform[1] = z->connections[k].transform[1];
        if (cg_1to1_write(fn, base, zone, z->connections[k].name, z->connections[k].donor_zone, range, donor, transform,
                          &conn))
            return failed(fn, "cg_1to1_write", message, message_size);
    }
    return 0;
}

PLUGIN_API int eg2d_cgns_plugin_write_zones(const char *path, int nzones, const eg2d_cgns_zone *zones, char *message,
                                            size_t message_size) {
    int fn = -1, base, z;
    if (cg_open(path, CG_MODE_WRITE, &fn)) return failed(-1, "cg_open", message, message_size);
    if (cg_base_write(fn, "Base", 2, 2, &base)) return failed(fn, "cg_base_write", message, message_size);
    /* The coordinates are lengths in the user's unknown unit. */
    if (cg_goto(fn, base, "end") || cg_dataclass_write(NormalizedByUnknownDimensional))
        return failed(fn, "cg_dataclass_write", message, message_size);
    if (write_families(fn, base, nzones, zones, message, message_size)) return 1;
    for (z = 0; z < nzones; ++z)
        if (write_zone(fn, base, &zones[z], message, message_size)) return 1;
    if (cg_close(fn)) return failed(-1, "cg_close", message, message_size);
    return 0;
}

PLUGIN_API int eg2d_cgns_plugin_write(const char *path, int ni, int nj, const double *x, const double *y,
                                      int nfields, const char *const *names, const double *const *values,
                                      int npatches, const eg2d_cgns_patch *patches, int nconnections,
                                      const eg2d_cgns_connection *connections, char *message,
                                      size_t message_size) {
    const eg2d_cgns_zone zone = {"eg2d", ni, nj, x, y, nfields, names, values, npatches, patches, nconnections, connections};
    return eg2d_cgns_plugin_write_zones(path, 1, &zone, message, message_size);
}
