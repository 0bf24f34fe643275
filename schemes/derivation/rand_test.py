import random, sys, collections
from rule import *
from cx import check
seed=int(sys.argv[1]) if len(sys.argv)>1 else 1
n=int(sys.argv[2]) if len(sys.argv)>2 else 20
rng=random.Random(seed); stats=collections.Counter(); bad=0
for t in range(n):
    p=rng.random()
    bits=[rng.random()<p for _ in range(64)]
    fo=lambda x,y,z:bits[x+4*y+16*z]
    cx,used=build_periodic(fo,4)
    ok,h,bv,be,errs=check(cx,per=96,verbose=False)
    for k in used: stats[k]+=used[k]
    if not ok:
        bad+=1; print('FAIL trial',t,'p=%.2f'%p,used,bv[:3],be[:3],errs[:2])
print('seed',seed,'trials',n,'failures',bad,dict(stats))
