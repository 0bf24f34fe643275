# The transition rule: which element, under which axis permutation, goes into a coarse leaf.
import itertools
from cx import U, hexcell, Complex
from elems import Fo, FCo, C1o, C2o, C3o, Eo, VSo, VCo

# signature: (frozenset interfaces, frozenset tets, frozenset of (face normal, axis of the lower chain))
CANON = {
    'F':  (Fo,  {1}, set(), {(1,0)}),
    'F+C':(FCo, {1}, {1},   {(1,0)}),
    'C1': (C1o, set(), {0}, set()),
    'C2': (C2o, set(), {0,1}, set()),
    'C3': (C3o, set(), {0,1,2}, set()),
    'E':  (Eo,  {1,2}, set(), {(1,2),(2,1)}),
    'VS': (VSo, {1,2}, set(), {(1,2),(2,0)}),
    'VC': (VCo, {0,1,2}, set(), {(1,2),(2,0),(0,1)}),
}
PERMS=list(itertools.permutations(range(3)))
def permuted(sig, s):
    """canonical axis i -> local axis s[i]"""
    I,T,Lw=sig
    return (frozenset(s[i] for i in I), frozenset(s[i] for i in T), frozenset((s[n],s[a]) for n,a in Lw))
TABLE={}
for name,(fn,I,T,Lw) in CANON.items():
    for s in PERMS:
        TABLE.setdefault(permuted((I,T,Lw),s),(name,s))

def required_signature(fine_local):
    """fine_local(i,j,k): is the octant cube with local min corner (2i,2j,2k) fine (i,j,k in -1..1)."""
    e=[(1,0,0),(0,1,0),(0,0,1)]
    f=[fine_local(*[-e[a][i] for i in range(3)]) for a in range(3)]          # inner face a
    far=[fine_local(*[e[a][i] for i in range(3)]) for a in range(3)]         # Q's far face a
    I={a for a in range(3) if f[a]}
    T=set()
    for a in range(3):
        b,c=[x for x in range(3) if x!=a]
        if not f[b] and not f[c]:
            d=[0,0,0]; d[b]=-1; d[c]=-1
            if fine_local(*d): T.add(a)
    Lw=set()
    iface=[f[a] or far[a] for a in range(3)]   # Q has an interface normal to a
    for n in I:
        a,b=[x for x in range(3) if x!=n]
        # chain over the a-mid-plane runs along b; it is bent iff Q has an interface normal to b
        bentA, bentB = iface[b], iface[a]
        if bentA and not bentB: low=b
        elif bentB and not bentA: low=a
        else: low=(n+1)%3          # tie: cyclic convention
        Lw.add((n,low))
    return (frozenset(I),frozenset(T),frozenset(Lw))

def place(sig):
    if not sig[0] and not sig[1]: return None
    if sig not in TABLE: raise KeyError("no element for signature %s"%(sig,))
    return TABLE[sig]

def element_cells(name, s):
    fn=CANON[name][0]
    out=[]
    for n,fl in fn():
        out.append((n,[[tuple(p[[i for i in range(3) if s[i]==a][0]] for a in range(3)) for p in f] for f in fl]))
    return out

def build_periodic(fine_octant, n_oct, use=None):
    """fine_octant(ix,iy,iz): octant cube (indices mod n_oct) fine? Period = 2*n_oct coarse leaves."""
    per=2*n_oct*U
    cx=Complex(); used={}
    for ox,oy,oz in itertools.product(range(n_oct),repeat=3):
        lo=(2*ox,2*oy,2*oz)
        if fine_octant(ox,oy,oz):
            for i,j,k in itertools.product(range(4),repeat=3):
                cx.add('fine',hexcell((lo[0]*U+i*U//2,lo[1]*U+j*U//2,lo[2]*U+k*U//2),U//2))
            continue
        for i,j,k in itertools.product(range(2),repeat=3):
            leaf=(lo[0]+i,lo[1]+j,lo[2]+k)
            A=tuple(leaf[a] if leaf[a]%2==0 else leaf[a]+1 for a in range(3))
            d=tuple(1 if leaf[a]==A[a] else -1 for a in range(3))
            def fl(a,b,c):
                # local octant (a,b,c) in -1..1 -> world octant containing A + d*(2a+1,2b+1,2c+1)/... 
                loc=(a,b,c)
                w=[ (A[t]//2 + (loc[t] if d[t]>0 else -loc[t]-1)) % n_oct for t in range(3)]
                return fine_octant(*w)
            sig=required_signature(fl)
            pl=place(sig)
            if pl is None:
                cx.add('hex',hexcell((leaf[0]*U if d[0]>0 else (leaf[0])*U, leaf[1]*U, leaf[2]*U),U) if False else hexcell((min(A[0],A[0]+d[0])*U,min(A[1],A[1]+d[1])*U,min(A[2],A[2]+d[2])*U),U)); continue
            name,s=pl; used[name]=used.get(name,0)+1
            for n,fls in element_cells(name,s):
                cx.add(n,[[tuple(A[t]*U + d[t]*p[t] for t in range(3)) for p in f] for f in fls])
    return cx, used
