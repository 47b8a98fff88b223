#!/usr/bin/python3
"""Where a 2D mesh's bad triangles (rho = 2 r_in / r_circ below a threshold) are.

Reads a Gmsh 4.1 ASCII .msh (3D nodes, type-1 lines on the boundary, type-2 triangles)
and classifies every triangle by its place against the boundary, the size field's gradient
across it, its boundary edge's length against the size, the water angle at its boundary
nodes, the size criterion at its nodes and whether all its nodes are on the boundary.
Diagnosis only (docs/benchmarks.md, 2026-12-08); not run by ctest; about 70 s per 1.5 M
triangles. Usage: bad_triangles.py MESH.msh COAST_SIZE [THRESHOLD=0.9]
  COAST_SIZE: the size field on the boundary (ShoreSizeMin, metres); THRESHOLD: front2d's
  quality pass works on rho < 0.9 (src/mesh/face_smooth.cpp; del2d's is 0.75).
The optimiser's input: mesh with `-setnumber Mesh.QualityPass 0 -setnumber
Mesh.QualityFloor 0 -setstring Mesh.NodeData "size,criterion"` (the field size and the
criterion at the nodes; without them the local size is the mean length of a node's edges).
"""
import sys
import numpy as np


def read_msh(path):
    nodes, lines, tris, data = {}, [], [], {}
    with open(path) as f:
        it = iter(f)
        for row in it:
            if row.startswith('$Nodes'):
                nb, _, _, _ = map(int, next(it).split())
                for _ in range(nb):
                    _, _, _, n = map(int, next(it).split())
                    tags = [int(next(it)) for _ in range(n)]
                    for t in tags:
                        nodes[t] = [float(v) for v in next(it).split()]
            elif row.startswith('$NodeData'):
                name = [next(it).strip().strip('"') for _ in range(int(next(it)))][0]
                [next(it) for _ in range(int(next(it)))]
                ints = [int(next(it)) for _ in range(int(next(it)))]
                data[name] = dict((int(r.split()[0]), float(r.split()[1]))
                                  for r in (next(it) for _ in range(ints[2])))
            elif row.startswith('$Elements'):
                nb, _, _, _ = map(int, next(it).split())
                for _ in range(nb):
                    _, _, et, n = map(int, next(it).split())
                    dst = lines if et == 1 else tris if et == 2 else None
                    for _ in range(n):
                        r = next(it).split()
                        if dst is not None:
                            dst.append([int(v) for v in r[1:]])
    tags = np.array(sorted(nodes))
    index = np.full(tags.max() + 1, -1)
    index[tags] = np.arange(len(tags))
    xyz = np.array([nodes[t] for t in tags])
    fields = {k: np.array([v.get(t, np.nan) for t in tags]) for k, v in data.items()}
    return xyz, index[np.array(lines)], index[np.array(tris)], fields


def share(mask, bad):
    n, b = int(mask.sum()), int((mask & bad).sum())
    return n, b


