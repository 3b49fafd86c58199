// Yamagami & Ueta (1988), Proc. 6th Int. Conf. Numer. Meth. Geomech., Innsbruck: a
// homogeneous slope 5 m high at 2:1 (26.57 deg) on a 5 m foundation; c' = 9.8 kPa,
// phi' = 10 deg, gamma = 17.64 kN/m^3. The Rocscience Slide2 verification problem 17 and
// RS2 slope stability verification problem 13 (provenance: references/plastic.md).
// Section (m): (0,0) (25,0) (25,10) (15,10) crest, (5,5) toe, (0,5)
// Included by yu-*.geo, which set `shape` (and `refine`) first; extruded by ../slab.geo.
// Patches as in verification/cases/slope/slope.geo: A left of the toe and B right of it,
// both below the toe's level, C above it (the face to the crest).
If (!Exists(refine))
  refine = 1;
EndIf
H = 5;
t = 0.625;          // slab thickness (y), about one element
h = 0.625;          // element size of the unstructured shapes
x0 = 0; x1 = 25; zb = 0;
has_left = 1;
gx[] = {0, 5, 15, 25};
gz[] = {5, 5, 10, 10};

Point(1) = {0, 0, 0};
Point(2) = {5, 0, 0};
Point(3) = {25, 0, 0};
Point(4) = {25, 0, 5};
Point(5) = {25, 0, 10};
Point(6) = {15, 0, 10};
Point(7) = {5, 0, 5};
Point(8) = {0, 0, 5};
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
  // A: 8 x 8; B: 29 x 8; C: 29 along its base and the crest, 16 along the face and its right side
  Transfinite Curve{1, 7} = 8 * refine + 1;   // 0.625 m
  Transfinite Curve{8, 9, 3} = 8 * refine + 1;   // 0.625 m
  Transfinite Curve{2, 10, 5} = 29 * refine + 1;   // 0.690 m below, 0.345 m on the crest
  Transfinite Curve{6} = 16 * refine + 1;   // 0.699 m along the face
  Transfinite Curve{4} = 16 * refine + 1;   // 0.312 m
  Transfinite Surface{1} = {1, 2, 7, 8};
  Transfinite Surface{2} = {2, 3, 4, 7};
  Transfinite Surface{3} = {7, 4, 5, 6};
  Recombine Surface{1, 2, 3};
EndIf
