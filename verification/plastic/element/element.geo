// One hexahedron, 1 m x 1 m x 1 m, for the Mohr-Coulomb limit in plane-strain
// compression (references/plastic.md): y is the plane-strain direction (front and
// back held in y), sigma_3 acts on the x faces, the top is pushed down in z, and the
// vertical stress at yield is sigma_1 = sigma_3 N_phi + 2 c sqrt(N_phi),
// N_phi = (1 + sin phi) / (1 - sin phi).
// Groups: "soil"; "bottom" (z = 0), "top" (z = 1), "xmin", "xmax", "front" (y = 0),
// "back" (y = 1).
Mesh.MshFileVersion = 4.1;
If (!Exists(n))
  n = 1;   // elements along x and along z (element-4.geo: n = 2)
EndIf

Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {1, 0, 1};
Point(4) = {0, 0, 1};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {-4, -3, -2, -1};   // clockwise in (x, z): the normal points to +y
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = n + 1;
Transfinite Surface{1};
Recombine Surface{1};
out[] = Extrude {0, 1, 0} { Surface{1}; Layers{1}; Recombine; };

e = 1e-6;
Physical Volume("soil") = Volume{:};
Physical Surface("bottom") = Surface In BoundingBox{-e, -e, -e, 1 + e, 1 + e, e};
Physical Surface("top") = Surface In BoundingBox{-e, -e, 1 - e, 1 + e, 1 + e, 1 + e};
Physical Surface("xmin") = Surface In BoundingBox{-e, -e, -e, e, 1 + e, 1 + e};
Physical Surface("xmax") = Surface In BoundingBox{1 - e, -e, -e, 1 + e, 1 + e, 1 + e};
Physical Surface("front") = Surface In BoundingBox{-e, -e, -e, 1 + e, e, 1 + e};
Physical Surface("back") = Surface In BoundingBox{-e, 1 - e, -e, 1 + e, 1 + e, 1 + e};
