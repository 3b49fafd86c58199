// Prandtl's strip footing (references/plastic.md): a rigid rough strip footing of
// half-width a = 2 m on a weightless cohesive frictionless layer, half model by
// symmetry about x = 0, plane strain as a slab one element thick (y from 0 to t).
// The domain is FLAC3D's verification problem's (Itasca, "Rough strip footing on a
// cohesive frictionless material"): 20 m from the axis of symmetry, 10 m deep; the
// half-width a is ours (FLAC3D's is not in the copy of its manual we could read).
// Section in the x-z plane (m), the ground at z = 10:
//   (0,0) (20,0) (20,10) (2,10) footing edge, (0,10) footing centre
// Structured hexahedra, graded toward the footing edge (2, 10): 0.12-0.23 m wide and
// 0.18 m high there, 1.3 m wide at the far side, 0.78 m high at the base; 42 x 25 =
// 1050 hexahedra.
// Groups: "soil"; "footing" (z = 10, x in [0, a]: the footing's nodes), "ground"
// (z = 10, x in [a, 20]), "bottom", "left" (x = 0, the symmetry plane), "right",
// "front", "back".
Mesh.MshFileVersion = 4.1;

a = 2;       // footing half-width
W = 20;      // distance of the far side from the axis of symmetry
D = 10;      // depth of the layer
t = 0.2;     // slab thickness (y): about the element size at the footing edge

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
Transfinite Curve{5, 1} = 12 + 1 Using Progression 0.95;   // 0.22 m at x = 0 to 0.12 m at x = a
Transfinite Curve{4, 2} = 30 + 1 Using Progression 1.06;   // 0.23 m at x = a to 1.3 m at x = W
Transfinite Curve{6, 7} = 25 + 1 Using Progression 1.06;   // 0.18 m at the ground to 0.78 m at the base
Transfinite Curve{3} = 25 + 1 Using Progression 0.943396226415094;   // the same (1 / 1.06), from the base up
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
