// Two-layer laterally confined column for the contrast cases of the stiff and
// extreme suite: 4 m x 4 m x 40 m, "lower" z in [0, 20], "upper" z in [20, 40],
// 2 x 2 x 5 hexahedra per layer. Units m.
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
Transfinite Curve{1, 2, 3, 4} = 3;
Transfinite Surface{1};
Recombine Surface{1};

// lo[0] top of the lower layer, lo[1] its volume, lo[2..5] its sides.
lo[] = Extrude {0, 0, 20} { Surface{1}; Layers{5}; Recombine; };
up[] = Extrude {0, 0, 20} { Surface{lo[0]}; Layers{5}; Recombine; };

Physical Volume("lower") = {lo[1]};
Physical Volume("upper") = {up[1]};
Physical Surface("bottom") = {1};
Physical Surface("top") = {up[0]};
Physical Surface("ymin") = {lo[2], up[2]};
Physical Surface("xmax") = {lo[3], up[3]};
Physical Surface("ymax") = {lo[4], up[4]};
Physical Surface("xmin") = {lo[5], up[5]};
