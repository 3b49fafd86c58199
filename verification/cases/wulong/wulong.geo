// Wulong landslide (1 May 2001, Chongqing; paper Figs. 11-14, docs/method.md section 3):
// a plane-strain slab (x-z section, one element thick in y, 0..2 m) of a steep layered
// rock slope whose element faces follow the two joint sets.
//
// From the paper: bedding dipping 11 deg (SE130/11) and a steep set nearly parallel to
// the slope face; blocks up to about 10 m^3; a toe excavated at about 60 deg for
// National Road 319 and a building. Everything else is ours (the paper gives no
// section):
// - the section: a road/building platform at z = 20 m (x = 0..30 m, the toe at x = 30),
//   a 60 deg cut up to z = 45 m, a 38 deg natural slope up to the crest at z = 85 m
//   (slope height 65 m), behind the crest a dip slope along a bedding plane up to
//   x = 140 m; base z = 0 (20 m of rock below the platform);
// - in the section the bedding is drawn with an apparent dip of 11 deg toward the free
//   face (-x); the steep set dips 75 deg toward the face; spacings: 3.0 m along the
//   bedding between steep joints, 2.5 m along the steep joints between bedding planes
//   (blocks of 6.7 m^2, i.e. 13.5 m^3 in the 2 m slab);
// - the ground is snapped to the lattice: on every steep joint it passes through the
//   nearest joint/bedding intersection of the designed profile above, so the cut is
//   58-62 deg and the natural slope 39.7 deg (one bedding step per joint), with one
//   11 deg bench; the cells the ground cuts are clipped into quadrilaterals and
//   triangles (a triangle becomes a prism);
// - the jointed zone lies between the steep joint through the toe (i = 0), the steep
//   joint i = N = 28 (x = 110-127 m, 15-30 m behind the crest) and the bedding plane
//   4 spacings (10 m along the steep joint) below the toe; the platform, the base and
//   the far side around it ("frame") are meshed freely (3-6 m quadrilaterals, some
//   triangles): their faces do not follow the structure;
// - "nearsurface": the jointed blocks whose centroid lies within D = 8 m of the ground
//   (shortest distance); the other blocks and the frame are "interior". Surface
//   groups: "nearsurface_joints", every face of a near-surface block except its
//   ground face (so also the band's boundary with the interior); "interior_joints",
//   the other faces of the jointed zone. The frame's own faces and its boundary with
//   the jointed zone are in no group: where a freely meshed element meets a block, the
//   spring forces are uneven and would start a spurious crack along that boundary
//   (they did, along joint N, when it was breakable).
// One element per block (transfinite, 2 nodes per curve), built-in kernel; everything
// is extruded at once with Layers{1} and made coherent, so neighbours share their face
// (conforming hexahedra and prisms): 620 blocks (604 hexahedra, 16 prisms; 165 of them
// near-surface) and a frame of 291 elements (250 hexahedra, 41 prisms).
Mesh.MshFileVersion = 4.1;

// 1. Structure.
al = 11 * Pi / 180;          // bedding: apparent dip toward the face
be = 75 * Pi / 180;          // steep set
a = 3.0;                     // steep-joint spacing along the bedding (m)
c = 2.5;                     // bedding spacing along the steep joints (m)
bx = Cos(al); bz = Sin(al);  // along the bedding, up-dip (+x)
jx = Cos(be); jz = Sin(be);  // along a steep joint, upward
// Lattice point P(i, k) = toe + i a (bx, bz) + k c (jx, jz): steep joint i, bedding k.

// 2. Section (m).
L = 140; W = 2;
x0 = 30; z0 = 20;            // the toe, P(0, 0); the platform is z = z0, x < x0
zt = 45; zc = 85;            // top of the cut, crest
xt = x0 + (zt - z0) / Tan(60 * Pi / 180);
xc = xt + (zc - zt) / Tan(38 * Pi / 180);
px[] = {x0, xt, xc, xc + 200 * bx};   // designed profile: cut, natural slope, dip slope
pz[] = {z0, zt, zc, zc + 200 * bz};
N = 28;                      // steep joints i = 0..N
kb = -4;                     // lowest bedding plane of the jointed zone
D = 8;                       // near-surface band (m)
// `apron` (m, default 0): the platform (the toe road) extended this far beyond the model's
// left side at x = 0, to x = -apron, for the runout (verification/runout/wulong-apron.geo):
// ground for the blocks that leave the slope to land on. 0 gives the paper case's mesh.
If (!Exists(apron))
  apron = 0;
EndIf
lcs = 3; lcf = 6;            // mesh sizes: jointed zone, frame corners

