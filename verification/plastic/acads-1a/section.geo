// ACADS (1989) problem 1(a) (references/lem.md): a homogeneous slope 10 m high at 2:1
// on a 5 m foundation; c' = 3 kPa, phi' = 19.6 deg, gamma = 20 kN/m^3. The RS2 slope
// stability verification problem 1 (provenance: references/plastic.md). Section (m):
//   (20,20) (70,20) (70,35) (50,35) crest, (30,25) toe, (20,25)
// Included by acads-*.geo, which set `shape` (and `refine`) first; extruded by ../slab.geo.
// Patches as in verification/cases/slope/slope.geo: A left of the toe and B right of it,
// both below the toe's level, C above it (the face to the crest).
If (!Exists(refine))
  refine = 1;
EndIf
H = 10;
t = 1.25;          // slab thickness (y), about one element
h = 1.25;          // element size of the unstructured shapes
x0 = 20; x1 = 70; zb = 20;
has_left = 1;
gx[] = {20, 30, 50, 70};
gz[] = {25, 25, 35, 35};

Point(1) = {20, 0, 20};
Point(2) = {30, 0, 20};
Point(3) = {70, 0, 20};
Point(4) = {70, 0, 25};
Point(5) = {70, 0, 35};
Point(6) = {50, 0, 35};
Point(7) = {30, 0, 25};
Point(8) = {20, 0, 25};
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
  // A: 8 x 4; B: 32 x 4; C: 32 along its base and the crest, 18 along the face and its right side
  Transfinite Curve{1, 7} = 8 * refine + 1;   // 1.250 m
  Transfinite Curve{8, 9, 3} = 4 * refine + 1;   // 1.250 m
  Transfinite Curve{2, 10, 5} = 32 * refine + 1;   // 1.250 m below, 0.625 m on the crest
  Transfinite Curve{6} = 18 * refine + 1;   // 1.242 m along the face
  Transfinite Curve{4} = 18 * refine + 1;   // 0.556 m
  Transfinite Surface{1} = {1, 2, 7, 8};
  Transfinite Surface{2} = {2, 3, 4, 7};
  Transfinite Surface{3} = {7, 4, 5, 6};
  Recombine Surface{1, 2, 3};
EndIf
