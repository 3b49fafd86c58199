// The paper's slope (docs/method.md section 3): a plane-strain slab, one element
// thick. Section in the x-z plane (m):
//   (0,0) (80,0) (80,40) (56,40) (20,20) (0,20)
// 80 m long, base 20 m thick, slope 20 m high at 1V:1.8H from the toe (20,20)
// to the crest (56,40); y from 0 to 2 m. Hexahedra of about 2 m.
//
// Transfinite patches need four corners, so the section is split into three
// quadrilaterals that conform along their shared edges:
//   A  (0,0)  (20,0)  (20,20) (0,20)    10 x 10
//   B  (20,0) (80,0)  (80,20) (20,20)   30 x 10
//   C  (20,20) (80,20) (80,40) (56,40)  30 x 20 (2.06 m along the slope face)
Mesh.MshFileVersion = 4.1;

Point(1) = {0, 0, 0};
Point(2) = {20, 0, 0};
Point(3) = {80, 0, 0};
Point(4) = {80, 0, 20};
Point(5) = {80, 0, 40};
Point(6) = {56, 0, 40};
Point(7) = {20, 0, 20};
Point(8) = {0, 0, 20};

Line(1) = {1, 2};   // base of A
Line(2) = {2, 3};   // base of B
Line(3) = {3, 4};   // right side of B
Line(4) = {4, 5};   // right side of C
Line(5) = {5, 6};   // crest
Line(6) = {6, 7};   // slope face
Line(7) = {7, 8};   // ground left of the toe
Line(8) = {8, 1};   // left side
Line(9) = {2, 7};   // A | B
Line(10) = {7, 4};  // B | C

// `refine` scales the divisions (1: the 2 m mesh; the study meshes in
// verification/study/ set it before including this file).
If (!Exists(refine))
  refine = 1;
EndIf
Transfinite Curve{1, 7, 8, 9, 3} = 10 * refine + 1;   // 10 divisions at refine 1
Transfinite Curve{2, 10, 5} = 30 * refine + 1;        // 30 divisions
Transfinite Curve{4, 6} = 20 * refine + 1;            // 20 divisions

// Loops run clockwise in (x, z), so the surface normals point to +y, the
// direction of the extrusion. (gmsh orients extruded hexahedra positively
// either way; the reader checks every cell.)
Curve Loop(1) = {-8, -7, -9, -1};
Plane Surface(1) = {1};
Curve Loop(2) = {9, 10, -3, -2};
Plane Surface(2) = {2};
Curve Loop(3) = {-10, -6, -5, -4};
Plane Surface(3) = {3};

Transfinite Surface{1} = {1, 2, 7, 8};
Transfinite Surface{2} = {2, 3, 4, 7};
Transfinite Surface{3} = {7, 4, 5, 6};
Recombine Surface{1, 2, 3};

out[] = Extrude {0, 2, 0} { Surface{1, 2, 3}; Layers{1}; Recombine; };

e = 1e-6;
Physical Volume("rock") = Volume{:};
Physical Surface("bottom") = Surface In BoundingBox{-e, -e, -e, 80 + e, 2 + e, e};
Physical Surface("left") = Surface In BoundingBox{-e, -e, -e, e, 2 + e, 20 + e};
Physical Surface("right") = Surface In BoundingBox{80 - e, -e, -e, 80 + e, 2 + e, 40 + e};
Physical Surface("front") = Surface In BoundingBox{-e, -e, -e, 80 + e, e, 40 + e};
Physical Surface("back") = Surface In BoundingBox{-e, 2 - e, -e, 80 + e, 2 + e, 40 + e};
Physical Surface("ground") = {
  Surface In BoundingBox{-e, -e, 20 - e, 20 + e, 2 + e, 20 + e},  // z = 20, x in [0, 20]
  Surface In BoundingBox{20 - e, -e, 20 - e, 56 + e, 2 + e, 40 + e},  // slope face
  Surface In BoundingBox{56 - e, -e, 40 - e, 80 + e, 2 + e, 40 + e}   // crest
};
