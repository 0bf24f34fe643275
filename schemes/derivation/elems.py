from autolid import with_lid
from cx import *
H=U//2   # 1/2
L=U//4   # low apex height 1/4
def cube_pts():
    return {(a,b,c):(a*U,b*U,c*U) for a in (0,1) for b in (0,1) for c in (0,1)}
def hexleaf():
    return [('hex',hexcell((0,0,0),U))]

def F():
    """fine below (local octants Y,XY,YZ,XYZ). chain1 along x (C_x) lower, chain2 along z (C_z) upper."""
    O=(0,0,0); hx=(H,0,0); X1=(U,0,0); hz=(0,0,H); Z1=(0,0,U); m=(H,0,H); e1=(U,0,H); e2=(H,0,U); c=(U,0,U)
    a0=(0,L,0); a1=(H,L,0); a2=(U,H,0); b0=(0,H,0); b2=(0,H,U)
    T00=(0,U,0); T10=(U,U,0); T11=(U,U,U); T01=(0,U,U)
    p1=[[O,hz,a0],[hx,m,a1],[O,hx,m,hz],[O,hx,a1,a0],[hz,m,a1,a0]]
    p2=[[hx,m,a1],[X1,e1,a2],[hx,X1,e1,m],[hx,X1,a2,a1],[m,e1,a2,a1]]
    q=[[a0,a1,b0],[Z1,e2,b2],[a0,b0,b2,Z1,hz],[hz,m,a1,a0],[hz,m,e2,Z1],[b0,a1,m,e2,b2]]
    lid=[[T00,T10,T11,T01],[e1,c,T11,T10,a2],[e2,c,T11,T01,b2],[b0,T00,T01,b2],[b0,a1,a2,T10,T00],[m,e1,c,e2],[m,e1,a2,a1],[b0,a1,m,e2,b2]]
    return [('F.p1',p1),('F.p2',p2),('F.q',q),('F.lid',lid)]

def C1():
    """Corner tetrahedron at P (the corner patch of the three arches around a fine
    octant's convex corner) plus the rest of the leaf."""
    O=(0,0,0); a=(H,0,0); b=(0,H,0); c=(0,0,H)
    X1=(U,0,0); Y1=(0,U,0); Z1=(0,0,U); XY=(U,U,0); XZ=(U,0,U); YZ=(0,U,U); XYZ=(U,U,U)
    tet=[[O,a,b],[O,a,c],[O,b,c],[a,b,c]]
    rest=[[a,b,c],[a,X1,XY,Y1,b],[a,X1,XZ,Z1,c],[b,Y1,YZ,Z1,c],
          [X1,XY,XYZ,XZ],[Y1,XY,XYZ,YZ],[Z1,XZ,XYZ,YZ]]
    return [('C1.tet',tet),('C1.rest',rest)]

def swapxz(cells):
    return [(n,[[(p[2],p[1],p[0]) for p in f] for f in fl]) for n,fl in cells]

def Fp():
    """F with the chain along z (C_z) lower and C_x on top."""
    return [(n.replace('F.','Fp.'),fl) for n,fl in swapxz(F())]

def D_A():
    """Leaf diagonal to a convex x-edge (fine block y<0,z<0): the perpendicular chain T
    bends with a tetrahedron under the parallel chain W (option A)."""
    P=(0,0,0); hx=(H,0,0); X1=(U,0,0)
    aY=(0,L,0); aZ=(0,0,L); bY=(0,H,0); bZ=(0,0,H); wY=(U,H,0); wZ=(U,0,H)
    Y1=(0,U,0); Z1=(0,0,U); XY=(U,U,0); XZ=(U,0,U); YZ=(0,U,U); XYZ=(U,U,U)
    tet=[[P,hx,aY],[P,hx,aZ],[P,aY,aZ],[hx,aY,aZ]]
    W=[[aY,bY,wY,X1,hx],[aZ,bZ,wZ,X1,hx],[hx,aY,aZ],[aY,bY,bZ,aZ],[X1,wY,wZ],[bY,wY,wZ,bZ]]
    lid=[[bY,Y1,XY,wY],[bZ,Z1,XZ,wZ],[bY,Y1,YZ,Z1,bZ],[wY,XY,XYZ,XZ,wZ],[Y1,XY,XYZ,YZ],[Z1,XZ,XYZ,YZ],[bY,wY,wZ,bZ]]
    return [('DA.tet',tet),('DA.W',W),('DA.lid',lid)]

