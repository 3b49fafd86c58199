// A 1 m cube block resting on a 1 m cube base, one hexahedron each, sharing the
// face z = 1 ("contact"). Used by tests/srm.rs (strength reduction; a copy of tests/fixtures/block-on-plane.geo). Units m.
Mesh.MshFileVersion = 4.1;

Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {1, 1, 0};
Point(4) = {0, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = 2;
Transfinite Surface{1};
Recombine Surface{1};

lo[] = Extrude {0, 0, 1} { Surface{1}; Layers{1}; Recombine; };
up[] = Extrude {0, 0, 1} { Surface{lo[0]}; Layers{1}; Recombine; };

Physical Volume("base") = {lo[1]};
Physical Volume("block") = {up[1]};
Physical Surface("bottom") = {1};
Physical Surface("contact") = {lo[0]};
