// One-element-wide laterally confined column for the joint-stiffness cases of
// the stiff and extreme suite: 4 m x 4 m x 40 m, 1 x 1 x 10 hexahedra, so the
// only element interfaces are horizontal (an exactly 1-D problem). Units m.
Mesh.MshFileVersion = 4.1;

Point(1) = {0, 0, 0};
Point(2) = {4, 0, 0};
Point(3) = {4, 4, 0};
Point(4) = {0, 4, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = 2;
Transfinite Surface{1};
Recombine Surface{1};

// out[0] top, out[1] volume, out[2..5] sides along curves 1..4.
out[] = Extrude {0, 0, 40} { Surface{1}; Layers{10}; Recombine; };

Physical Volume("rock") = {out[1]};
Physical Surface("bottom") = {1};
Physical Surface("top") = {out[0]};
Physical Surface("ymin") = {out[2]};
Physical Surface("xmax") = {out[3]};
Physical Surface("ymax") = {out[4]};
Physical Surface("xmin") = {out[5]};
