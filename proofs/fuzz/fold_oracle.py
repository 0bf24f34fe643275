# Fold oracle for certificates (a tool for finding counterexamples, not a proof and not part
# of the checker): at random rational points x, the winding numbers of the cells' fan
# surfaces around x (torus: summed over the translates) are computed exactly by casting a
# ray with Fractions. An embedded subdivision has exactly one cell winding 1 at every x and
# all others 0; a point where that fails is a witness of overlap.
#   python3 fold_oracle.py CERT [SAMPLES] ["(x, y, z)" to sample within 9 units of]
import sys, random, itertools
from fractions import Fraction as Fr
def parse(fn):
    toks=[l.split('#')[0].split() for l in open(fn)]; toks=[x for x in toks if x]
    d={}
    for k,x in enumerate(toks):
        if x[0]=='domain': d['P']=int(x[2]) if x[1]=='torus' else None
        if x[0]=='vertices': n=int(x[1]); d['pos']=[tuple(map(int,y)) for y in toks[k+1:k+1+n]]
        if x[0]=='faces': n=int(x[1]); d['faces']=[list(map(int,y)) for y in toks[k+1:k+1+n]]
        if x[0]=='cells': n=int(x[1]); d['cells']=[[(int(y[1:]),y[0]=='-') for y in r] for r in toks[k+1:k+1+n]]
    return d
def sub(a,b): return (a[0]-b[0],a[1]-b[1],a[2]-b[2])
def cross(a,b): return (a[1]*b[2]-a[2]*b[1],a[2]*b[0]-a[0]*b[2],a[0]*b[1]-a[1]*b[0])
def dot(a,b): return a[0]*b[0]+a[1]*b[1]+a[2]*b[2]
def tris(d,k):
    P=d['P']; pos=d['pos']; cl=d['cells'][k]
    ref=pos[d['faces'][cl[0][0]][0]]
    def nr(p):
        if not P: return p
        return tuple(ref[a]+(((p[a]-ref[a])%P) if ((p[a]-ref[a])%P)<=P//2 else ((p[a]-ref[a])%P)-P) for a in range(3))
    out=[]
    for f,rev in cl:
        l=d['faces'][f]
        if rev: l=[l[0]]+l[1:][::-1]
        ps=[nr(pos[v]) for v in l]
        for j in range(1,len(ps)-1): out.append((ps[0],ps[j],ps[j+1]))
    return out
def winding(T,x,r):
    # signed crossings of ray x + t r (t>0) with triangles
    w=0
    for a,b,c in T:
        n=cross(sub(b,a),sub(c,a)); den=dot(n,r)
        if den==0: 
            if dot(n,sub(x,a))==0 and n!=(0,0,0): raise ValueError
            continue
        t=Fr(dot(n,sub(a,x)),den)
        if t<=0: continue
        p=tuple(x[i]+t*r[i] for i in range(3))
        s=[dot(cross(sub(b,a),sub(p,a)),n),dot(cross(sub(c,b),sub(p,b)),n),dot(cross(sub(a,c),sub(p,c)),n)]
        if any(v==0 for v in s): raise ValueError
        if all(v>0 for v in s) or all(v<0 for v in s): w+= 1 if den>0 else -1  # leaving along the outward normal
    return w
def check(fn, samples=300, seed=0, focus=None):
    d=parse(fn); P=d['P']; random.seed(seed)
    T=[tris(d,k) for k in range(len(d['cells']))]
    lo=[min(p[a] for p in d['pos']) for a in range(3)]; hi=[max(p[a] for p in d['pos']) for a in range(3)]
    bad=0
    for s in range(samples):
        if focus: x=tuple(Fr(focus[a]*1000+random.randint(-9000,9000),1000)+Fr(1,7919) for a in range(3))
        else: x=tuple(Fr(random.randint(lo[a]*1000,hi[a]*1000),1000)+Fr(1,7919) for a in range(3))
        r=tuple(random.randint(-10**6,10**6) for a in range(3))
        ws=[]
        try:
            for k,t in enumerate(T):
                shifts=[(0,0,0)] if not P else list(itertools.product([-P,0,P],repeat=3))
                w=0
                for sh in shifts:
                    y=(x[0]+sh[0],x[1]+sh[1],x[2]+sh[2])
                    if all(min(p[a] for tr in t for p in tr)<=y[a]<=max(p[a] for tr in t for p in tr) for a in range(3)): w+=winding(t,y,r)
                if w: ws.append((k,w))
        except ValueError: continue
        if not (len(ws)==1 and ws[0][1]==1): bad+=1; 
        if bad==1 and not (len(ws)==1 and ws[0][1]==1): print('  bad point',[float(v) for v in x],ws)
    return bad
if __name__=='__main__':
    print(sys.argv[1], 'bad samples', check(sys.argv[1], int(sys.argv[2]) if len(sys.argv)>2 else 100, focus=eval(sys.argv[3]) if len(sys.argv)>3 else None))
