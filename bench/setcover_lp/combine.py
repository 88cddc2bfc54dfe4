"""Combine patch runs over disjoint patch sets of the same partition (same instance, dual,
spacing, seed): OPT >= sum u + sum of all patch gains. Also checks the patch ids are distinct."""
import sys, json
runs = [json.load(open(f)) for f in sys.argv[1:]]
r0 = runs[0]
for r in runs:
    assert (r['instance'], r['spacing'], r['seed'], r['K'], r['sum_u']) == (r0['instance'], r0['spacing'], r0['seed'], r0['K'], r0['sum_u'])
ids = [p['patch'] for r in runs for p in r['patches']]
assert len(ids) == len(set(ids)), "overlapping patches"
gain = sum(max(0.0, p['lb'] - p['U']) for r in runs for p in r['patches'])
nopt = sum(p['status'] == 0 for r in runs for p in r['patches'])
print(f"{r0['instance']}: {len(ids)} of {r0['K']} patches ({nopt} optimal): OPT >= {r0['sum_u']:.6f} + {gain:.6f} = {r0['sum_u'] + gain:.6f}")