// 3. The ground row kg[i] of every steep joint: the nearest bedding plane to where
//    the joint meets the designed profile. The lattice ground must not fall toward +x.
For i In {0:N}
  ox = x0 + i * a * bx; oz = z0 + i * a * bz;
  found = 0;
  For s In {0:#px[] - 2}
    dx = px[s + 1] - px[s]; dz = pz[s + 1] - pz[s];
    det = dx * jz - dz * jx;
    rx = px[s] - ox; rz = pz[s] - oz;
    t = (rz * dx - rx * dz) / det;
    u = (rz * jx - rx * jz) / det;
    If (found == 0 && u >= -1e-9 && u <= 1 + 1e-9)
      kg[i] = Floor(t / c + 0.5);
      found = 1;
    EndIf
  EndFor
  If (i > 0)
    If (kg[i] < kg[i - 1])
      Error("wulong.geo: the lattice ground falls at steep joint %g", i);
      Exit;
    EndIf
  EndIf
EndFor
NK = kg[N] - kb + 1;         // rows per joint in the index tables: P(i, k) -> i NK + k - kb

// 4. Lattice points up to the ground, steep-joint and bedding segments.
For i In {0:N}
  For k In {kb:kg[i]}
    p = newp;
    Point(p) = {x0 + i * a * bx + k * c * jx, 0, z0 + i * a * bz + k * c * jz, lcs};
    pt[i * NK + k - kb] = p;
  EndFor
EndFor
For i In {0:N}
  For k In {kb:kg[i] - 1}
    l = newl; Line(l) = {pt[i * NK + k - kb], pt[i * NK + k + 1 - kb]}; jl[i * NK + k - kb] = l;
  EndFor
EndFor
For i In {0:N - 1}
  For k In {kb:kg[i]}
    l = newl; Line(l) = {pt[i * NK + k - kb], pt[(i + 1) * NK + k - kb]}; bl[i * NK + k - kb] = l;
  EndFor
EndFor

// The ground polyline (for the band): platform, lattice ground, dip slope to x = L.
zR = z0 + N * a * bz + kg[N] * c * jz + (L - (x0 + N * a * bx + kg[N] * c * jx)) * Tan(al);
gx[] = {0}; gz[] = {z0};
For i In {0:N}
  gx[] += x0 + i * a * bx + kg[i] * c * jx; gz[] += z0 + i * a * bz + kg[i] * c * jz;
EndFor
gx[] += L; gz[] += zR;

gc[] = {};                   // ground curves
blocks[] = {}; near[] = {}; ncrv[] = {}; inner[] = {}; crvs[] = {};

// One block: curve loop crv[] through the points vp[] (same order), one element;
// sorted into the band by the distance of its centroid to the ground. Its curves
// (ground curves as 0) are kept for the extrusion below.
Macro AddBlock
  cl = newcl; Curve Loop(cl) = crv[];
  s = news; Plane Surface(s) = {cl};
  Transfinite Surface{s}; Recombine Surface{s};
  cx = 0; cz = 0;
  For q In {0:#vp[] - 1}
    xyz[] = Point{vp[q]};
    cx = cx + xyz[0] / #vp[]; cz = cz + xyz[2] / #vp[];
  EndFor
  dmin = 1e9;
  For q In {0:#gx[] - 2}
    ex = gx[q + 1] - gx[q]; ez = gz[q + 1] - gz[q];
    f = ((cx - gx[q]) * ex + (cz - gz[q]) * ez) / (ex * ex + ez * ez);
    f = Max(0, Min(1, f));
    dmin = Min(dmin, Hypot(cx - gx[q] - f * ex, cz - gz[q] - f * ez));
  EndFor
  blocks[] += s; near[] += (dmin < D); ncrv[] += #crv[];
  For q In {0:#crv[] - 1}
    ground = 0;
    For g In {0:#gc[] - 1}
      If (Fabs(crv[q]) == gc[g])
        ground = 1;
      EndIf
    EndFor
    inner[] += 1 - ground; crvs[] += crv[q];
  EndFor
Return

Transfinite Curve{:} = 2;

// 5. Blocks, column by column (between steep joints i and i + 1).
For i In {0:N - 1}
  A = i * NK - kb; B = (i + 1) * NK - kb;       // pt[A + k] = P(i, k), pt[B + k] = P(i + 1, k)
  kl = kg[i]; kr = kg[i + 1]; n = kr - kl;
  If (n == 0)
    gc[] += bl[A + kl];                         // the ground runs along a bedding plane
  EndIf
  For k In {kb:kl - 1}                          // whole blocks
    crv[] = {bl[A + k], jl[B + k], -bl[A + k + 1], -jl[A + k]};
    vp[] = {pt[A + k], pt[B + k], pt[B + k + 1], pt[A + k + 1]};
    Call AddBlock;
  EndFor
  If (n > 0)                                    // the ground rises across rows kl..kr-1:
    gl[] = Point{pt[A + kl]}; gr[] = Point{pt[B + kr]};
    S = pt[A + kl]; bot = bl[A + kl];           // clipped blocks between the bedding
    For r In {kl:kr - 1}                        // planes, steep joint i + 1 and the ground
      If (r + 1 < kr)
        f = (r + 1 - kl) / n;
        X = newp; Point(X) = {gl[0] + f * (gr[0] - gl[0]), 0, gl[2] + f * (gr[2] - gl[2]), lcs};
        pb = newl; Line(pb) = {X, pt[B + r + 1]};
        g = newl; Line(g) = {S, X}; gc[] += g;
        Transfinite Curve{pb, g} = 2;
        crv[] = {bot, jl[B + r], -pb, -g};
        vp[] = {S, pt[B + r], pt[B + r + 1], X};
        Call AddBlock;
        S = X; bot = pb;
      Else
        g = newl; Line(g) = {S, pt[B + kr]}; gc[] += g;
        Transfinite Curve{g} = 2;
        crv[] = {bot, jl[B + r], -g};
        vp[] = {S, pt[B + r], pt[B + kr]};
        Call AddBlock;
      EndIf
    EndFor
  EndIf
EndFor

// 6. The frame: platform, base and far side around the jointed zone, meshed freely.
f1 = newp; Point(f1) = {-apron, 0, 0, lcf};
f2 = newp; Point(f2) = {L, 0, 0, lcf};
f3 = newp; Point(f3) = {L, 0, zR, lcf};
f4 = newp; Point(f4) = {-apron, 0, z0, lcf};
l1 = newl; Line(l1) = {f1, f2};
l2 = newl; Line(l2) = {f2, f3};
l3 = newl; Line(l3) = {f3, pt[N * NK + kg[N] - kb]};
crv[] = {l1, l2, l3};
For k In {kg[N] - 1:kb:-1}
  crv[] += -jl[N * NK + k - kb];
EndFor
For i In {N - 1:0:-1}
  crv[] += -bl[i * NK];
EndFor
For k In {kb:-1}
  crv[] += jl[k - kb];
EndFor
l4 = newl; Line(l4) = {pt[-kb], f4};
l5 = newl; Line(l5) = {f4, f1};
fb[] = crv[{3:#crv[] - 1}];                      // curves shared with the jointed zone
crv[] += {l4, l5};
cl = newcl; Curve Loop(cl) = crv[];
frame = news; Plane Surface(frame) = {cl};
Recombine Surface{frame};
Mesh.Algorithm = 8;

// 7. One extrusion of everything, then one coherence pass (shared curves give
//    shared faces; automatic coherence after each extrusion takes 15 s). The output lists, per
//    surface: top, volume, then the faces extruded from its curves in curve-loop
//    order; coherence keeps the first (lowest) of duplicate faces: lat[curve].
Geometry.AutoCoherence = 0;
out[] = Extrude {0, W, 0} { Surface{blocks[], frame}; Layers{1}; Recombine; };
Coherence;
nsv[] = {}; inv[] = {}; nsj[] = {}; ij[] = {};
lat[newl] = 0;
o = 0; c0 = 0;
For m In {0:#blocks[] - 1}
  For q In {0:ncrv[m] - 1}
    C = Fabs(crvs[c0 + q]);
    If (lat[C] == 0 || out[o + 2 + q] < lat[C])
      lat[C] = out[o + 2 + q];
    EndIf
  EndFor
  o += 2 + ncrv[m]; c0 += ncrv[m];
EndFor
o = 0; c0 = 0;
For m In {0:#blocks[] - 1}
  If (near[m])
    nsv[] += out[o + 1];
    For q In {0:ncrv[m] - 1}
      If (inner[c0 + q])
        nsj[] += lat[Fabs(crvs[c0 + q])];
      EndIf
    EndFor
  Else
    inv[] += out[o + 1];
    For q In {0:ncrv[m] - 1}
      ij[] += lat[Fabs(crvs[c0 + q])];
    EndFor
  EndIf
  o += 2 + ncrv[m]; c0 += ncrv[m];
EndFor
inv[] += out[o + 1];                              // the frame
nsj[] = Unique(nsj[]);
ij[] = Unique(ij[]);
ij[] -= nsj[];                                    // the band's boundary is near-surface
For q In {0:#fb[] - 1}                            // the boundary with the frame is not
  nsj[] -= lat[Fabs(fb[q])];                      // a joint: in no group, like the frame
  ij[] -= lat[Fabs(fb[q])];
EndFor

// 8. Groups.
Physical Volume("interior") = {inv[]};
Physical Volume("nearsurface") = {nsv[]};
Physical Surface("nearsurface_joints") = {nsj[]};
Physical Surface("interior_joints") = {ij[]};
e = 1e-6;
Physical Surface("bottom") = Surface In BoundingBox{-apron - e, -e, -e, L + e, W + e, e};
Physical Surface("left") = Surface In BoundingBox{-apron - e, -e, -e, -apron + e, W + e, z0 + e};
Physical Surface("right") = Surface In BoundingBox{L - e, -e, -e, L + e, W + e, zR + e};
Physical Surface("front") = Surface In BoundingBox{-apron - e, -e, -e, L + e, e, 2 * zR};
Physical Surface("back") = Surface In BoundingBox{-apron - e, W - e, -e, L + e, W + e, 2 * zR};
