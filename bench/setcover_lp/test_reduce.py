# check reduce_patch keeps the optimum on small random covering instances
import numpy as np, scipy.sparse as sp
from scipy.optimize import milp, LinearConstraint, Bounds
from patches_dual import reduce_patch
rng = np.random.default_rng(1)
def opt(S, c):
    r = milp(c, constraints=LinearConstraint(S, lb=np.ones(S.shape[0]), ub=np.inf),
             integrality=np.ones(len(c)), bounds=Bounds(0, 1))
    return r.fun
for t in range(200):
    m, n = rng.integers(5, 25), rng.integers(5, 30)
    S = (rng.random((m, n)) < rng.uniform(0.1, 0.4)).astype(float)
    S[np.arange(m), rng.integers(0, n, m)] = 1
    S = np.vstack([S, S[:2]])                     # duplicate rows
    S = np.hstack([S, S[:, :3]])                  # duplicate columns
    c = rng.choice([0.5, 1.0, 0.25, 0.75], S.shape[1])
    S = sp.csc_matrix(S)
    R, cr = reduce_patch(S, c)
    a, b = opt(S, c), opt(R, cr)
    assert abs(a - b) < 1e-9, (t, a, b)
print("ok")
