// An unconfined column, 1 m x 1 m x 4 m, 1 x 1 x 8 hexahedra, for the uniaxial limits of
// the Mohr-Coulomb rock mass with a tension cut-off (references/plastic.md): pulled
// at the top, the axial stress is limited by the tensile strength T (the cut-off, when
// T < c / tan(phi)); pushed, by the uniaxial compressive strength 2 c sqrt(N_phi).
// The sides are free; the base is held in z, the point (0,0,0) in x and y and the
// point (1,0,0) in y (no rigid motion, no lateral restraint).
// Groups: "soil"; "bottom" (z = 0), "top" (z = 4), the points "anchor" (0,0,0) and
// "roller" (1,0,0).
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
// out[0] top, out[1] volume.
out[] = Extrude {0, 0, 4} { Surface{1}; Layers{8}; Recombine; };

Physical Volume("soil") = {out[1]};
Physical Surface("bottom") = {1};
Physical Surface("top") = {out[0]};
Physical Point("anchor") = {1};
Physical Point("roller") = {2};
