// Cheng, Lansivaara & Wei (2007), Computers and Geotechnics 34(3), 137-150: the
// homogeneous slope 11 m high, a 45 deg face 6 m high from the toe, then 1:2 to the
// crest; c' = 10 kPa, phi' = 30 deg, gamma = 20 kN/m^3, E = 14 MPa, nu = 0.3. The RS2
// slope stability verification problem 63 (provenance: references/plastic.md).
// Section (m): (0,0) (46,0) (46,21) (26,21) crest, (16,16), (10,10) toe, (0,10)
// Included by c63-*.geo, which set `shape` (and `refine`) first; extruded by ../slab.geo.
// Patches as in verification/cases/slope/slope.geo: A left of the toe and B right of it,
// both below the toe's level, C above it (the face to the crest).
If (!Exists(refine))
  refine = 1;
EndIf
H = 11;
t = 1.375;          // slab thickness (y), about one element
h = 1.375;          // element size of the unstructured shapes
x0 = 0; x1 = 46; zb = 0;
has_left = 1;
gx[] = {0, 10, 16, 26, 46};
gz[] = {10, 10, 16, 21, 21};

Point(1) = {0, 0, 0};
Point(2) = {10, 0, 0};
Point(3) = {46, 0, 0};
Point(4) = {46, 0, 10};
Point(5) = {46, 0, 21};
Point(6) = {26, 0, 21};
Point(7) = {16, 0, 16};
Point(8) = {10, 0, 10};
Point(9) = {0, 0, 10};
Line(1) = {1, 2};   // base of A
Line(2) = {2, 3};   // base of B
Line(3) = {3, 4};   // right side of B
Line(4) = {4, 5};   // right side of C
Line(5) = {5, 6};   // crest
Line(6) = {6, 7};   // slope face, segment 1 from the crest
Line(7) = {7, 8};   // slope face, segment 2 from the crest
Line(8) = {8, 9};   // ground left of the toe
Line(9) = {9, 1};   // left side
Line(10) = {2, 8};   // A | B
Line(11) = {8, 4};   // B | C
// Loops clockwise in (x, z): the normals point to +y, the extrusion direction.
Curve Loop(1) = {-9, -8, -10, -1};
Plane Surface(1) = {1};
Curve Loop(2) = {10, 11, -3, -2};
Plane Surface(2) = {2};
Curve Loop(3) = {-7, -6, -5, -4, -11};
Plane Surface(3) = {3};
surf[] = {1, 2, 3};
fc[] = {6, 7};   // the slope face

If (shape == 0)
  // A: 8 x 8; B: 27 x 8; C: 27 along its base and the crest, 16 along the face and its right side
  Transfinite Curve{1, 8} = 8 * refine + 1;   // 1.250 m
  Transfinite Curve{9, 10, 3} = 8 * refine + 1;   // 1.250 m
  Transfinite Curve{2, 11, 5} = 27 * refine + 1;   // 1.333 m below, 0.741 m on the crest
  Transfinite Curve{6} = 9 * refine + 1;   // 1.242 m along the face
  Transfinite Curve{7} = 7 * refine + 1;   // 1.212 m along the face
  Transfinite Curve{4} = 16 * refine + 1;   // 0.688 m
  Transfinite Surface{1} = {1, 2, 8, 9};
  Transfinite Surface{2} = {2, 3, 4, 8};
  Transfinite Surface{3} = {8, 4, 5, 6};
  Recombine Surface{1, 2, 3};
EndIf
