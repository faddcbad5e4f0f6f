"""The C-grid cut's node count through the Python package (eg2d_get_cut): the library's
automatic count, about 0.21 (ni-1) (EG2D_PARAM_AIRFOIL_WAKE_NODES 0), and 0 on the other
topologies. That a program makes `eg2d airfoil`'s grid node for node:
tests/examples_match_command.sh over examples/*/command_grid.*."""
import eg2d


def test_cut_of_each_topology():
    g = eg2d.Grid(65, 33)
    assert g.get_cut() == 0
    g.set_airfoil(eg2d.Curve.naca4("0012"), eg2d.TOPO_O)
    assert g.get_cut() == 0
    g.set_airfoil(eg2d.Curve.naca4("0012"), eg2d.TOPO_C)
    assert g.get_cut() == 14  # 0.21 x 64 = 13.4: a multiple of 2 within 1.28 of it
    g = eg2d.Grid(385, 97)
    g.set_airfoil(eg2d.Curve.naca4("0012"), eg2d.TOPO_C)
    assert g.get_cut() == 80  # 80.6: a multiple of 16 (64 gave 0.167 (ni-1))
