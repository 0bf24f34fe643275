# Prototype checker for scheme design (scratch, not part of the product).
# Units: coarse leaf = U lattice units.
import itertools, collections
U = 12

def canon_face(loop):
    n=len(loop); i=min(range(n), key=lambda k: loop[k])
    a=loop[i:]+loop[:i]
    b=[a[0]]+a[1:][::-1]
    return tuple(min(a,b))

def sub(a,b): return (a[0]-b[0],a[1]-b[1],a[2]-b[2])
def cross(a,b): return (a[1]*b[2]-a[2]*b[1],a[2]*b[0]-a[0]*b[2],a[0]*b[1]-a[1]*b[0])
def dot(a,b): return a[0]*b[0]+a[1]*b[1]+a[2]*b[2]

def orient_cell(faces):
    """Orient faces of a closed cell consistently & outward (by signed volume)."""
    faces=[list(f) for f in faces]
    n=len(faces)
    edge_faces=collections.defaultdict(list)
    for i,f in enumerate(faces):
        for k in range(len(f)):
            a,b=f[k],f[(k+1)%len(f)]
            edge_faces[frozenset((a,b))].append(i)
    for e,fl in edge_faces.items():
        if len(fl)!=2: raise ValueError("cell edge %s in %d faces"%(sorted(e),len(fl)))
    done=[False]*n; done[0]=True; stack=[0]
    def dirs(f):
        return {(f[k],f[(k+1)%len(f)]) for k in range(len(f))}
    while stack:
        i=stack.pop(); di=dirs(faces[i])
        for (a,b) in di:
            for j in edge_faces[frozenset((a,b))]:
                if j==i or done[j]: continue
                if (a,b) in dirs(faces[j]): faces[j]=faces[j][::-1]
                done[j]=True; stack.append(j)
    if not all(done): raise ValueError("cell faces disconnected")
    vol=0
    for f in faces:
        for k in range(1,len(f)-1):
            vol+=dot(f[0],cross(f[k],f[k+1]))
    if vol<0: faces=[f[::-1] for f in faces]
    return faces, abs(vol)

class Complex:
    def __init__(s): s.cells=[]  # list of (name, faces)
    def add(s, name, faces): s.cells.append((name, faces))

def wrap(p, per):
    if per is None: return p
    return tuple(c%per for c in p)

def check(cx, per=None, interior=None, verbose=True, maxerr=20):
    """per: period (torus) or None. interior(p)->bool for which vertices to check."""
    faces={}  # canon -> list of (cell, orientation-sign)
    cellfaces=[]
    errs=[]
    for ci,(name,fl) in enumerate(cx.cells):
        try:
            of,vol=orient_cell([[wrap(p,per) for p in f] for f in fl]) if per is None else orient_cell_raw(fl, per)
        except ValueError as e:
            errs.append("cell %d %s: %s"%(ci,name,e)); continue
        cf=[]
        for f in of:
            wf=[wrap(p,per) for p in f]
            if len(set(wf))!=len(wf): errs.append("cell %s face with repeated vertex %s"%(name,wf))
            c=canon_face(wf)
            same = (c==tuple(rot_min(wf)))
            faces.setdefault(c,[]).append((ci,same))
            cf.append(c)
        cellfaces.append(cf)
    for c,l in faces.items():
        if len(l)>2: errs.append("face %s in %d cells: %s"%(c,len(l),[cx.cells[i][0] for i,_ in l]))
        if len(l)==2 and l[0][1]==l[1][1]: errs.append("face %s same orientation in %s"%(c,[cx.cells[i][0] for i,_ in l]))
        if per is not None and len(l)==1: errs.append("boundary face in torus %s (cell %s)"%(c,cx.cells[l[0][0]][0]))
    # edges
    edge_faces=collections.defaultdict(set)
    for c in faces:
        for k in range(len(c)):
            edge_faces[frozenset((c[k],c[(k+1)%len(c)]))].add(c)
    vert_edges=collections.defaultdict(set)
    for e in edge_faces:
        a,b=tuple(e); vert_edges[a].add(b); vert_edges[b].add(a)
    boundary_v=set()
    for c,l in faces.items():
        if len(l)==1: boundary_v.update(c)
    edge_cells=collections.defaultdict(set)
    for ci,cf in enumerate(cellfaces):
        for c in cf:
            for k in range(len(c)):
                edge_cells[frozenset((c[k],c[(k+1)%len(c)]))].add(ci)
    bad_v=[]; bad_e=[]
    for v,nb in vert_edges.items():
        if v in boundary_v: continue
        if interior and not interior(v): continue
        if len(nb)!=6: bad_v.append((v,len(nb)))
    for e,cs in edge_cells.items():
        a,b=tuple(e)
        if a in boundary_v or b in boundary_v: continue
        if interior and not (interior(a) and interior(b)): continue
        if len(cs)!=4: bad_e.append((tuple(sorted(e)),len(cs)))
    hist=collections.Counter(len(c) for c in faces)
    ok = not errs and not bad_v and not bad_e
    if verbose:
        for e in errs[:maxerr]: print("ERR",e)
        for v in bad_v[:maxerr]: print("VAL", v)
        for e in bad_e[:maxerr]: print("EDGE", e)
        print("cells",len(cx.cells),"faces",len(faces),"hist",dict(sorted(hist.items())),"badv",len(bad_v),"bade",len(bad_e),"errs",len(errs), "OK" if ok else "FAIL")
    return ok, hist, bad_v, bad_e, errs

def rot_min(loop):
    n=len(loop); i=min(range(n), key=lambda k: loop[k]); return loop[i:]+loop[:i]

def orient_cell_raw(fl, per):
    # orient using unwrapped coordinates, return unwrapped faces
    of,vol=orient_cell(fl)
    return of,vol

def face_hist(cells):
    fs={}
    for name,fl in cells:
        for f in fl: fs[canon_face(list(f))]=1
    return dict(sorted(collections.Counter(len(c) for c in fs).items()))

# symmetry: signed permutation applied about origin
def symm(p, perm, sign):
    return tuple(sign[i]*p[perm[i]] for i in range(3))

def hexcell(lo, size):
    x0,y0,z0=lo; s=size
    P=lambda a,b,c:(x0+a*s,y0+b*s,z0+c*s)
    return [[P(0,0,0),P(0,1,0),P(1,1,0),P(1,0,0)],[P(0,0,1),P(1,0,1),P(1,1,1),P(0,1,1)],
            [P(0,0,0),P(1,0,0),P(1,0,1),P(0,0,1)],[P(0,1,0),P(0,1,1),P(1,1,1),P(1,1,0)],
            [P(0,0,0),P(0,0,1),P(0,1,1),P(0,1,0)],[P(1,0,0),P(1,1,0),P(1,1,1),P(1,0,1)]]

def hexcell_split(lo,size,extra):
    """hex whose faces include extra vertices lying on them (hanging nodes seen from the coarse side)"""
    raise NotImplementedError
