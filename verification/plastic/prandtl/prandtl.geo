// Prandtl's strip footing (references/plastic.md): a rigid rough strip footing of
// half-width a = 2 m on a weightless cohesive frictionless layer, half model by
// symmetry about x = 0, plane strain as a slab one element thick (y from 0 to t).
// The domain is FLAC3D's verification problem's (Itasca, "Rough strip footing on a
// cohesive frictionless material"): 20 m from the axis of symmetry, 10 m deep; the
// half-width a is ours (FLAC3D's is not in the copy of its manual we could read).
// Section in the x-z plane (m), the ground at z = 10:
//   (0,0) (20,0) (20,10) (2,10) footing edge, (0,10) footing centre
// Structured hexahedra, graded toward the footing edge (2, 10), where the stress is
// singular and the mesh error is made: 0.06 m wide on both sides of the edge and 0.06 m
// high there, 0.11 m wide at the axis, 1.4 m wide at the far side, 0.79 m high at the
// base; (24 + 42) x 35 = 2310 hexahedra. (The first mesh, 42 x 25 = 1050 hexahedra of
// 0.12-0.23 m at the edge, gave +7.1 %; references/plastic.md has the refinement study.)
// Groups: "soil"; "footing" (z = 10, x in [0, a]: the footing's nodes), "ground"
// (z = 10, x in [a, 20]), "bottom", "left" (x = 0, the symmetry plane), "right",
// "front", "back".
Mesh.MshFileVersion = 4.1;

a = 2;       // footing half-width
W = 20;      // distance of the far side from the axis of symmetry
D = 10;      // depth of the layer
t = 0.1;     // slab thickness (y)

Point(1) = {0, 0, 0};
Point(2) = {a, 0, 0};
Point(3) = {W, 0, 0};
Point(4) = {W, 0, D};
Point(5) = {a, 0, D};
Point(6) = {0, 0, D};
Line(1) = {1, 2};   // base under the footing
Line(2) = {2, 3};   // base beyond it
Line(3) = {3, 4};   // far side
Line(4) = {5, 4};   // ground, from the footing edge out
Line(5) = {6, 5};   // footing, from the axis to its edge
Line(6) = {6, 1};   // axis of symmetry, from the top down
Line(7) = {5, 2};   // below the footing edge, from the top down
// Loops clockwise in (x, z): the normals point to +y, the extrusion direction.
Curve Loop(1) = {-6, 5, 7, -1};
Plane Surface(1) = {1};
Curve Loop(2) = {-7, 4, -3, -2};
Plane Surface(2) = {2};

// Grading: sizes shrink toward the footing edge (x = a) and toward the ground.
Transfinite Curve{5, 1} = 24 + 1 Using Progression 0.974679;   // 0.11 m at x = 0 to 0.06 m at x = a
Transfinite Curve{4, 2} = 42 + 1 Using Progression 1.08;   // 0.06 m at x = a to 1.4 m at x = W
Transfinite Curve{6, 7} = 35 + 1 Using Progression 1.08;   // 0.06 m at the ground to 0.79 m at the base
Transfinite Curve{3} = 35 + 1 Using Progression 0.925925925925926;   // the same (1 / 1.08), from the base up
Transfinite Surface{1} = {1, 2, 5, 6};
Transfinite Surface{2} = {2, 3, 4, 5};
Recombine Surface{1, 2};

out[] = Extrude {0, t, 0} { Surface{1, 2}; Layers{1}; Recombine; };

e = 1e-6;
Physical Volume("soil") = Volume{:};
Physical Surface("footing") = Surface In BoundingBox{-e, -e, D - e, a + e, t + e, D + e};
Physical Surface("ground") = Surface In BoundingBox{a - e, -e, D - e, W + e, t + e, D + e};
Physical Surface("bottom") = Surface In BoundingBox{-e, -e, -e, W + e, t + e, e};
Physical Surface("left") = Surface In BoundingBox{-e, -e, -e, e, t + e, D + e};
Physical Surface("right") = Surface In BoundingBox{W - e, -e, -e, W + e, t + e, D + e};
Physical Surface("front") = Surface In BoundingBox{-e, -e, -e, W + e, e, D + e};
Physical Surface("back") = Surface In BoundingBox{-e, t - e, -e, W + e, t + e, D + e};