def D_B():
    """Leaf diagonal to a convex x-edge: W (parallel chain) lower in the face-adjacent
    leaves, so T bends over W's first prism as a prism (option B)."""
    P=(0,0,0); hx=(H,0,0); X1=(U,0,0)
    aY0=(0,L,0); aY1=(H,L,0); aY2=(U,H,0); aZ0=(0,0,L); aZ1=(H,0,L); aZ2=(U,0,H)
    bY=(0,H,0); bZ=(0,0,H)
    Y1=(0,U,0); Z1=(0,0,U); XY=(U,U,0); XZ=(U,0,U); YZ=(0,U,U); XYZ=(U,U,U)
    p1=[[P,aY0,aZ0],[hx,aY1,aZ1],[P,hx,aY1,aY0],[P,hx,aZ1,aZ0],[aY0,aY1,aZ1,aZ0]]
    p2=[[hx,aY1,aZ1],[X1,aY2,aZ2],[hx,X1,aY2,aY1],[hx,X1,aZ2,aZ1],[aY1,aY2,aZ2,aZ1]]
    T=[[aY0,aY1,bY],[aZ0,aZ1,bZ],[aY0,aY1,aZ1,aZ0],[aY0,bY,bZ,aZ0],[bY,aY1,aZ1,bZ]]
    lid=[[bY,aY1,aY2,XY,Y1],[bZ,aZ1,aZ2,XZ,Z1],[bY,Y1,YZ,Z1,bZ],[aY2,XY,XYZ,XZ,aZ2],
         [Y1,XY,XYZ,YZ],[Z1,XZ,XYZ,YZ],[aY1,aY2,aZ2,aZ1],[bY,aY1,aZ1,bZ]]
    return [('DB.p1',p1),('DB.p2',p2),('DB.T',T),('DB.lid',lid)]

def E1():
    """Concave edge along z (fine: x<0 or y<0), interfaces x=0 and y=0. The turning chain T
    (over z=0) hugs the interface; the corner cut C_z passes over it. Single arrangement of
    Sigma_T (z=1/2 arch) and Sigma_C (x=1/2 ~ y=1/2 arch around the concave edge)."""
    T=U; h=H
    P=(0,0,0)
    g=lambda x,y,z:(x,y,z)
    Tc=[[P,(h,0,0),(h,0,h),(0,0,h)],[P,(0,h,0),(0,h,h),(0,0,h)],[P,(h,0,0),(0,h,0)],
        [(h,0,0),(h,0,h),(0,h,h),(0,h,0)],[(0,0,h),(h,0,h),(0,h,h)]]
    To=[[(h,0,0),(T,0,0),(T,0,h),(h,0,h)],[(0,h,0),(0,T,0),(0,T,h),(0,h,h)],
        [(h,0,0),(T,0,0),(T,h,0),(h,T,0),(0,T,0),(0,h,0)],[(T,0,0),(T,h,0),(T,0,h)],[(0,T,0),(h,T,0),(0,T,h)],
        [(h,0,0),(h,0,h),(0,h,h),(0,h,0)],[(h,0,h),(T,0,h),(T,h,0),(h,T,0),(0,T,h),(0,h,h)]]
    Cz=[[(0,0,h),(h,0,h),(h,0,T),(0,0,T)],[(0,0,h),(0,h,h),(0,h,T),(0,0,T)],[(0,0,h),(h,0,h),(0,h,h)],
        [(0,0,T),(h,0,T),(0,h,T)],[(h,0,h),(h,0,T),(0,h,T),(0,h,h)]]
    return with_lid([('E1.Tc',Tc),('E1.To',To),('E1.Cz',Cz)],'E1.lid')

# ---------------- odd-chain model: chains hug the far faces (octant mid-planes) -------------
def reflect(cells, axes):
    def m(p): return tuple(U-p[i] if i in axes else p[i] for i in range(3))
    return [(n,[[m(p) for p in f] for f in fl]) for n,fl in cells]

def Fo():
    """Flat: fine below (y<0). Chains over the mid-planes x=1 and z=1 cross at the far
    corner (1,0,1); the chain along x (hugging z=1) is the lower one."""
    return [(n.replace('F.','Fo.'),fl) for n,fl in reflect(F(),(0,2))]

