# Build an element from its non-lid cells: the lid is the complement in the leaf.
from cx import *
import collections

def on_segment(p,a,b):
    if p==a or p==b: return False
    d=sub(b,a); e=sub(p,a)
    if cross(d,e)!=(0,0,0): return False
    t=dot(e,d); return 0<t<dot(d,d)

def insert_tjunctions(loop, verts):
    out=[]
    n=len(loop)
    for k in range(n):
        a,b=loop[k],loop[(k+1)%n]
        out.append(a)
        mids=[v for v in verts if on_segment(v,a,b)]
        mids.sort(key=lambda v: dot(sub(v,a),sub(b,a)))
        out.extend(mids)
    return out

def leaf_face_of(f):
    for axis in range(3):
        for val in (0,U):
            if all(p[axis]==val for p in f): return (axis,val)
    return None

def with_lid(cells, name='lid'):
    """cells: list of (name, faces) not including the lid. Returns cells + lid."""
    verts=set(p for _,fl in cells for f in fl for p in f)
    # leaf corners
    for a in (0,U):
        for b in (0,U):
            for c in (0,U): verts.add((a,b,c))
    cells=[(n,[insert_tjunctions(f,verts) for f in fl]) for n,fl in cells]
    cnt=collections.Counter(canon_face(f) for _,fl in cells for f in fl)
    lid_faces=[]
    # exposed interior faces
    rep={}
    for _,fl in cells:
        for f in fl: rep[canon_face(f)]=f
    for c,k in cnt.items():
        if k==1 and leaf_face_of(rep[c]) is None: lid_faces.append(list(rep[c]))
    # uncovered parts of each leaf face
    for axis in range(3):
        for val in (0,U):
            covered=[rep[c] for c in cnt if leaf_face_of(rep[c])==(axis,val)]
            # boundary edges of the leaf face square, split at vertices on it
            o=[i for i in range(3) if i!=axis]
            def P(s,t):
                p=[0,0,0]; p[axis]=val; p[o[0]]=s; p[o[1]]=t; return tuple(p)
            sq=insert_tjunctions([P(0,0),P(U,0),P(U,U),P(0,U)], verts)
            edges=collections.Counter()
            for k in range(len(sq)): edges[frozenset((sq[k],sq[(k+1)%len(sq)]))]+=1
            for f in covered:
                for k in range(len(f)): edges[frozenset((f[k],f[(k+1)%len(f)]))]+=1
            # an edge of the uncovered region appears exactly once (square edge not covered,
            # or covered-polygon edge not on the square and not shared by two covered polygons)
            sqset=set(frozenset((sq[k],sq[(k+1)%len(sq)])) for k in range(len(sq)))
            bd=[e for e,k in edges.items() if k==1]
            if not bd: continue
            # chain into loops
            adj=collections.defaultdict(list)
            for e in bd:
                a,b=tuple(e); adj[a].append(b); adj[b].append(a)
            seen=set()
            for start in list(adj):
                if start in seen: continue
                loop=[start]; seen.add(start); prev=None; cur=start
                while True:
                    nxt=[q for q in adj[cur] if q!=prev]
                    if len(adj[cur])!=2: raise ValueError("non-simple lid region on face %s=%s at %s"%(axis,val,cur))
                    q=nxt[0]
                    if q==start: break
                    loop.append(q); seen.add(q); prev,cur=cur,q
                lid_faces.append(loop)
    return cells+[(name,lid_faces)]
