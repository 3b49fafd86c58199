// Arai & Tagyo (1985), Soils and Foundations 25(1), example 1: a homogeneous slope 20 m
// high at 1.5:1 (33.69 deg) on a 15 m foundation; c' = 41.65 kPa, phi' = 15 deg,
// gamma = 18.82 kN/m^3. The Rocscience Slide2 verification problem 14 and RS2 slope
// stability verification problem 10 (provenance: references/plastic.md). Section (m):
//   (0,0) (66,0) (66,35) (48,35) crest, (18,15) toe, (0,15)
// Included by at-*.geo, which set `shape` (and `refine`) first; extruded by ../slab.geo.
// Patches as in verification/cases/slope/slope.geo: A left of the toe and B right of it,
// both below the toe's level, C above it (the face to the crest).
If (!Exists(refine))
  refine = 1;
EndIf
H = 20;
t = 2.5;          // slab thickness (y), about one element
h = 2.5;          // element size of the unstructured shapes
x0 = 0; x1 = 66; zb = 0;
has_left = 1;
gx[] = {0, 18, 48, 66};
gz[] = {15, 15, 35, 35};

Point(1) = {0, 0, 0};
Point(2) = {18, 0, 0};
Point(3) = {66, 0, 0};
Point(4) = {66, 0, 15};
Point(5) = {66, 0, 35};
Point(6) = {48, 0, 35};
Point(7) = {18, 0, 15};
Point(8) = {0, 0, 15};
Line(1) = {1, 2};   // base of A
Line(2) = {2, 3};   // base of B
Line(3) = {3, 4};   // right side of B
Line(4) = {4, 5};   // right side of C
Line(5) = {5, 6};   // crest
Line(6) = {6, 7};   // slope face
Line(7) = {7, 8};   // ground left of the toe
Line(8) = {8, 1};   // left side
Line(9) = {2, 7};   // A | B
Line(10) = {7, 4};   // B | C
// Loops clockwise in (x, z): the normals point to +y, the extrusion direction.
Curve Loop(1) = {-8, -7, -9, -1};
Plane Surface(1) = {1};
Curve Loop(2) = {9, 10, -3, -2};
Plane Surface(2) = {2};
Curve Loop(3) = {-6, -5, -4, -10};
Plane Surface(3) = {3};
surf[] = {1, 2, 3};
fc[] = {6};   // the slope face

If (shape == 0)
  // A: 8 x 6; B: 20 x 6; C: 20 along its base and the crest, 15 along the face and its right side
  Transfinite Curve{1, 7} = 8 * refine + 1;   // 2.250 m
  Transfinite Curve{8, 9, 3} = 6 * refine + 1;   // 2.500 m
  Transfinite Curve{2, 10, 5} = 20 * refine + 1;   // 2.400 m below, 0.900 m on the crest
  Transfinite Curve{6} = 15 * refine + 1;   // 2.404 m along the face
  Transfinite Curve{4} = 15 * refine + 1;   // 1.333 m
  Transfinite Surface{1} = {1, 2, 7, 8};
  Transfinite Surface{2} = {2, 3, 4, 7};
  Transfinite Surface{3} = {7, 4, 5, 6};
  Recombine Surface{1, 2, 3};
EndIf