def tet_at(c):
    """Bend tetrahedron at leaf corner c (a far end of an inner edge): c and the three
    half-edge points next to it."""
    pts=[]
    for i in range(3):
        q=list(c); q[i]=H; pts.append(tuple(q))
    a,b,d=pts
    return [[c,a,b],[c,a,d],[c,b,d],[a,b,d]]

def Cn(corners):
    return with_lid([('C.tet%d'%k, tet_at(c)) for k,c in enumerate(corners)], 'C.rest')
def C1o(): return Cn([(U,0,0)])
def C2o(): return Cn([(U,0,0),(0,U,0)])
def C3o(): return Cn([(U,0,0),(0,U,0),(0,0,U)])
def FCo():
    """F plus the bend tetrahedron at the top of the inner edge perpendicular to the interface."""
    return with_lid([c for c in Fo() if 'lid' not in c[0]] + [('FC.tet', tet_at((0,U,0)))], 'FC.lid')

def Eo():
    """Concave edge along x (interfaces y=0 and z=0; X coarse). The chain over the mid-plane
    x=1 turns around the edge and passes BELOW the chains over z=1 (face y=0) and y=1
    (face z=0) at the two crossings on the far corners (12,0,12) and (12,12,0)."""
    g=lambda x,y,z:(x,y,z)
    r1=(U,L,U); r2=(U,L,H); r3=(U,H,L); r4=(U,U,L)
    P1=[[(H,0,H),(U,0,H),(U,0,U),(H,0,U)],[(U,0,H),(U,0,U),r1,r2],[(H,0,U),(U,0,U),r1],
        [(H,0,H),(U,0,H),r2],[(H,0,H),(H,0,U),r1,r2]]
    sw=lambda cells:[[(p[0],p[2],p[1]) for p in f] for f in cells]
    P1b=sw(P1)
    Ab=[[(H,0,0),(U,0,0),(U,0,H),(H,0,H)],[(H,0,0),(U,0,0),(U,H,0),(H,H,0)],
        [(U,0,0),(U,0,H),r2,r3,(U,H,0)],[(H,0,H),(U,0,H),r2],[(H,H,0),(U,H,0),r3],
        [(H,0,H),(H,0,0),(H,H,0),r3,r2]]
    Bq=[[(0,0,H),(H,0,H),(H,0,U),(0,0,U)],[(0,0,H),(0,0,U),(0,H,U)],
        [(0,0,U),(H,0,U),r1,(U,H,U),(0,H,U)],[r1,r2,(U,H,U)],[(H,0,H),(H,0,U),r1,r2],
        [(0,0,H),(H,0,H),r2,(U,H,U),(0,H,U)]]
    Cq=sw(Bq)
    return with_lid([('E.P1',P1),('E.P1b',P1b),('E.bend',Ab),('E.B',Bq),('E.C',Cq)],'E.lid')

def _VS_parts():
    c1=(U,U,L); c2=(H,U,L); r2=(U,L,H)
    E=dict(Eo())
    P1=E['E.P1']; Bq=E['E.B']
    p1c=[[(U,U,0),(U,H,0),c1],[(H,U,0),(H,H,0),c2],[(U,U,0),(H,U,0),(H,H,0),(U,H,0)],
         [(U,U,0),(H,U,0),c2,c1],[(U,H,0),(H,H,0),c2,c1]]
    p2c=[[(H,U,0),(H,H,0),c2],[(0,U,0),(0,H,0),(0,U,H)],[(H,U,0),(0,U,0),(0,H,0),(H,H,0)],
         [(H,U,0),(0,U,0),(0,U,H),c2],[(H,H,0),(0,H,0),(0,U,H),c2]]
    bend=[[(H,0,0),(U,0,0),(U,0,H),(H,0,H)],[(H,0,0),(U,0,0),(U,H,0),(H,H,0)],
          [(U,0,0),(U,0,H),r2,(U,U,H),c1,(U,H,0)],[(H,0,H),(U,0,H),r2],
          [(U,H,0),(H,H,0),c2,c1],[c1,c2,(U,U,H)],[(H,0,H),(H,0,0),(H,H,0),c2,(U,U,H),r2]]
    return P1,Bq,p1c,p2c,bend

