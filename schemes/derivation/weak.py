# Three-level periodic domains for the weakly balanced schemes (prototype).
import itertools, collections
from cx import *
from rule import required_signature, place, element_cells

def build_levels(level_of, n_oct, extra_rule=None, S=24):
    """level_of(ox,oy,oz) in {0,1,2} per octant cube (size 2 level-0 leaves = 2*S units).
    Level-0 leaf = S units. Elements are defined at 12 units -> scaled by S/12 (level 0) and
    S/24 (level 1). Returns complex, usage."""
    per=2*n_oct*S
    cx=Complex(); used=collections.Counter()
    def lev_at(p):  # level of the octant cube containing lattice point region p (min corner, unit-aligned)
        return level_of(*[(p[t]//(2*S))%n_oct for t in range(3)])
    for ox,oy,oz in itertools.product(range(n_oct),repeat=3):
        lvl=level_of(ox,oy,oz); lo=(2*S*ox,2*S*oy,2*S*oz)
        size=S>>lvl; n=(2*S)//size
        for i,j,k in itertools.product(range(n),repeat=3):
            leaf=(lo[0]+i*size,lo[1]+j*size,lo[2]+k*size)
            if lvl==2: cx.add('L2',hexcell(leaf,size)); continue
            # application point: the corner with coordinates multiple of 2*size
            A=tuple(leaf[a] if leaf[a]%(2*size)==0 else leaf[a]+size for a in range(3))
            d=tuple(1 if leaf[a]==A[a] else -1 for a in range(3))
            def fl(a,b,c,A=A,d=d,size=size,lvl=lvl):
                loc=(a,b,c)
                # local octant cube min corner in world: A + d*(2*size*loc) adjusted
                w=[A[t] + (2*size*loc[t] if d[t]>0 else -2*size*(loc[t]+1)) for t in range(3)]
                return lev_at(w) > lvl
            sig=required_signature(fl)
            pl=place(sig)
            if extra_rule: pl=extra_rule(lvl,fl,sig,pl)
            if pl is None: cx.add('hex%d'%lvl,hexcell(tuple(min(A[t],A[t]+d[t]*size) for t in range(3)),size)); continue
            name,s=pl; used[(lvl,name)]+=1
            cells=element_cells(name,s) if isinstance(name,str) else name(s)
            sc=size//12 if size>=12 else None
            for nm,fls in cells:
                cx.add(nm+'@%d'%lvl,[[tuple(A[t] + d[t]*p[t]*size//12 for t in range(3)) for p in f] for f in fls])
    return cx, used, per

from elems import truncate, H
from rule import element_cells

def weak_extra(lvl, fl, sig, pl, level_of_local=None):
    return pl

def mr_placement(lvl, fl_level, sig, pl):
    """fl_level(a,b,c): level difference of the local octant (a,b,c) relative to the leaf
    (1 = one level finer, 2 = two levels finer...). For a concave inner edge (both faces
    interfaces) whose diagonal octant is two levels finer, truncate the element at that
    edge's midpoint."""
    if pl is None: return None
    name,s=pl
    mr=[]
    for a in range(3):
        b,c=[x for x in range(3) if x!=a]
        fb=[0,0,0]; fb[b]=-1; fc=[0,0,0]; fc[c]=-1; dg=[0,0,0]; dg[b]=-1; dg[c]=-1
        if fl_level(*fb)>=1 and fl_level(*fc)>=1 and fl_level(*dg)>=2: mr.append(a)
    if not mr: return pl
    def cells(s2, name=name, mr=tuple(mr)):
        cs=element_cells(name,s2)      # local frame
        for a in mr:
            p=[0,0,0]; p[a]=H; cs=truncate(cs,tuple(p))
        return cs
    return (cells, s, name+'-MR%s'%''.join('xyz'[a] for a in mr))

def build_weak(level_of, n_oct, S=24):
    per=2*n_oct*S
    cx=Complex(); used=collections.Counter()
    def lev_at(p): return level_of(*[(p[t]//(2*S))%n_oct for t in range(3)])
    for ox,oy,oz in itertools.product(range(n_oct),repeat=3):
        lvl=level_of(ox,oy,oz); lo=(2*S*ox,2*S*oy,2*S*oz)
        size=S>>lvl; n=(2*S)//size
        for i,j,k in itertools.product(range(n),repeat=3):
            leaf=(lo[0]+i*size,lo[1]+j*size,lo[2]+k*size)
            if lvl==2: cx.add('L2',hexcell(leaf,size)); continue
            A=tuple(leaf[a] if leaf[a]%(2*size)==0 else leaf[a]+size for a in range(3))
            d=tuple(1 if leaf[a]==A[a] else -1 for a in range(3))
            def wcorner(loc,A=A,d=d,size=size):
                return [A[t] + (2*size*loc[t] if d[t]>0 else -2*size*(loc[t]+1)) for t in range(3)]
            fl=lambda a,b,c,lvl=lvl,wc=wcorner: lev_at(wc((a,b,c)))>lvl
            fll=lambda a,b,c,lvl=lvl,wc=wcorner: lev_at(wc((a,b,c)))-lvl
            sig=required_signature(fl); pl=place(sig)
            pl=mr_placement(lvl,fll,sig,pl)
            if pl is None: cx.add('hex%d'%lvl,hexcell(tuple(min(A[t],A[t]+d[t]*size) for t in range(3)),size)); continue
            if len(pl)==3: fn,s,tag=pl; cells=fn(s)
            else: tag=pl[0]; cells=element_cells(*pl)
            used[(lvl,tag)]+=1
            for nm,fls in cells:
                cx.add(nm+'@%d'%lvl,[[tuple(A[t] + d[t]*p[t]*size//12 for t in range(3)) for p in f] for f in fls])
    return cx, used, per
