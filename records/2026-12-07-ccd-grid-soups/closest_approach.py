# The closest approach over the interval of each pair that the reference reported and the
# detector left out, from soak_2000_2042.txt (corners in hex at both ends): the distance of the
# two moving triangles, sampled at 20,001 times and refined by ternary search. Run with
# /usr/bin/python3 closest_approach.py [FILE].
import sys
import numpy as np
def seg_seg(p0,p1,q0,q1):
    # the closed-form candidates of the closest pair of points (robust to degenerate segments)
    d1=p1-p0; d2=q1-q0; r=p0-q0
    a=d1@d1; e=d2@d2; f=d2@r; c=d1@r; b=d1@d2
    cands=[(0.0,0.0),(0.0,1.0),(1.0,0.0),(1.0,1.0)]
    for s in [0.0,1.0]:
        if e>0: cands.append((s,float(np.clip((b*s+f)/e,0,1))))
    for t in [0.0,1.0]:
        if a>0: cands.append((float(np.clip((b*t-c)/a,0,1)),t))
    den=a*e-b*b
    if a>0 and e>0 and den>1e-30*a*e:
        s=float(np.clip((b*f-c*e)/den,0,1)); t=float(np.clip((b*s+f)/e,0,1)); cands.append((s,t))
        s2=float(np.clip((b*t-c)/a,0,1)); cands.append((s2,t))
    return min(np.linalg.norm(p0+s*d1-(q0+t*d2)) for s,t in cands)
def pt_tri(p,a,b,c):
    n=np.cross(b-a,c-a); nn=np.linalg.norm(n)
    best=min(seg_seg(p,p,q0,q1) for q0,q1 in ((a,b),(b,c),(c,a)))
    if nn>1e-14:
        u,v,w=np.linalg.solve(np.array([b-a,c-a,n]).T,p-a)
        if u>=0 and v>=0 and u+v<=1: best=min(best,abs(w)*nn)
    return best
def seg_tri(p0,p1,a,b,c):
    n=np.cross(b-a,c-a); nn=np.linalg.norm(n)
    if nn>1e-14:
        s0=(p0-a)@n; s1=(p1-a)@n
        if s0*s1<=0 and s0!=s1:
            s=s0/(s0-s1); x=p0+s*(p1-p0)
            u,v,w=np.linalg.solve(np.array([b-a,c-a,n]).T,x-a)
            if u>=-1e-15 and v>=-1e-15 and u+v<=1+1e-15: return 0.0
    return min(pt_tri(p0,a,b,c),pt_tri(p1,a,b,c),*(seg_seg(p0,p1,q0,q1) for q0,q1 in ((a,b),(b,c),(c,a))))
def tri_tri(P,Q):
    return min(min(seg_tri(P[i],P[(i+1)%3],*Q) for i in range(3)), min(seg_tri(Q[i],Q[(i+1)%3],*P) for i in range(3)))
def parse(line, shift):
    v=[float.fromhex(x) for x in line.split(':')[1].split()]
    return [np.array(v[0:3])-shift,np.array(v[3:6])-shift,np.array(v[6:9])-shift]
def run(lines):
    x0=float.fromhex(lines[0].split(':')[1].split()[0]); shift=np.array([round(x0),0,0]) if abs(x0)>1000 else np.zeros(3)
    A0,A1,B0,B1=[parse(l,shift) for l in lines]
    def D(t):
        P=[(1-t)*A0[i]+t*A1[i] for i in range(3)]; Q=[(1-t)*B0[i]+t*B1[i] for i in range(3)]
        return tri_tri(P,Q)
    ts=np.linspace(0,1,20001); vals=np.array([D(t) for t in ts])
    i=int(np.argmin(vals)); print("  grid min %.3e at t=%.5f" % (vals[i], ts[i]))
    lo,hi=ts[max(i-2,0)],ts[min(i+2,len(ts)-1)]
    for _ in range(100):
        m1=lo+(hi-lo)/3; m2=hi-(hi-lo)/3
        if D(m1)<D(m2): hi=m2
        else: lo=m1
    print("  refined min %.3e at t=%.7f" % (D((lo+hi)/2), (lo+hi)/2))
L=open(sys.argv[1] if len(sys.argv) > 1 else 'soak_2000_2042.txt').read().splitlines()
seen=set()
for k,l in enumerate(L):
    if 'only in reference' not in l: continue
    key=l.split('|')[0]
    if key in seen: continue
    seen.add(key); print(l.strip()); run(L[k-5:k-1])
