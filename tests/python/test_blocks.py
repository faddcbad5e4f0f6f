"""A set of blocks from Python (eg2d.Blocks), as tests/c/test_blocks.c does
in C: the unit square with a bulging top as one block and as two blocks
joined down its middle solve to the same grid, and it is written as one
SU2 mesh; a bad join raises the error naming both ranges; the set keeps
its Grids alive; the blocks' names are read and set, a name another
block has is refused, and the .vtm names the block."""
import gc
import os

import numpy as np
import pytest

import eg2d

NI, NJ, MID = 17, 9, 8


def square(s, t):
    g = eg2d.Grid(len(s), len(t))
    top = lambda x: 1 + x * (1 - x) / 4  # noqa: E731
    g.set_side(eg2d.SIDE_JMIN, s, 0 * s)
    g.set_side(eg2d.SIDE_IMAX, 0 * t + s[-1], t * top(s[-1]))
    g.set_side(eg2d.SIDE_JMAX, s, top(s))
    g.set_side(eg2d.SIDE_IMIN, 0 * t + s[0], t * top(s[0]))
    return g


def test_set_is_the_single_block(tmp_path):
    s, t = np.linspace(0, 1, NI), np.linspace(0, 1, NJ)
    one = square(s, t)
    one.set_tolerance(1e-13)
    one.solve()
    x, y = one.get_coordinates()
    with eg2d.Blocks() as blocks:
        left, right = square(s[:MID + 1], t), square(s[MID:], t)
        assert (blocks.add(left), blocks.add(right)) == (0, 1)
        with pytest.raises(eg2d.Error) as e:
            blocks.join(0, eg2d.SIDE_IMAX, 0, 1, 1, eg2d.SIDE_IMIN, 0, 2)
        assert e.value.status == eg2d.ERR_ARGUMENT
        assert "block 0 side IMAX nodes 0..1 has 2 nodes, block 1 side IMIN nodes 0..2 has 3" in str(e.value)
        blocks.join(0, eg2d.SIDE_IMAX, 0, NJ - 1, 1, eg2d.SIDE_IMIN, 0, NJ - 1)
        # names: block0, block1 until named; the library's rule refused by name
        assert (blocks.name(0), blocks.name(1)) == ("block0", "block1")
        blocks.set_name(1, "right-half")
        with pytest.raises(eg2d.Error) as e:
            blocks.set_name(0, "right-half")
        assert e.value.status == eg2d.ERR_ARGUMENT and 'name "right-half": block 1 has that name' in str(e.value)
        assert (blocks.name(0), blocks.name(1)) == ("block0", "right-half")
        with pytest.raises(IndexError):
            blocks.name(2)
        left.set_tolerance(1e-13)
        del left, right  # the set keeps its Grids alive
        gc.collect()
        blocks.solve()
        iterations, residual, unknowns = blocks.run()
        assert unknowns == (NI - 2) * (NJ - 2) and residual <= 1e-13 and iterations > 0
        at, near = blocks.kinks()
        assert at > 0 and near > 0
        xl, yl = blocks._grids[0].get_coordinates()
        xr, yr = blocks._grids[1].get_coordinates()
        assert np.abs(xl - x[:MID + 1]).max() < 1e-9 and np.abs(yl - y[:MID + 1]).max() < 1e-9
        assert np.abs(xr - x[MID:]).max() < 1e-9 and np.abs(yr - y[MID:]).max() < 1e-9
        path = tmp_path / "set.su2"
        blocks.write(path, eg2d.FORMAT_SU2)
        text = path.read_text()
        assert "NELEM= %d" % ((NI - 1) * (NJ - 1)) in text
        assert "NPOIN= %d" % (NI * NJ) in text  # the joined nodes once
        blocks.write(tmp_path / "set.vtm", eg2d.FORMAT_VTM)  # VTK multiblock: a .vts a block in set/
        assert sorted(os.listdir(tmp_path / "set")) == ["set_0.vts", "set_1.vts"]
        assert 'file="set/set_1.vts"' in (tmp_path / "set.vtm").read_text()
        assert 'name="right-half"' in (tmp_path / "set.vtm").read_text()
    assert blocks.closed
    with pytest.raises(eg2d.StateError):
        blocks.solve()
    assert os.path.exists(path)
