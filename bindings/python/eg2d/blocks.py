"""Blocks: a set of blocks (one eg2d_blocks handle) solved as one grid,
freed by close(), by the end of a `with` block, or when collected.

    with eg2d.Blocks() as s:
        a, b = s.add(left), s.add(right)        # Grids with their sides set
        s.join(a, eg2d.SIDE_IMAX, 0, nj - 1, b, eg2d.SIDE_IMIN, 0, nj - 1)
        s.solve()                               # every block gets its part
        s.write("set.su2", eg2d.FORMAT_SU2)

The set refers to its Grids (eg2d.h, "Sets of blocks"): it keeps the Grid
objects alive while it is open. Threads: a set and its grids belong to one
thread at a time, as a Grid does.
"""
import os
from ctypes import byref, c_double, c_int

from ._capi import lib
from ._handle import Handle
from .errors import error_for
from .functions import _text, last_error


class Blocks(Handle):
    """A set of single-block grids joined node to node (eg2d_blocks_*)."""

    _kind = "set of blocks"

    def __init__(self):
        super().__init__()
        self._grids = []  # the set refers to them: keep them alive
        status = lib.eg2d_blocks_create(byref(self._h))
        if status:
            raise error_for(status, last_error())

    def _destroy(self, h):
        lib.eg2d_blocks_destroy(h)
        self._grids = []

    def _check(self, status):
        if status:
            raise error_for(status, self.last_error)

    @property
    def last_error(self):
        """The message of the last failed call on this set ("" if none)."""
        return _text(lib.eg2d_blocks_last_error(self._h)) if self._h else ""

    def add(self, grid):
        """Adds the Grid as the next block; returns its index."""
        b = c_int()
        self._check(lib.eg2d_blocks_add(self._handle(), grid._handle(), byref(b)))
        self._grids.append(grid)
        return b.value

    def set_name(self, block, name):
        """Names the block in the files that hold a zone a block (CGNS, VTK multiblock)."""
        self._check(lib.eg2d_blocks_set_name(self._handle(), int(block), str(name).encode()))

    def name(self, block):
        """The block's name ("block0", ... until named)."""
        n = lib.eg2d_blocks_name(self._handle(), int(block))
        if n is None:
            raise IndexError("the set has no block %d" % block)
        return _text(n)

    def join(self, block_a, side_a, first_a, last_a, block_b, side_b, first_b, last_b):
        """Nodes first_a..last_a of side_a of block_a are nodes first_b..last_b of side_b of block_b."""
        self._check(lib.eg2d_blocks_join(self._handle(), int(block_a), int(side_a), int(first_a), int(last_a),
                                         int(block_b), int(side_b), int(first_b), int(last_b)))

    def hold_join(self, join, held=True):
        """Join `join` (0 for the first) held where the blocks' sides put it, or free again."""
        self._check(lib.eg2d_blocks_hold_join(self._handle(), int(join), 1 if held else 0))

    def check(self):
        """Raises what solve() would raise before it iterates."""
        self._check(lib.eg2d_blocks_check(self._handle()))

    def solve(self):
        """Solves the set as one grid; each block's Grid holds its part."""
        self._check(lib.eg2d_blocks_solve(self._handle()))

    def run(self):
        """(iterations, residual, unknowns) of the last solve."""
        it, r, n = c_int(), c_double(), c_int()
        self._check(lib.eg2d_blocks_get_run(self._handle(), byref(it), byref(r), byref(n)))
        return it.value, r.value, n.value

    def kinks(self):
        """(at_joins, nearby): the largest turn of a grid line at the joins and one node in, degrees."""
        at, near = c_double(), c_double()
        self._check(lib.eg2d_blocks_get_kinks(self._handle(), byref(at), byref(near)))
        return at.value, near.value

    def write(self, path, format):
        """Writes the set to path as FORMAT_* (| PLOT3D_* flags): one mesh, a zone a block, or (FORMAT_VTM) a .vts a block named by the .vtm."""
        self._check(lib.eg2d_blocks_write(self._handle(), os.fsencode(path), int(format)))
