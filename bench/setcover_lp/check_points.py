# sanity: rebuild the rho=0.1 incidence from the points and compare with the written file
import sys, numpy as np
from scipy.spatial import cKDTree
from scp import load
pts = np.loadtxt(sys.argv[1]); rho = float(sys.argv[3])
m, n, c, A = load(sys.argv[2])
tree = cKDTree(pts)
pairs = tree.query_pairs(rho * 1.0 - 1e-12, output_type='ndarray')
# the C++ uses <= r^2 with r = rho*scale (scale=1 here); count only (approx check)
print("file nnz", A.nnz, "kd pairs*2+n", 2 * len(pairs) + n)
