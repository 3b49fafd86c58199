// Laterally confined rock column: 4 m x 4 m (x, y) x 40 m (z), 2 x 2 x 10
// hexahedra. Units m. Used to check the self-weight solution
// (sigma_zz = -rho g z at the base, docs/method.md section 3).
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

// out[0] top, out[1] volume, out[2..5] sides along curves 1..4.
// `layers` (default 10) is set by the study meshes in verification/study/.
If (!Exists(layers))
  layers = 10;
EndIf
out[] = Extrude {0, 0, 40} { Surface{1}; Layers{layers}; Recombine; };

Physical Volume("rock") = {out[1]};
Physical Surface("bottom") = {1};
Physical Surface("top") = {out[0]};
Physical Surface("ymin") = {out[2]};
Physical Surface("xmax") = {out[3]};
Physical Surface("ymax") = {out[4]};
Physical Surface("xmin") = {out[5]};
