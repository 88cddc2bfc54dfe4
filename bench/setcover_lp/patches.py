"""Lower bound on the integer optimum by cost-splitting decomposition.

Rows are partitioned into geometric patches P_1..P_K.  Every column j gets split costs
c_j^p = c_j * |S_j ∩ P_p| / |S_j|  (sum_p c_j^p = c_j).  For any integer cover x,
x restricted to the columns meeting P_p covers P_p, so  c.x = sum_p sum_j c_j^p x_j
>= sum_p OPT_p, where OPT_p = min { c^p.y : y binary, y covers P_p }.  Hence
OPT >= sum_p LB_p for any valid lower bounds LB_p <= OPT_p (here: HiGHS MIP dual bounds,
minus a safety margin of 1e-6 * (1 + |LB_p|) for solver tolerances).
The patch partition only affects the strength of the bound, never its validity.

usage: patches.py POINTS INSTANCE SPACING TIME_PER_PATCH [MAX_PATCHES] [SEED]
"""
import sys, time, json
import numpy as np
import scipy.sparse as sp
from scipy.spatial import cKDTree
from scipy.optimize import milp, LinearConstraint, Bounds, linprog
from scp import load

def make_patches(pts, s, seed=0, lloyd=4):
    rng = np.random.default_rng(seed)
    tree = cKDTree(pts)
    blocked = np.zeros(len(pts), bool)
    seeds = []
    for t in rng.permutation(len(pts)):
        if blocked[t]:
            continue
        seeds.append(t)
        blocked[tree.query_ball_point(pts[t], s)] = True
    centers = pts[seeds]
    for _ in range(lloyd):
        lab = cKDTree(centers).query(pts)[1]
        K = len(centers)
        cnt = np.bincount(lab, minlength=K)
        cen = np.stack([np.bincount(lab, weights=pts[:, d], minlength=K) for d in range(3)], 1) / np.maximum(cnt, 1)[:, None]
        centers = pts[tree.query(cen)[1]]          # snap to the nearest sample
    lab = cKDTree(centers).query(pts)[1]
    return lab

def main():
    ptsf, inst, s, tl = sys.argv[1], sys.argv[2], float(sys.argv[3]), float(sys.argv[4])
    maxp = int(sys.argv[5]) if len(sys.argv) > 5 else 10**9
    seed = int(sys.argv[6]) if len(sys.argv) > 6 else 0
    pts = np.loadtxt(ptsf)
    m, n, c, A = load(inst)
    Ac = A.tocsc()
    csize = np.diff(Ac.indptr).astype(float)
    lab = make_patches(pts, s, seed)
    K = lab.max() + 1
    sizes = np.bincount(lab, minlength=K)
    print(f"{inst}: spacing {s}: {K} patches, rows per patch min/mean/max {sizes.min()}/{sizes.mean():.0f}/{sizes.max()}", flush=True)
    order = np.argsort(-sizes) if maxp < K else np.arange(K)
    tot_lb = tot_lp = 0.0
    out = []
    t0 = time.time()
    for cnt_, p in enumerate(order[:maxp]):
        R = np.flatnonzero(lab == p)
        sub = A[R]                                   # rows of the patch, all columns
        J = np.unique(sub.indices)
        sub = sub[:, J].tocsc()
        inside = np.diff(sub.indptr).astype(float)   # |S_j ∩ P|
        cp = c[J] * inside / csize[J]
        t = time.time()
        lp = linprog(cp, A_ub=-sub, b_ub=-np.ones(len(R)), bounds=(0, None), method='highs')
        res = milp(cp, constraints=LinearConstraint(sub, lb=np.ones(len(R)), ub=np.inf),
                   integrality=np.ones(len(J)), bounds=Bounds(0, 1),
                   options=dict(time_limit=tl, disp=False))
        db = getattr(res, 'mip_dual_bound', None)
        if db is None or not np.isfinite(db):
            db = lp.fun                              # LP value is always a valid bound
        db = max(db, lp.fun)
        lb = db - 1e-6 * (1 + abs(db))
        tot_lb += lb; tot_lp += lp.fun
        out.append(dict(patch=int(p), rows=len(R), cols=len(J), lp=lp.fun, lb=lb,
                        primal=(res.fun if res.fun is not None else None), status=res.status,
                        secs=time.time() - t))
        print(f"patch {p:4d} rows {len(R):5d} cols {len(J):5d} lp {lp.fun:9.4f} mip_lb {lb:9.4f} "
              f"best {res.fun if res.fun is not None else float('nan'):9.4f} ratio {lb/lp.fun:.4f} "
              f"st {res.status} {time.time()-t:6.1f}s | cum lb {tot_lb:.2f} lp {tot_lp:.2f} "
              f"ratio {tot_lb/tot_lp:.4f} [{cnt_+1}/{min(maxp,K)}, {time.time()-t0:.0f}s]", flush=True)
    json.dump(dict(instance=inst, spacing=s, time_per_patch=tl, seed=seed, K=int(K),
                   complete=bool(maxp >= K), sum_lb=tot_lb, sum_lp=tot_lp, patches=out),
              open(inst.replace('.txt', f'_patches_s{s}_t{tl}.json'), 'w'), indent=1)
    print(f"TOTAL over {len(out)} of {K} patches: sum LB {tot_lb:.3f}  sum patch-LP {tot_lp:.3f}", flush=True)

if __name__ == '__main__':
    main()
