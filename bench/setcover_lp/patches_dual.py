"""Lower bound on the integer optimum by LP-dual cost splitting over geometric patches.

Let u >= 0 with A^T u <= c (LP dual feasible; verified exactly, rounded to 2^-30) and
r_j = c_j - sum_{i in S_j} u_i >= 0.  Rows are partitioned into patches P_1..P_K and column j
gets, in patch p, the split cost
      c_j^p = sum_{i in S_j ∩ P_p} u_i + r_j * |S_j ∩ P_p| / |S_j|,     sum_p c_j^p = c_j.
For any integer cover x, x restricted to the columns meeting P_p covers P_p, so
      c.x = sum_p c^p.x >= sum_p OPT_p,   OPT_p = min{c^p.y : y in {0,1}, y covers P_p}.
u restricted to P_p is dual feasible for patch p, so OPT_p >= U_p := sum_{i in P_p} u_i
(no computation needed).  Hence, for ANY subset of patches that we solve,
      OPT >= sum_i u_i + sum_{p solved} max(0, LB_p - U_p),
with LB_p the HiGHS MIP dual bound of patch p (minus a 1e-6*(1+|LB_p|) tolerance margin).
The partition only affects the strength of the bound, never its validity.

usage: patches_dual.py POINTS INSTANCE DUAL.npz SPACING TIME_PER_PATCH WALL_SECONDS [SEED [SKIP]]
"""
import sys, time, json
import numpy as np
from scipy.optimize import milp, LinearConstraint, Bounds
from scp import load, exact_dual, SCALE

def dual_scaled(Ac, y):
    """global scaling u = y / max(1, max_j load_j) (kept identical across continued runs)"""
    y = np.maximum(y, 0)
    load_ = Ac.T @ y
    return y / max(1.0, load_.max()) * (1 - 1e-12)
from patches import make_patches

def reduce_patch(sub, cp):
    """Exact reductions that keep the patch optimum: drop rows that contain another row's
    column set (ties by index), then columns whose row set is inside another column's with
    no smaller cost (ties by index), and empty columns."""
    sub = sub.tocsr().astype(np.int32)
    deg = np.diff(sub.indptr)
    M = (sub @ sub.T).tocoo()                       # |set(i) ∩ set(k)|
    sel = (M.row != M.col) & (M.data == deg[M.row]) # set(i) ⊆ set(k), i=row, k=col
    i, k = M.row[sel], M.col[sel]
    strict = (deg[i] < deg[k]) | (i < k)
    drop_rows = np.zeros(sub.shape[0], bool); drop_rows[k[strict]] = True
    sub = sub[~drop_rows].tocsc()
    cs = np.diff(sub.indptr)
    keep = cs > 0
    N = (sub.T @ sub).tocoo()                       # |S_j ∩ S_k|
    sel = (N.row != N.col) & (N.data == cs[N.row]) & keep[N.row] & keep[N.col]
    j, k = N.row[sel], N.col[sel]                  # S_j ⊆ S_k
    dom = (cp[k] <= cp[j]) & ((cs[j] < cs[k]) | (cp[k] < cp[j]) | (k < j))
    drop_cols = ~keep; drop_cols[j[dom]] = True
    return sub[:, ~drop_cols].tocsc(), cp[~drop_cols]

def main():
    ptsf, inst, dualf = sys.argv[1], sys.argv[2], sys.argv[3]
    s, tl, wall = float(sys.argv[4]), float(sys.argv[5]), float(sys.argv[6])
    seed = int(sys.argv[7]) if len(sys.argv) > 7 else 0
    skip = int(sys.argv[8]) if len(sys.argv) > 8 else 0   # continue a run: skip its first patches
    pts = np.loadtxt(ptsf)
    m, n, c, A = load(inst)
    Ac = A.tocsc()
    u = dual_scaled(Ac, np.load(dualf)['u'])
    feas, ku, numu = exact_dual(A, u)
    assert feas
    u = ku.astype(float) / SCALE                      # exact dyadic values, A^T u <= 1 verified
    base = numu / SCALE
    red = c - Ac.T @ u                                # reduced costs (>= 0 up to float rounding)
    red = np.maximum(red, 0)
    csize = np.diff(Ac.indptr).astype(float)
    lab = make_patches(pts, s, seed)
    K = lab.max() + 1
    sizes = np.bincount(lab, minlength=K)
    print(f"{inst}: sum u = {base:.6f} (verified); spacing {s}: {K} patches, rows/patch "
          f"{sizes.min()}/{sizes.mean():.0f}/{sizes.max()}", flush=True)
    order = np.random.default_rng(seed).permutation(K)[skip:]
    gain = 0.0; out = []; t0 = time.time(); nopt = 0
    for cnt_, p in enumerate(order):
        if time.time() - t0 > wall:
            break
        R = np.flatnonzero(lab == p)
        sub = A[R]
        J = np.unique(sub.indices)
        sub = sub[:, J].tocsc()
        inside = np.diff(sub.indptr).astype(float)
        cp = (sub.T @ u[R]) + red[J] * inside / csize[J]
        Up = u[R].sum()
        t = time.time()
        sub, cp = reduce_patch(sub, cp)
        res = milp(cp, constraints=LinearConstraint(sub, lb=np.ones(sub.shape[0]), ub=np.inf),
                   integrality=np.ones(len(cp)), bounds=Bounds(0, 1),
                   options=dict(time_limit=tl, disp=False))
        db = getattr(res, 'mip_dual_bound', None)
        if db is None or not np.isfinite(db):
            db = -np.inf
        lb = db - 1e-6 * (1 + abs(db))
        g = max(0.0, lb - Up)
        gain += g; nopt += res.status == 0
        out.append(dict(patch=int(p), rows=len(R), cols=len(J), U=Up, lb=lb,
                        primal=(float(res.fun) if res.fun is not None else None), status=int(res.status),
                        secs=time.time() - t))
        print(f"patch {p:4d} rows {len(R):5d}>{sub.shape[0]:4d} cols {len(J):5d}>{sub.shape[1]:4d} U {Up:8.4f} lb {lb:8.4f} "
              f"best {res.fun if res.fun is not None else float('nan'):8.4f} +{100*g/Up:5.2f}% st {res.status} "
              f"{time.time()-t:5.1f}s | OPT >= {base+gain:.3f} (+{100*gain/base:.3f}%) "
              f"[{cnt_+1}/{K}, {time.time()-t0:.0f}s]", flush=True)
        json.dump(dict(instance=inst, sum_u=base, spacing=s, time_per_patch=tl, seed=seed, skip=skip, K=int(K),
                       solved=len(out), optimal=int(nopt), gain=gain, opt_lower_bound=base + gain,
                       patches=out),
                  open(inst.replace('.txt', f'_dualpatches_s{s}_skip{skip}.json'), 'w'), indent=1)
    print(f"FINAL: {len(out)} of {K} patches ({nopt} to optimality): OPT >= {base:.6f} + {gain:.6f} = {base+gain:.6f}", flush=True)

if __name__ == '__main__':
    main()
