// Griffiths & Lane (1999), Geotechnique 49(3), 387-403, Example 1: a homogeneous
// 2:1 slope (26.57 deg) with no foundation layer (depth factor D = 1: the firm base
// at the toe's level), crest platform 1.2 H behind the crest, here with H = 10 m
// (the paper is dimensionless: c'/(gamma H) = 0.05, phi' = 20 deg). Provenance:
// references/plastic.md. Section in the x-z plane (m), the toe at the origin:
//   (0,0) toe   (20,10) crest   (32,10) back of the crest platform   (32,0)
// One patch (the whole trapezoid): corners toe, (32,0), (32,10), crest; for
// hexahedra the face and the back get nS divisions, the base and the crest nB.
// Included by gl1-*.geo, which set `shape` (and `refine`) first.
If (!Exists(refine))
  refine = 1;
EndIf
H = 10;
t = 1.25;          // slab thickness (y), about one element (H/8)
h = 1.25 / refine; // element size of the unstructured shapes (H/8 at refine = 1)
x0 = 0; x1 = 32; zb = 0;
has_left = 0;      // the toe is the section's left end
gx[] = {0, 20, 32};
gz[] = {0, 10, 10};

Point(1) = {0, 0, 0};
Point(2) = {32, 0, 0};
Point(3) = {32, 0, 10};
Point(4) = {20, 0, 10};
Line(1) = {1, 2};   // base
Line(2) = {2, 3};   // back
Line(3) = {3, 4};   // crest platform
Line(4) = {4, 1};   // slope face
// Clockwise in (x, z): the normal points to +y, the extrusion direction.
Curve Loop(1) = {-4, -3, -2, -1};
Plane Surface(1) = {1};
surf[] = {1};
fc[] = {4};   // the slope face

If (shape == 0)
  nS = 16 * refine;   // face 22.36 m / 16 = 1.40 m (H/7), back 10 m / 16 = 0.63 m
  nB = 24 * refine;   // base 32 m / 24 = 1.33 m, crest 12 m / 24 = 0.5 m
  Transfinite Curve{4, 2} = nS + 1;
  Transfinite Curve{1, 3} = nB + 1;
  Transfinite Surface{1} = {1, 2, 3, 4};
  Recombine Surface{1};
EndIf