def VSo():
    """Concave edge along x next to a concave corner: the turning chain over x=1 passes
    below the chain over z=1 (face y=0) but above the chain over y=1 (face z=0)."""
    P1,Bq,p1c,p2c,bend=_VS_parts()
    return with_lid([('VS.P1',P1),('VS.B',Bq),('VS.p1c',p1c),('VS.p2c',p2c),('VS.bend',bend)],'VS.lid')

def rot(cells):
    R=lambda p:(p[2],p[0],p[1])
    return [[R(p) for p in f] for f in cells]

def VCo():
    """Concave corner: three turning chains, each below at one crossing and above at the
    next (cyclic x -> y -> z)."""
    P1,Bq,p1c,p2c,bend=_VS_parts()
    out=[]
    for k,(a,b) in enumerate([(P1,bend),(rot(P1),rot(bend)),(rot(rot(P1)),rot(rot(bend)))]):
        out+= [('VC.P1_%d'%k,a),('VC.bend_%d'%k,b)]
    return with_lid(out,'VC.lid')

# ---------------- crossing variants (issue 4) ----------------
def swyz(cells): return [[(p[0],p[2],p[1]) for p in f] for f in cells]

def _low_x_chain_faceY():
    """The chain over z=1 on face y=0 (runs along x, hugs z=12) passing BELOW at the
    crossing (12,0,12): F's lower chain, cells p1 (x in [6,12]) and p2 (x in [0,6])."""
    d=dict(Fo()); return d['Fo.p1'], d['Fo.p2']

def bend_UU():
    c1=(U,U,L); c2=(H,U,L); b1=(U,L,U); b2=(H,L,U)
    return [[(H,0,0),(U,0,0),(U,0,H),(H,0,H)],[(H,0,0),(U,0,0),(U,H,0),(H,H,0)],
            [(U,0,0),(U,0,H),b1,(U,H,U),(U,U,H),c1,(U,H,0)],
            [(U,0,H),(H,0,H),b2,b1],[(U,H,0),(H,H,0),c2,c1],
            [b1,b2,(U,H,U)],[c1,c2,(U,U,H)],
            [(H,0,0),(H,0,H),b2,(U,H,U),(U,U,H),c2,(H,H,0)]]

def E_variant(sy, sz):
    """Concave edge along x; sy/sz: does the turning chain pass below ('L') or above ('U') at
    the crossing on face y=0 / z=0."""
    P1,Bq,p1c,p2c,bend_LU=_VS_parts()
    E=dict(Eo())
    cells=[]
    if sy=='L': cells+=[('P1y',E['E.P1']),('By',E['E.B'])]
    else:
        p1,p2=_low_x_chain_faceY(); cells+=[('lowy1',p1),('lowy2',p2)]
    if sz=='L': cells+=[('P1z',swyz(E['E.P1'])),('Cz',swyz(E['E.B']))]
    else: cells+=[('lowz1',p1c),('lowz2',p2c)]
    bend={('L','L'):E['E.bend'],('L','U'):bend_LU,('U','L'):swyz(bend_LU),('U','U'):bend_UU()}[(sy,sz)]
    cells.append(('bend',bend))
    return with_lid(cells,'lid')

def unit_x(sy, sz):
    E=dict(Eo()); P1,Bq,p1c,p2c,bend_LU=_VS_parts()
    cells=[]
    if sy=='L': cells.append(E['E.P1'])
    if sz=='L': cells.append(swyz(E['E.P1']))
    cells.append({('L','L'):E['E.bend'],('L','U'):bend_LU,('U','L'):swyz(bend_LU),('U','U'):bend_UU()}[(sy,sz)])
    return cells

def corner_variant(ly, lz, lx):
    """Concave corner. ly: which chain passes below at the crossing on face y=0 ('X' = the
    chain turning around the x-edge, or 'Z'); lz on face z=0 ('X' or 'Y'); lx on face x=0
    ('Y' or 'Z')."""
    s=lambda c:'L' if c else 'U'
    ux=unit_x(s(ly=='X'), s(lz=='X'))
    uy=[rot(f) for f in unit_x(s(lz=='Y'), s(lx=='Y'))]
    uz=[rot(rot(f)) for f in unit_x(s(lx=='Z'), s(ly=='Z'))]
    cells=[('c%d'%k,c) for k,c in enumerate(ux+uy+uz)]
    return with_lid(cells,'lid')

