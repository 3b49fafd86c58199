// Cheng, Lansivaara & Wei (2007), Computers and Geotechnics 34(3), 137-150: the benched
// homogeneous slope of the local and global minima, 16.85 m high; c' = 5 kPa,
// phi' = 30 deg, gamma = 20 kN/m^3. The RS2 slope stability verification problem 61,
// case 1 (the global minimum); the coordinates are the RS2 model's as transcribed in
// the public xslope benchmark set (provenance: references/plastic.md). Section (m):
//   (-0.057,0.073) (54.324,0.073) (54.324,26.811) (42.905,26.811) crest,
//   (34.878,22.797) (31.939,19.858) (26.003,19.858) (20.011,14.883),
//   (10.118,9.965) toe, (-0.057,9.965)
// Included by c61-*.geo, which set `shape` (and `refine`) first; extruded by ../slab.geo.
// Patches as in verification/cases/slope/slope.geo: A left of the toe and B right of it,
// both below the toe's level; above it, C up to the bench's level (z = 19.858) and D
// above the bench (a single patch over the bench would squash the hexahedra under it).
If (!Exists(refine))
  refine = 1;
EndIf
H = 16.846;
t = 2.1;          // slab thickness (y), about one element
h = 2.1 / refine; // element size of the unstructured shapes (2.1 m at refine = 1)
x0 = -0.057; x1 = 54.324; zb = 0.073;
has_left = 1;
gx[] = {-0.057, 10.118, 20.011, 26.003, 31.939, 34.878, 42.905, 54.324};
gz[] = {9.965, 9.965, 14.883, 19.858, 19.858, 22.797, 26.811, 26.811};

Point(1) = {-0.057, 0, 0.073};
Point(2) = {10.118, 0, 0.073};
Point(3) = {54.324, 0, 0.073};
Point(4) = {54.324, 0, 9.965};
Point(5) = {54.324, 0, 26.811};
Point(6) = {42.905, 0, 26.811};
Point(7) = {34.878, 0, 22.797};
Point(8) = {31.939, 0, 19.858};
Point(9) = {26.003, 0, 19.858};
Point(10) = {20.011, 0, 14.883};
Point(11) = {10.118, 0, 9.965};
Point(12) = {-0.057, 0, 9.965};
Point(13) = {54.324, 0, 19.858};
Line(1) = {1, 2};   // base of A
Line(2) = {2, 3};   // base of B
Line(3) = {3, 4};   // right side of B
Line(4) = {4, 13};   // right side of C
Line(5) = {5, 6};   // crest
Line(6) = {6, 7};   // slope face, segment 1 from the crest
Line(7) = {7, 8};   // slope face, segment 2 from the crest
Line(8) = {8, 9};   // slope face, segment 3 from the crest
Line(9) = {9, 10};   // slope face, segment 4 from the crest
Line(10) = {10, 11};   // slope face, segment 5 from the crest
Line(11) = {11, 12};   // ground left of the toe
Line(12) = {12, 1};   // left side
Line(13) = {2, 11};   // A | B
Line(14) = {11, 4};   // B | C
Line(15) = {13, 5};   // right side of D
Line(16) = {8, 13};   // C | D, at the bench's level
// Loops clockwise in (x, z): the normals point to +y, the extrusion direction.
Curve Loop(1) = {-12, -11, -13, -1};
Plane Surface(1) = {1};
Curve Loop(2) = {13, 14, -3, -2};
Plane Surface(2) = {2};
Curve Loop(3) = {-10, -9, -8, 16, -4, -14};
Plane Surface(3) = {3};
Curve Loop(4) = {-7, -6, -5, -15, -16};
Plane Surface(4) = {4};
surf[] = {1, 2, 3, 4};
fc[] = {6, 7, 8, 9, 10};   // the slope face

If (shape == 0)
  // A: 5 x 5; B: 22 x 5; C: 22 along its base (3 on the bench, 19 right of it),
  // 10 up the lower face and its right side; D: 19 x 7
  Transfinite Curve{1, 11} = 5 * refine + 1;   // 2.035 m
  Transfinite Curve{12, 13, 3} = 5 * refine + 1;   // 1.978 m
  Transfinite Curve{2, 14} = 22 * refine + 1;   // 2.009 m
  Transfinite Curve{16, 5} = 19 * refine + 1;   // 1.178 m at the bench's level, 0.601 m on the crest
  Transfinite Curve{6} = 5 * refine + 1;   // 1.795 m along the face
  Transfinite Curve{7} = 2 * refine + 1;   // 2.078 m along the face
  Transfinite Curve{8} = 3 * refine + 1;   // 1.979 m along the bench
  Transfinite Curve{9} = 4 * refine + 1;   // 1.947 m along the face
  Transfinite Curve{10} = 6 * refine + 1;   // 1.841 m along the face
  Transfinite Curve{4} = 10 * refine + 1;   // 0.989 m
  Transfinite Curve{15} = 7 * refine + 1;   // 0.993 m
  Transfinite Surface{1} = {1, 2, 11, 12};
  Transfinite Surface{2} = {2, 3, 4, 11};
  Transfinite Surface{3} = {11, 4, 13, 9};
  Transfinite Surface{4} = {8, 13, 5, 6};
  Recombine Surface{1, 2, 3, 4};
EndIf