def main():
    path, coast = sys.argv[1], float(sys.argv[2])
    thr = float(sys.argv[3]) if len(sys.argv) > 3 else 0.9
    xyz, lines, tris, fields = read_msh(path)
    p = xyz[tris]                                   # (T, 3, 3)
    e = [np.linalg.norm(p[:, (i + 1) % 3] - p[:, (i + 2) % 3], axis=1) for i in range(3)]
    a, b, c = e
    s = (a + b + c) / 2
    area = np.sqrt(np.maximum(s * (s - a) * (s - b) * (s - c), 0))
    rho = 2 * (area / s) / np.maximum(a * b * c / np.maximum(4 * area, 1e-300), 1e-300)
    bad = rho < thr
    nv, nt = len(xyz), len(tris)
    # Mesh edges: local size per node.
    ed = np.sort(np.concatenate([tris[:, [1, 2]], tris[:, [2, 0]], tris[:, [0, 1]]]), axis=1)
    ed = np.unique(ed, axis=0)
    el = np.linalg.norm(xyz[ed[:, 0]] - xyz[ed[:, 1]], axis=1)
    cnt = np.bincount(ed.ravel(), minlength=nv)
    h = np.bincount(ed.ravel(), weights=np.repeat(el, 2), minlength=nv) / np.maximum(cnt, 1)
    # Boundary: nodes, edges; rings by breadth-first search over mesh edges.
    onb = np.zeros(nv, bool)
    onb[lines.ravel()] = True
    ring = np.where(onb, 0, 99)
    for r in range(1, 4):
        nb = (ring[ed[:, 0]] == r - 1) | (ring[ed[:, 1]] == r - 1)
        for k in (0, 1):
            sel = nb & (ring[ed[:, k]] > r)
            ring[ed[sel, k]] = r
    bkey = set(map(tuple, np.sort(lines, axis=1).tolist()))
    bedge = np.zeros((nt, 3), bool)
    for i in range(3):
        pair = np.sort(tris[:, [(i + 1) % 3, (i + 2) % 3]], axis=1)
        cand = onb[pair[:, 0]] & onb[pair[:, 1]]
        for t in np.nonzero(cand)[0]:
            bedge[t, i] = tuple(pair[t]) in bkey
    # Angles: the water angle at a boundary node is the sum of its triangles' angles.
    ang = np.zeros((nt, 3))
    for i in range(3):
        u = p[:, (i + 1) % 3] - p[:, i]
        v = p[:, (i + 2) % 3] - p[:, i]
        cosv = (u * v).sum(1) / np.maximum(np.linalg.norm(u, axis=1) * np.linalg.norm(v, axis=1), 1e-300)
        ang[:, i] = np.degrees(np.arccos(np.clip(cosv, -1, 1)))
    water = np.bincount(tris.ravel(), weights=ang.ravel(), minlength=nv)
    tmin_ring = ring[tris].min(1)
    print(f'{path}: {nt} triangles, {int(bad.sum())} below {thr} ({100 * bad.mean():.1f}%)')

    def table(title, classes):
        print(f'\n{title}\n  {"class":34s} {"tris":>9s} {"bad":>8s} {"bad%":>6s} {"of bad":>6s}')
        for name, m in classes:
            n, k = share(m, bad)
            print(f'  {name:34s} {n:9d} {k:8d} {100 * k / max(n, 1):6.1f} {100 * k / max(bad.sum(), 1):6.1f}')

    has_be = bedge.any(1)
    table('place against the boundary', [
        ('has a boundary edge', has_be),
        ('boundary node, no boundary edge', ~has_be & (tmin_ring == 0)),
        ('one ring in', tmin_ring == 1),
        ('two rings in', tmin_ring == 2),
        ('farther', tmin_ring >= 3)])
    if 'size' in fields:                            # Mesh.NodeData "size,criterion"
        h = fields['size']
    hr = h[tris].max(1) / h[tris].min(1)
    table('size gradient: max/min size of the 3 nodes' + (' (field)' if 'size' in fields else ' (proxy)'), [
        (f'< 1.3', hr < 1.3), ('1.3 - 2', (hr >= 1.3) & (hr < 2)),
        ('2 - 4', (hr >= 2) & (hr < 4)), ('>= 4', hr >= 4)])
    L = np.where(bedge, np.stack(e, 1), np.nan)
    lb = np.nanmax(np.where(has_be[:, None], L, 0), axis=1)
    rel = lb / coast
    if 'size' in fields:
        u, v = p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]
        d1, d2 = h[tris[:, 1]] - h[tris[:, 0]], h[tris[:, 2]] - h[tris[:, 0]]
        uu, uv, vv = (u * u).sum(1), (u * v).sum(1), (v * v).sum(1)
        det = uu * vv - uv * uv
        al, be = (vv * d1 - uv * d2) / det, (uu * d2 - uv * d1) / det
        g = np.linalg.norm(al[:, None] * u + be[:, None] * v, axis=1)   # |grad size|
        table('|grad size| over the triangle (linear in the field size at its nodes)', [
            ('< 0.1', g < 0.1), ('0.1 - 0.2', (g >= 0.1) & (g < 0.2)), ('0.2 - 0.3', (g >= 0.2) & (g < 0.3)),
            ('0.3 - 0.5', (g >= 0.3) & (g < 0.5)), ('>= 0.5', g >= 0.5)])
        hb = np.zeros(nt)
        for i in range(3):
            hb = np.where(bedge[:, i], (h[tris[:, (i + 1) % 3]] + h[tris[:, (i + 2) % 3]]) / 2, hb)
        relf = lb / np.where(hb > 0, hb, 1)
        table('boundary edge length / field size there (triangles with a boundary edge)', [
            ('< 0.5', has_be & (relf < 0.5)), ('0.5 - 0.8', has_be & (relf >= 0.5) & (relf < 0.8)),
            ('0.8 - 1.25', has_be & (relf >= 0.8) & (relf < 1.25)), ('>= 1.25', has_be & (relf >= 1.25))])
        em = (a + b + c) / 3 / h[tris].mean(1)
        table('mean edge / mean field size of the triangle', [
            ('< 0.7', em < 0.7), ('0.7 - 0.9', (em >= 0.7) & (em < 0.9)),
            ('0.9 - 1.2', (em >= 0.9) & (em < 1.2)), ('>= 1.2', em >= 1.2)])
    if 'criterion' in fields:
        cr = fields['criterion'][tris]
        table('size criterion at the nodes (0: ChannelWidth)', [
            ('a node sized by ChannelWidth', (cr == 0).any(1)),
            ('criteria differ across the triangle', cr.min(1) != cr.max(1))] +
            [(f'all nodes by field {int(k)}', (cr == k).all(1)) for k in np.unique(cr)])
    table('boundary edge length / COAST_SIZE (triangles with a boundary edge)', [
        ('< 0.3', has_be & (rel < 0.3)), ('0.3 - 0.7', has_be & (rel >= 0.3) & (rel < 0.7)),
        ('0.7 - 1.4', has_be & (rel >= 0.7) & (rel < 1.4)), ('>= 1.4', has_be & (rel >= 1.4))])
    wmin = np.where(onb[tris], water[tris], 360).min(1)
    table('smallest water angle at a boundary node of the triangle', [
        ('< 30 deg', wmin < 30), ('30 - 60 deg', (wmin >= 30) & (wmin < 60)),
        ('60 - 120 deg', (wmin >= 60) & (wmin < 120)), ('>= 120 deg or none', wmin >= 120)])
    allb = onb[tris].all(1)
    hm = (a + b + c) / 3
    table('narrow water', [
        ('all three nodes on the boundary', allb),
        ('mean edge < 0.7 COAST_SIZE', hm < 0.7 * coast),
        ('all three on boundary, no bd edge', allb & ~has_be)])
    # Bad triangles touching the boundary: is the interior node's edge length the problem?
    r0 = has_be & bad
    print(f'\nbad with a boundary edge: median boundary edge / coast size {np.median(rel[r0]):.2f}, '
          f'median rho {np.median(rho[r0]):.3f}; all triangles with one: {np.median(rel[has_be]):.2f}')


if __name__ == '__main__':
    main()