CORNER_ASSIGNMENTS=[(a,b,c) for a in 'XZ' for b in 'XY' for c in 'YZ']

# ---------------- weak balance (issue 5) ----------------
Q=U//4  # 3: a level-2 (twice finer) half-leaf step in level-0 units

def twin_tets(c, axis):
    """The two bend tetrahedra of the twice-finer transition around a convex edge along
    `axis`, meeting at point c on that edge (c is where the finer octant's mid-plane
    crosses the edge)."""
    o=[a for a in range(3) if a!=axis]
    def P(da, db, dc):
        p=list(c); p[axis]+=da; p[o[0]]+=db; p[o[1]]+=dc; return tuple(p)
    t=[]
    for s in (-1,1):
        e=P(s*Q,0,0); u=P(0,Q,0); v=P(0,0,Q)
        t.append([[c,e,u],[c,e,v],[c,u,v],[e,u,v]])
    return t

def E_MR():
    """E whose concave x-edge also carries the twice-finer hanging nodes (the octant across
    the edge is two levels finer): the finer transition's chains bend around that convex
    edge through this leaf with two tetrahedra at (6,0,0)."""
    E=dict(Eo())
    t1,t2=twin_tets((H,0,0),0)
    r2=(U,L,H); r3=(U,H,L)
    bend=[[(H,0,Q),(H+Q,0,0),(U,0,0),(U,0,H),(H,0,H)],[(H,Q,0),(H+Q,0,0),(U,0,0),(U,H,0),(H,H,0)],
          [(U,0,0),(U,0,H),r2,r3,(U,H,0)],[(H,0,H),(U,0,H),r2],[(H,H,0),(U,H,0),r3],
          [(H+Q,0,0),(H,Q,0),(H,0,Q)],
          [(H,0,H),(H,0,Q),(H,Q,0),(H,H,0),r3,r2]]
    cells=[('P1',E['E.P1']),('P1b',E['E.P1b']),('B',E['E.B']),('C',E['E.C']),('bend',bend),('tet1',t1),('tet2',t2)]
    return with_lid(cells,'lid')

def truncate(cells, c, step=Q):
    """Cut vertex c off every cell: each face through c gets two new vertices (at `step` from c
    along its two edges at c); each cell with a corner at c gets the cap polygon as a new
    face, and that corner becomes a cell of its own (a tetrahedron for a trihedral corner).
    This is how the twice-finer convex transition's bend enters a coarse leaf whose concave
    edge carries the extra hanging nodes (the MR elements)."""
    def toward(a, b):
        d=[b[i]-a[i] for i in range(3)]; n=max(abs(x) for x in d)
        # edges at c are axis-aligned or diagonal within a face; step along the edge
        assert n>0
        return tuple(a[i]+(d[i]*step)//n for i in range(3))
    out=[]; corners=[]
    for name,fl in cells:
        newf=[]; cap_edges=[]
        for f in fl:
            if c not in f: newf.append(f); continue
            k=f.index(c); prev=f[k-1]; nxt=f[(k+1)%len(f)]
            a=toward(c,prev); b=toward(c,nxt)
            newf.append(f[:k]+[a,b]+f[k+1:])
            cap_edges.append((a,b))
        if not cap_edges: out.append((name,fl)); continue
        # chain the cap edges into a loop
        adj={}
        for a,b in cap_edges: adj.setdefault(a,[]).append(b); adj.setdefault(b,[]).append(a)
        start=cap_edges[0][0]; loop=[start]; prev=None; cur=start
        while True:
            nx=[q for q in adj[cur] if q!=prev][0]
            if nx==start: break
            loop.append(nx); prev,cur=cur,nx
        newf.append(loop)
        out.append((name,newf))
        corner=[[c,a,b] for a,b in cap_edges]+[loop]
        corners.append((name+'.corner',corner))
    return out+corners

def rename(cells,tag): return [(tag+'.'+n.split('.',1)[-1],f) for n,f in cells]
def E_MR2(): return truncate(Eo(),(H,0,0))
def VS_MR(): return truncate(VSo(),(H,0,0))
def VC_MR(k):
    cells=VCo()
    for c in [(H,0,0),(0,H,0),(0,0,H)][:k]: cells=truncate(cells,c)
    return cells
