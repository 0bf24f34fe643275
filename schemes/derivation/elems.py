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
