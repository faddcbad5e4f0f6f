/* Writes a set of blocks as one mesh, for blocks_formats.py to check with
 * readers eg2d did not write (meshio, OpenFOAM's checkMesh). Usage:
 * write_block_samples DIR [no-cgns]. The backward-facing step of block_domains.h
 * (blocks 25x41, 81x41 and 81x17), solved, with the patches: "wall" on
 * every wall (the floors, the top, the step's face), "inlet" (block 0's
 * IMIN), "outlet" (blocks 1 and 2's IMAX); the joins none. Writes
 * DIR/step.su2, the OpenFOAM case DIR/step_foam (and DIR/rewritten_foam:
 * the set's case with its cellZones, then block 0 alone over it, which
 * removes them), the three blocks as zones
 * of the one-cell-thick ASCII Plot3D DIR/step.p3d, a zone a block with
 * its boundary conditions and the joins as 1-to-1 connections in
 * DIR/step.cgns (unless no-cgns; and there a block named as a patch is
 * refused: EG2D_ERR_ARGUMENT, no DIR/clash.cgns), VTK's multiblock DIR/step.vtm (its
 * blocks in DIR/step/), DIR/step.txt: "cells points wall inlet outlet",
 * the counts worked out here from the blocks, and DIR/step_nodes.txt:
 * each block's "ni nj" line, then its nodes "x y" (eg2d_get_coordinates,
 * i fastest), and each block's grid as eg2d_write's vts DIR/step-K.vts
 * (what the .vtm's block files must equal). Block 0's grid alone as DIR/one.vtm. Then refuses
 * EG2D_FORMAT_VTS for a set (EG2D_ERR_UNSUPPORTED) and a .vtm path without
 * an extension (EG2D_ERR_ARGUMENT, nothing written), and fails as a whole
 * (EG2D_ERR_IO naming the file, no .vtm, no block file, no temporary left):
 * a file where the blocks' directory goes, a directory where a block file
 * goes, a .vtm that is a FIFO with no reader (the blocks' directory, made
 * for it, removed again). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <dirent.h>
#include <sys/stat.h>
#include <unistd.h>

#include "block_domains.h"
#include "eg2d.h"

static void check(int status, const char *what, const char *message) {
    if (status != EG2D_OK) {
        fprintf(stderr, "%s: %s\n", what, message);
        exit(1);
    }
}

/* Each block's size and nodes, for the VTK multiblock check. */
static void write_nodes(const char *path, eg2d_grid *const *g, int n) {
    FILE *f = fopen(path, "w");
    if (!f) exit(1);
    for (int b = 0; b < n; ++b) {
        int ni, nj;
        check(eg2d_get_size(g[b], &ni, &nj), "eg2d_get_size", eg2d_last_error(g[b]));
        double *x = malloc(sizeof(double) * (size_t)ni * (size_t)nj), *y = malloc(sizeof(double) * (size_t)ni * (size_t)nj);
        if (!x || !y) exit(1);
        check(eg2d_get_coordinates(g[b], x, y), "eg2d_get_coordinates", eg2d_last_error(g[b]));
        fprintf(f, "%d %d\n", ni, nj);
        for (long k = 0; k < (long)ni * nj; ++k) fprintf(f, "%.17g %.17g\n", x[k], y[k]);
        free(x), free(y);
    }
    if (fclose(f)) exit(1);
}

static int exists(const char *dir, const char *name) {
    char path[4096];
    struct stat st;
    snprintf(path, sizeof path, "%s/%s", dir, name);
    return lstat(path, &st) == 0;
}

/* A temporary (".eg2d-tmp-") left in dir (none where dir is no directory). */
static int temporary_left(const char *dir) {
    DIR *d = opendir(dir);
    struct dirent *e;
    int found = 0;
    if (!d) return 0;
    while ((e = readdir(d)) != NULL) found |= strstr(e->d_name, ".eg2d-tmp-") != NULL;
    closedir(d);
    return found;
}

