// A block on a long base, in the x-z section, one element deep in y (1 m).
// Included by sliding.geo, at-rest.geo, toppling.geo, launched.geo and
// dropped.geo, which set: h (block height), w (block length along x),
// nz (block layers), gap (block's lift above the base; 0: they share nodes
// along the face "contact", whose springs hand over to the runout contact),
// x_end (the base's downslope end). The base runs from x = -4 to x_end,
// 2 m elements, 2 m deep; the block from x = 0 to w in 2 m elements.
// Units m. Gravity is tilted by the scene or the test (the plane is level).
Mesh.MshFileVersion = 4.1;
dx = 2.0;

// Base section (z from -2 to 0): three rectangles split at x = 0 and x = w.
Point(1) = {-4, 0, -2};
Point(2) = {0, 0, -2};
Point(3) = {w, 0, -2};
Point(4) = {x_end, 0, -2};
Point(5) = {x_end, 0, 0};
Point(6) = {w, 0, 0};
Point(7) = {0, 0, 0};
Point(8) = {-4, 0, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 6};
Line(6) = {6, 7};
Line(7) = {7, 8};
Line(8) = {8, 1};
Line(9) = {2, 7};
Line(10) = {3, 6};
Curve Loop(1) = {1, 9, 7, 8};
Curve Loop(2) = {2, 10, 6, -9};
Curve Loop(3) = {3, 4, 5, -10};
Plane Surface(1) = {1};
Plane Surface(2) = {2};
Plane Surface(3) = {3};
Transfinite Curve{1, 7} = 3;
Transfinite Curve{2, 6} = Round(w / dx) + 1;
Transfinite Curve{3, 5} = Round((x_end - w) / dx) + 1;
Transfinite Curve{4, 8, 9, 10} = 2;

// Block section (z from gap to gap + h).
If (gap > 0)
  Point(11) = {0, 0, gap};
  Point(12) = {w, 0, gap};
  Line(11) = {11, 12};
  b0 = 11; b1 = 12; bottom_line = 11;
Else
  b0 = 7; b1 = 6; bottom_line = -6;
EndIf
Point(13) = {w, 0, gap + h};
Point(14) = {0, 0, gap + h};
Line(12) = {b1, 13};
Line(13) = {13, 14};
Line(14) = {14, b0};
Curve Loop(4) = {bottom_line, 12, 13, 14};
Plane Surface(4) = {4};
If (gap > 0)
  Transfinite Curve{11} = Round(w / dx) + 1;
EndIf
Transfinite Curve{13} = Round(w / dx) + 1;
Transfinite Curve{12, 14} = nz + 1;
Transfinite Surface{1, 2, 3, 4};
Recombine Surface{1, 2, 3, 4};

// One element deep: the section (x-z, normal -y) extruded along +y.
ex[] = Extrude {0, 1, 0} { Surface{1, 2, 3, 4}; Layers{1}; Recombine; };

Physical Volume("base") = {ex[1], ex[7], ex[13]};
Physical Volume("block") = {ex[19]};
Physical Surface("bottom") = Surface In BoundingBox{-4.01, -0.01, -2.01, x_end + 0.01, 1.01, -1.99};
If (gap == 0)
  Physical Surface("contact") = Surface In BoundingBox{-0.01, -0.01, -0.01, w + 0.01, 1.01, 0.01};
EndIf
