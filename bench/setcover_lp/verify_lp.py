"""Repair + exactly verify an LP solution file (x, u) for INSTANCE: prints the verified LP
upper bound (feasible x, rounded up to 2^-30, A x >= 1 checked in integers) and lower bound
(u >= 0 scaled so A^T u <= 1, rounded down, checked in integers)."""
import sys
import numpy as np
from scp import load, exact_primal, exact_dual
from pdhg import repair_primal, dual_scaled
name, sol = sys.argv[1], sys.argv[2]
m, n, c, A = load(name); Ac = A.tocsc()
w = np.load(sol)
x = repair_primal(A, Ac, w['x'])
fp, kx, numx = exact_primal(A, x)
print(f"{name}: raw c.x {w['x'].sum():.6f}; VERIFIED primal feasible={fp}: LP <= {numx}/2^30 = {numx/2**30:.6f}")
if w['u'] is not None and w['u'].shape != ():
    u = dual_scaled(Ac, w['u'])
    fd, ku, numu = exact_dual(A, u)
    print(f"{name}: raw 1.u {w['u'].sum():.6f}; VERIFIED dual feasible={fd}: LP >= {numu}/2^30 = {numu/2**30:.6f}")
