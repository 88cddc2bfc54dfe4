"""Restarted PDHG (PDLP-style, simplified) for min 1.x s.t. A x >= 1, x >= 0 (unit costs),
then repair to an exactly verified primal x (LP upper bound) and a scaled dual u with
A^T u <= 1 verified exactly (LP lower bound).

usage: pdhg.py INSTANCE SECONDS [WARMSTART.npz]
"""
import sys, time
import numpy as np
from scp import load, exact_primal, exact_dual

def repair_primal(A, Ac, x):
    x = np.maximum(x, 0)
    cov = A @ x
    d = np.maximum(0, 1 - cov) * (1 + 1e-9) + (cov < 1) * 1e-12
    deg = np.diff(A.indptr)
    w = d / deg
    add = np.maximum.reduceat(w[Ac.indices], Ac.indptr[:-1])
    return x + add

def dual_scaled(Ac, y):
    """u_i = y_i / max_{j covering i} max(1, load_j): then every column load is <= 1."""
    y = np.maximum(y, 0)
    load_ = np.maximum(1.0, Ac.T @ y)
    A = Ac.tocsr()
    f = np.maximum.reduceat(load_[A.indices], A.indptr[:-1])
    return y / f * (1 - 1e-12)

def main():
    name, secs = sys.argv[1], float(sys.argv[2])
    m, n, c, A = load(name)
    Ac = A.tocsc()
    AT = A.T.tocsr()
    b = np.ones(m)
    # spectral norm by power iteration
    v = np.random.default_rng(0).random(n)
    for _ in range(50):
        v = AT @ (A @ v); nv = np.linalg.norm(v); v /= nv
    L = np.sqrt(nv) * 1.01
    eta = 0.95 / L
    omega = 1.0
    if len(sys.argv) > 3:
        w = np.load(sys.argv[3]); x = w['x']; y = w['u']
    else:
        x = np.zeros(n); y = np.zeros(m)
    t0 = time.time(); it = 0
    best_ub = np.inf; best_lb = 0
    xs, ys, cnt = np.zeros(n), np.zeros(m), 0
    x0, y0 = x.copy(), y.copy()
    T = 200
    def kkt(x, y):
        r_p = np.linalg.norm(np.maximum(0, b - A @ x))
        r_d = np.linalg.norm(np.minimum(0, c - AT @ y))
        gap = abs(c @ x - b @ y)
        return np.sqrt(r_p**2 + r_d**2 + gap**2)
    last_restart_err = kkt(x, y)
    while time.time() - t0 < secs:
        tau, sigma = eta / omega, eta * omega
        xn = np.maximum(0, x - tau * (c - AT @ y))
        y = np.maximum(0, y + sigma * (b - A @ (2 * xn - x)))
        x = xn
        xs += x; ys += y; cnt += 1; it += 1
        if cnt == T:
            xa, ya = xs / cnt, ys / cnt
            ea, ec = kkt(xa, ya), kkt(x, y)
            if ea < ec: x, y, e = xa, ya, ea
            else: e = ec
            dx, dy = np.linalg.norm(x - x0), np.linalg.norm(y - y0)
            if dx > 1e-10 and dy > 1e-10:
                omega = np.exp(0.5 * np.log(dy / dx) + 0.5 * np.log(omega))
            x0, y0 = x.copy(), y.copy(); xs[:] = 0; ys[:] = 0; cnt = 0
            xr = repair_primal(A, Ac, x); ub = xr.sum()
            yr = dual_scaled(Ac, y); lb = yr.sum()
            if ub < best_ub: best_ub, bx = ub, xr
            if lb > best_lb: best_lb, by = lb, yr
            print(f"it {it:6d} t {time.time()-t0:6.0f}s kkt {e:.3e} obj {c@x:.3f} ub {ub:.3f} lb {lb:.3f} "
                  f"best [{best_lb:.3f}, {best_ub:.3f}] gap {100*(best_ub-best_lb)/best_lb:.3f}% omega {omega:.3g}", flush=True)
    fp, kx, numx = exact_primal(A, bx)
    fd, ky, numy = exact_dual(A, by)
    print(f"VERIFIED primal feasible={fp} LP <= {numx}/2^30 = {numx/2**30:.6f}")
    print(f"VERIFIED dual feasible={fd}   LP >= {numy}/2^30 = {numy/2**30:.6f}")
    np.savez(name.replace('.txt', '_pdhg.npz'), x=bx, u=by, kx=kx, ky=ky)

if __name__ == '__main__':
    main()