/* The set written as DIR/NAME.vtm fails with EG2D_ERR_IO naming `what`,
 * and leaves no .vtm, no block 0 and no temporary behind. */
static int vtm_fails(eg2d_blocks *set, const char *dir, const char *name, const char *what) {
    char path[4096], blocks[4096], block0[4096];
    snprintf(path, sizeof path, "%s/%s.vtm", dir, name);
    snprintf(blocks, sizeof blocks, "%s/%s", dir, name);
    snprintf(block0, sizeof block0, "%s_0.vts", name);
    struct stat st;
    const int is_fifo = stat(path, &st) == 0 && S_ISFIFO(st.st_mode);
    if (eg2d_blocks_write(set, path, EG2D_FORMAT_VTM) != EG2D_ERR_IO || !strstr(eg2d_blocks_last_error(set), what) ||
        (!is_fifo && exists(dir, strrchr(path, '/') + 1)) || exists(blocks, block0) || temporary_left(dir) ||
        temporary_left(blocks)) {
        fprintf(stderr, "%s.vtm: \"%s\": a half set left, or not the error expected (%s)\n", name,
                eg2d_blocks_last_error(set), what);
        return 0;
    }
    return 1;
}

static void left_half(int i, int j, int *I, int *J, const int *p) { (void)p, *I = i, *J = j; }
static void right_quarter(int i, int j, int *I, int *J, const int *p) { (void)p, *I = 8 + j, *J = 8 - i; }

