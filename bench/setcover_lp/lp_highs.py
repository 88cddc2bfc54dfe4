"""Solve the LP relaxation min 1.x, A x >= 1, x >= 0 with HiGHS (scipy) and save x and duals."""
import sys, time
import numpy as np
from scipy.optimize import linprog
from scp import load
name, method, tl = sys.argv[1], sys.argv[2], float(sys.argv[3])
m, n, c, A = load(name)
t = time.time()
res = linprog(c, A_ub=-A, b_ub=-np.ones(m), bounds=(0, None), method=method,
              options=dict(time_limit=tl, disp=True, presolve=True))
print("status", res.status, res.message, "fun", res.fun, "secs", time.time() - t, flush=True)
if res.x is not None:
    u = -res.ineqlin.marginals if res.ineqlin is not None else None
    np.savez(name.replace('.txt', f'_{method}.npz'), x=res.x, u=u)
