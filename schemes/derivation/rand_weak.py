import random, sys, collections, itertools
from weak import build_weak
from cx import check
seed=int(sys.argv[1]); n=int(sys.argv[2]); N=int(sys.argv[3]) if len(sys.argv)>3 else 4
rng=random.Random(seed); stats=collections.Counter(); bad=0
for t in range(n):
    L=[rng.choice([0,0,1,1,2]) for _ in range(N**3)]
    idx=lambda x,y,z:(x%N)+N*(y%N)+N*N*(z%N)
    changed=True
    while changed:   # weak balance between face-adjacent octant cubes
        changed=False
        for x,y,z in itertools.product(range(N),repeat=3):
            for dx,dy,dz in ((1,0,0),(0,1,0),(0,0,1),(-1,0,0),(0,-1,0),(0,0,-1)):
                if L[idx(x+dx,y+dy,z+dz)]-L[idx(x,y,z)]>1: L[idx(x,y,z)]+=1; changed=True
    lv=lambda x,y,z:L[idx(x,y,z)]
    cx,used,per=build_weak(lv,N)
    ok,h,bv,be,errs=check(cx,per=per,verbose=False)
    for k,v in used.items(): stats[k[1]]+=v
    if not ok: bad+=1; print('FAIL',t,bv[:3],be[:3],errs[:2]); print(L)
print('seed',seed,'trials',n,'failures',bad,dict(stats))
