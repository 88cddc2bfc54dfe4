"""Shared helpers: read an OR-Library row-format set-cover file, exact feasibility checks."""
import numpy as np
import scipy.sparse as sp

def load(path):
    with open(path, 'rb') as f:
        tok = np.array(f.read().split(), dtype=np.int64)
    m, n = int(tok[0]), int(tok[1])
    cost = tok[2:2 + n].astype(float)
    pos = 2 + n
    indptr = np.zeros(m + 1, dtype=np.int64)
    # rows: count k then k 1-based column indices
    idx_chunks = []
    for i in range(m):
        k = int(tok[pos]); pos += 1
        idx_chunks.append(tok[pos:pos + k]); pos += k
        indptr[i + 1] = indptr[i] + k
    assert pos == len(tok), "trailing data"
    cols = np.concatenate(idx_chunks) - 1
    A = sp.csr_matrix((np.ones(len(cols)), cols, indptr), shape=(m, n))
    A.sum_duplicates()
    return m, n, cost, A   # A[i, j] = 1 iff column j covers row i

SCALE = 2 ** 30

def exact_primal(A, x):
    """Round x up to multiples of 2^-30 and check A x >= 1 in exact integer arithmetic.
    Returns (feasible, exact cost as a Fraction-compatible pair (numerator, denominator))."""
    k = np.ceil(np.maximum(x, 0) * SCALE).astype(np.int64)
    Ai = A.astype(np.int64)
    cov = Ai @ k                      # int64, exact (values < 2^30 * 1000)
    feas = bool(np.all(cov >= SCALE))
    return feas, k, int(k.sum())

def exact_dual(A, u):
    """Round u down to multiples of 2^-30 and check A^T u <= 1 exactly (unit costs)."""
    k = np.floor(np.maximum(u, 0) * SCALE).astype(np.int64)
    Ai = A.astype(np.int64).tocsc()
    load_ = Ai.T @ k
    feas = bool(np.all(load_ <= SCALE))
    return feas, k, int(k.sum())