int main(int argc, char **argv) {
    if (argc < 2 || argc > 3) {
        fprintf(stderr, "usage: write_block_samples DIR [no-cgns]\n");
        return 2;
    }
    enum { UP = 25, DOWN = 81, UPPER = 41, LOWER = 17 };
    eg2d_grid *g[3];
    eg2d_blocks *set;
    check(step_blocks(UP, DOWN, UPPER, LOWER, g, &set), "step_blocks", eg2d_last_error(NULL));
    /* The step's blocks named (their CGNS zones and VTK blocks); the turned pair keeps block0, block1. */
    check(eg2d_blocks_set_name(set, 0, "upstream") || eg2d_blocks_set_name(set, 1, "upper") ||
              eg2d_blocks_set_name(set, 2, "lower"),
          "eg2d_blocks_set_name", eg2d_blocks_last_error(set));
    const struct {
        int block, side, first, last, type;
        const char *name;
    } patches[] = {
        {0, EG2D_SIDE_JMIN, 0, UP - 1, EG2D_PATCH_WALL, "wall"},    {0, EG2D_SIDE_JMAX, 0, UP - 1, EG2D_PATCH_WALL, "wall"},
        {0, EG2D_SIDE_IMIN, 0, UPPER - 1, EG2D_PATCH_INFLOW, "inlet"},
        {1, EG2D_SIDE_JMAX, 0, DOWN - 1, EG2D_PATCH_WALL, "wall"},  {1, EG2D_SIDE_IMAX, 0, UPPER - 1, EG2D_PATCH_OUTFLOW, "outlet"},
        {2, EG2D_SIDE_JMIN, 0, DOWN - 1, EG2D_PATCH_WALL, "wall"},  {2, EG2D_SIDE_IMIN, 0, LOWER - 1, EG2D_PATCH_WALL, "wall"},
        {2, EG2D_SIDE_IMAX, 0, LOWER - 1, EG2D_PATCH_OUTFLOW, "outlet"},
    };
    for (size_t k = 0; k < sizeof patches / sizeof patches[0]; ++k)
        check(eg2d_set_patch(g[patches[k].block], patches[k].side, patches[k].first, patches[k].last, patches[k].type,
                             patches[k].name),
              "eg2d_set_patch", eg2d_last_error(g[patches[k].block]));
    check(eg2d_blocks_solve(set), "eg2d_blocks_solve", eg2d_blocks_last_error(set));
    char path[4096];
    snprintf(path, sizeof path, "%s/step.su2", argv[1]);
    check(eg2d_blocks_write(set, path, EG2D_FORMAT_SU2), path, eg2d_blocks_last_error(set));
    snprintf(path, sizeof path, "%s/step_foam", argv[1]);
    check(eg2d_blocks_write(set, path, EG2D_FORMAT_OPENFOAM), path, eg2d_blocks_last_error(set));
    {   /* a grid written over a set's case: the set's cell zones go with its mesh */
        char zones[4200];
        snprintf(path, sizeof path, "%s/rewritten_foam", argv[1]);
        check(eg2d_blocks_write(set, path, EG2D_FORMAT_OPENFOAM), path, eg2d_blocks_last_error(set));
        snprintf(zones, sizeof zones, "%s/constant/polyMesh/cellZones", path);
        check(access(zones, F_OK), zones, "no cellZones written for a set");
        check(eg2d_write(g[0], path, EG2D_FORMAT_OPENFOAM), path, eg2d_last_error(g[0]));
        check(access(zones, F_OK) == 0, zones, "an earlier set's cellZones left beside a single grid's mesh");
    }
    snprintf(path, sizeof path, "%s/step.p3d", argv[1]);
    check(eg2d_blocks_write(set, path, EG2D_FORMAT_PLOT3D_ASCII | EG2D_PLOT3D_EXTRUDED), path, eg2d_blocks_last_error(set));
    if (argc < 3 || strcmp(argv[2], "no-cgns")) {
        snprintf(path, sizeof path, "%s/step.cgns", argv[1]);
        check(eg2d_blocks_write(set, path, EG2D_FORMAT_CGNS), path, eg2d_blocks_last_error(set));
        /* A block named as a patch (a family of the base): refused by name, no file. */
        snprintf(path, sizeof path, "%s/clash.cgns", argv[1]);
        check(eg2d_blocks_set_name(set, 1, "outlet"), "eg2d_blocks_set_name", eg2d_blocks_last_error(set));
        if (eg2d_blocks_write(set, path, EG2D_FORMAT_CGNS) != EG2D_ERR_ARGUMENT ||
            !strstr(eg2d_blocks_last_error(set), "block 1's name \"outlet\" is also a patch's") || access(path, F_OK) == 0) {
            fprintf(stderr, "%s: a block named as a patch was not refused: %s\n", path, eg2d_blocks_last_error(set));
            return 1;
        }
        check(eg2d_blocks_set_name(set, 1, "upper"), "eg2d_blocks_set_name", eg2d_blocks_last_error(set));
    }
    snprintf(path, sizeof path, "%s/step.vtm", argv[1]);
    check(eg2d_blocks_write(set, path, EG2D_FORMAT_VTM), path, eg2d_blocks_last_error(set));
    snprintf(path, sizeof path, "%s/step_nodes.txt", argv[1]);
    write_nodes(path, g, 3);
    for (int b = 0; b < 3; ++b) {
        snprintf(path, sizeof path, "%s/step-%d.vts", argv[1], b);
        check(eg2d_write(g[b], path, EG2D_FORMAT_VTS), path, eg2d_last_error(g[b]));
    }
    snprintf(path, sizeof path, "%s/one.vtm", argv[1]);
    check(eg2d_write(g[0], path, EG2D_FORMAT_VTM), path, eg2d_last_error(g[0]));
    snprintf(path, sizeof path, "%s/step.vts", argv[1]);
    if (eg2d_blocks_write(set, path, EG2D_FORMAT_VTS) != EG2D_ERR_UNSUPPORTED ||
        !strstr(eg2d_blocks_last_error(set),
                "the vts format cannot hold a set of blocks (plot3d, plot3d-ascii, cgns, su2, openfoam, vtm can")) {
        fprintf(stderr, "VTS for a set: \"%s\"\n", eg2d_blocks_last_error(set));
        return 1;
    }
    struct stat st;
    snprintf(path, sizeof path, "%s/bare", argv[1]);
    if (eg2d_blocks_write(set, path, EG2D_FORMAT_VTM) != EG2D_ERR_ARGUMENT ||
        !strstr(eg2d_blocks_last_error(set), "/bare: a VTK multiblock file needs an extension (NAME.vtm)") ||
        stat(path, &st) == 0) {
        fprintf(stderr, "a .vtm path without an extension: \"%s\"\n", eg2d_blocks_last_error(set));
        return 1;
    }
    char held[4096];
    snprintf(path, sizeof path, "%s/clash", argv[1]);
    FILE *clash = fopen(path, "w");
    snprintf(held, sizeof held, "%s/held", argv[1]);
    mkdir(held, 0777);
    snprintf(held, sizeof held, "%s/held/held_1.vts", argv[1]);
    mkdir(held, 0777);
    snprintf(path, sizeof path, "%s/pipe.vtm", argv[1]);
    if (!clash || fclose(clash) || mkfifo(path, 0666) ||
        !vtm_fails(set, argv[1], "clash", "/clash: cannot make the directory: a file that is not a directory is in the way") ||
        !vtm_fails(set, argv[1], "held", "/held/held_1.vts: is a directory: not written, and not replaced") ||
        !vtm_fails(set, argv[1], "pipe", "/pipe.vtm: a FIFO with no reader: not written") || exists(argv[1], "pipe"))
        return 1;
    /* The bump in two blocks, the right one turned by 90 degrees (its JMIN
     * joined to the left one's IMAX the other way round): a 1-to-1
     * connection with the transform [2, -1] (block_domains.h). */
    if (argc < 3 || strcmp(argv[2], "no-cgns")) {
        eg2d_grid *h[2];
        eg2d_blocks *pair = NULL;
        const int mid = 8;
        check(bump_block(17, 9, mid + 1, 9, left_half, NULL, &h[0]), "bump_block", eg2d_last_error(NULL));
        check(bump_block(17, 9, 9, 17 - mid, right_quarter, NULL, &h[1]), "bump_block", eg2d_last_error(NULL));
        int b;
        check(eg2d_blocks_create(&pair), "eg2d_blocks_create", eg2d_last_error(NULL));
        const int rc = eg2d_blocks_add(pair, h[0], &b) || eg2d_blocks_add(pair, h[1], &b) ||
                       eg2d_blocks_join(pair, 0, EG2D_SIDE_IMAX, 0, 8, 1, EG2D_SIDE_JMIN, 8, 0) || eg2d_blocks_solve(pair);
        check(rc, "the turned pair", eg2d_blocks_last_error(pair));
        snprintf(path, sizeof path, "%s/turned.cgns", argv[1]);
        check(eg2d_blocks_write(pair, path, EG2D_FORMAT_CGNS), path, eg2d_blocks_last_error(pair));
        eg2d_blocks_destroy(pair);
        eg2d_destroy(h[0]), eg2d_destroy(h[1]);
    }
    /* Cells; points: every block's nodes less one per joined node (the
     * step's corner is in both joins and three blocks: two fewer, as the
     * sum of the joins' counts says); edges per patch. */
    const long cells = (long)(UP - 1) * (UPPER - 1) + (long)(DOWN - 1) * (UPPER - 1) + (long)(DOWN - 1) * (LOWER - 1);
    const long points = (long)UP * UPPER + (long)DOWN * UPPER + (long)DOWN * LOWER - UPPER - DOWN;
    const long wall = 2 * (UP - 1) + 2 * (DOWN - 1) + (LOWER - 1), inlet = UPPER - 1, outlet = (UPPER - 1) + (LOWER - 1);
    snprintf(path, sizeof path, "%s/step.txt", argv[1]);
    FILE *f = fopen(path, "w");
    if (!f) return 1;
    fprintf(f, "%ld %ld %ld %ld %ld\n", cells, points, wall, inlet, outlet);
    fclose(f);
    eg2d_blocks_destroy(set);
    for (int k = 0; k < 3; ++k) eg2d_destroy(g[k]);
    return 0;
}
