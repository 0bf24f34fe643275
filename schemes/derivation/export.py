# Writes the derived elements as `dualhex-element 1` files (untrusted producer; the C++
# element checker validates every file at load time).
import sys, os
from cx import orient_cell, U
from rule import CANON

def export(name, cells, path):
    verts={}
    lines=[]
    oriented=[]
    for label,fl in cells:
        of,_=orient_cell(fl)
        oriented.append((label,of))
        for f in of:
            for p in f: verts.setdefault(p,len(verts))
    out=['# %s — derived in schemes/derivation (see docs/scheme-derivation.md); checked by dualhex::check_element'%name,
         'dualhex-element 1','name %s'%name,'leaf %d'%U]
    for p,i in sorted(verts.items(), key=lambda kv:kv[1]):
        out.append('vertex %d %d %d %d'%(i,p[0],p[1],p[2]))
    for label,of in oriented:
        out.append('cell %s'%label.split('.',1)[-1].replace('.','_'))
        for f in of: out.append('face '+' '.join(str(verts[p]) for p in f))
        out.append('end')
    open(path,'w').write('\n'.join(out)+'\n')

if __name__=='__main__':
    d=sys.argv[1]
    for name,(fn,*_) in CANON.items():
        export(name, fn(), os.path.join(d, name+'.element'))
        print('wrote', name)
