import itertools
from cx import *

def P(x,y,z): return (x,y,z)
OCT={1:'X',2:'Y',4:'Z',3:'XY',5:'XZ',6:'YZ',7:'XYZ'}

def local_pattern(fine, A, d):
    """fine(octant_lo)->bool for octant cube with min corner (coarse units). A app point, d leaf direction signs.
    Returns 7-bit set of local octants m (bit i set = local negative along axis i) that are fine."""
    S=0
    for m in range(1,8):
        # local direction per axis: negative if bit set -> actual direction -d[i]
        dirs=[(-d[i] if (m>>i)&1 else d[i]) for i in range(3)]
        lo=tuple(A[i] + (0 if dirs[i]>0 else -2) for i in range(3))
        if fine(lo): S|=1<<m
    return S

PERMS=list(itertools.permutations(range(3)))
def perm_mask(S, perm):
    # local octant m (bits per axis) -> permuted: new axis i takes old axis perm[i]
    T=0
    for m in range(1,8):
        if (S>>m)&1:
            nm=0
            for i in range(3):
                if (m>>perm[i])&1: nm|=1<<i
            T|=1<<nm
    return T

def place(cells, perm, d, A, scale=U):
    out=[]
    for name,fl in cells:
        nf=[]
        for f in fl:
            nf.append([tuple(A[i]*scale + d[i]*p[perm[i]] for i in range(3)) for p in f])
        out.append((name,nf))
    return out

def build_torus(finemask, elements, per_units=4, verbose=False):
    """finemask: 8-bit over octant cubes of the 4x4x4 torus; bit b: cube lo=(2*(b&1),2*(b>>1&1),2*(b>>2&1))."""
    per=per_units*U
    def fine(lo):
        b=sum(((lo[i]%4)//2)<<i for i in range(3))
        return (finemask>>b)&1
    cx=Complex(); missing=set()
    for b in range(8):
        lo=(2*(b&1),2*(b>>1&1),2*(b>>2&1))
        if (finemask>>b)&1:
            for i,j,k in itertools.product(range(4),repeat=3):
                cx.add('fine',hexcell((lo[0]*U+i*U//2,lo[1]*U+j*U//2,lo[2]*U+k*U//2),U//2))
        else:
            for i,j,k in itertools.product(range(2),repeat=3):
                leaf=(lo[0]+i,lo[1]+j,lo[2]+k)
                # app point: the even corner
                A=tuple(leaf[a] if leaf[a]%2==0 else leaf[a]+1 for a in range(3))
                d=tuple(1 if leaf[a]==A[a] else -1 for a in range(3))
                S=local_pattern(fine,A,d)
                found=None
                for perm in PERMS:
                    T=perm_mask(S,perm)
                    if T in elements: found=(T,perm); break
                if found is None:
                    missing.add(min(perm_mask(S,p) for p in PERMS)); continue
                T,perm=found
                # element defined for pattern T in frame F; leaf frame coords q with q[perm^-1]... 
                # perm_mask maps old axis perm[i] -> new axis i. element point e (new frame) -> old frame: old[perm[i]] = e[i]
                inv=[0]*3
                for i in range(3): inv[perm[i]]=i
                cells=elements[T]()
                cells=[(n,[[tuple(p[inv[a]] for a in range(3)) for p in f] for f in fl]) for n,fl in cells]
                cx.cells += place(cells,(0,1,2),d,A)
    return cx, missing

def pattern_name(S):
    return '{'+','.join(OCT[m] for m in range(1,8) if (S>>m)&1)+'}'
