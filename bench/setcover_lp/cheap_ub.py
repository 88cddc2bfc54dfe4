import sys, time
from fractions import Fraction
import numpy as np
from scp import load, exact_primal
for name in sys.argv[1:]:
    t = time.time()
    m, n, c, A = load(name)
    assert np.all(c == 1)
    deg = np.diff(A.indptr)                    # columns covering each row
    csize = np.diff(A.tocsc().indptr)          # rows covered by each column
    Ac = A.tocsc()
    # x_j = max_{i in S_j} 1/deg(i)
    inv = 1.0 / deg
    x = np.zeros(n)
    rows_of = Ac.indices; ptr = Ac.indptr
    x = np.maximum.reduceat(inv[rows_of], ptr[:-1]) * (csize > 0)
    feas, k, num = exact_primal(A, x)
    print(f"{name}: m={m} n={n} nnz={A.nnz} rowdeg min/mean/max={deg.min()}/{deg.mean():.2f}/{deg.max()} "
          f"colsize min/mean/max={csize.min()}/{csize.mean():.2f}/{csize.max()}  "
          f"cheap UB feasible={feas} cost={num/2**30:.3f}  m/maxcol={m/csize.max():.1f} load {time.time()-t:.1f}s")
