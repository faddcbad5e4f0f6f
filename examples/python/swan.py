"""The swan of the elliptic-grid course notes from Python (run with PYTHONPATH at the package and,
outside an install, EG2D_LIBRARY=path/to/libeg2d.so.1)."""
import numpy as np

import eg2d

n = 65
s = np.arange(n) / (n - 1)
with eg2d.Grid(n, n) as g:
    g.set_side(eg2d.SIDE_JMIN, s, 0 * s)                      # bottom y = 0
    g.set_side(eg2d.SIDE_IMAX, 1 + 2 * s - 2 * s * s, s)      # right  x = 1+2y-2y^2
    g.set_side(eg2d.SIDE_JMAX, s, 1 - 2 * s + 2 * s * s)      # top    y = 1-2x+2x^2
    g.set_side(eg2d.SIDE_IMIN, 0 * s, s)                      # left   x = 0
    g.set_tolerance(1e-10)
    g.solve()                                                 # raises eg2d.Error with the message
    x, y = g.get_coordinates()                                # (ni, nj) arrays, x[i, j]
print(f"swan {n}x{n}: centre node ({x[n // 2, n // 2]:.6f}, {y[n // 2, n // 2]:.6f})")
