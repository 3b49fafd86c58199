// The tutorial's slope (docs/tutorial.md): a two-layer slope with a weak
// bedding seam between the layers. Section in the x-z plane (m), one element
// thick in y (0..2 m, plane strain as the paper's slope), hexahedra.
//
//   z
//   25 |                 crest (30,25) ___________ seam exit (47.5,25) _____ (60,25)
//      |                   /  upper  ___---'''
//   15 |   seam daylight (20,15)---'''    lower
//   10 |_______ toe (15,10)
//      |             lower
//    0 |________________________________________________________________ (60,0)
//
// The slope face rises at 45 deg from the toe (15,10) to the crest (30,25),
// 15 m high. The seam is a bedding plane dipping 20 deg out of the slope
// (toward -x): it daylights in the face 5 m above the toe and reaches the
// crest at x = 47.47 m. Above it: the softer upper layer ("upper", a wedge of
// 87.37 m^2); below it: the stiffer lower layer ("lower"). The seam is the
// surface group "seam", an interface between the two that the scene makes
// breakable. Units m.
Mesh.MshFileVersion = 4.1;

beta = 20 * Pi / 180;                // dip of the seam
xe = 20 + 10 / Tan(beta);            // where the seam reaches the crest z = 25
h = 4;                               // halved by the subdivision: about 2 m

Point(1) = {0, 0, 0, h};
Point(2) = {60, 0, 0, h};
Point(3) = {60, 0, 25, h};
Point(4) = {xe, 0, 25, h / 2};       // seam exit on the crest
Point(5) = {30, 0, 25, h / 2};       // crest edge
Point(6) = {20, 0, 15, h / 2};       // seam daylight in the face
Point(7) = {15, 0, 10, h / 2};       // toe
Point(8) = {0, 0, 10, h};

Line(1) = {1, 2};                    // base
Line(2) = {2, 3};                    // right side
Line(3) = {3, 4};                    // crest behind the seam
Line(4) = {4, 5};                    // crest above the seam
Line(5) = {5, 6};                    // face of the upper layer
Line(6) = {6, 7};                    // face of the lower layer
Line(7) = {7, 8};                    // ground left of the toe
Line(8) = {8, 1};                    // left side
Line(9) = {6, 4};                    // the seam, daylight -> crest

Curve Loop(1) = {5, 9, 4};           // upper layer
Plane Surface(1) = {1};
Curve Loop(2) = {1, 2, 3, -9, 6, 7, 8}; // lower layer
Plane Surface(2) = {2};

Mesh.RecombineAll = 1;
Mesh.Algorithm = 8;
Mesh.SubdivisionAlgorithm = 1;
Mesh.RecombinationAlgorithm = 2;

up[] = Extrude {0, 2, 0} { Surface{1}; Layers{1}; Recombine; };
low[] = Extrude {0, 2, 0} { Surface{2}; Layers{1}; Recombine; };

e = 1e-6;
Physical Volume("upper") = {up[1]};
Physical Volume("lower") = {low[1]};
Physical Surface("seam") = {up[3]};        // extruded from line 9 (loop order 5, 9, 4)
Physical Surface("bottom") = Surface In BoundingBox{-e, -e, -e, 60 + e, 2 + e, e};
Physical Surface("left") = Surface In BoundingBox{-e, -e, -e, e, 2 + e, 10 + e};
Physical Surface("right") = Surface In BoundingBox{60 - e, -e, -e, 60 + e, 2 + e, 25 + e};
Physical Surface("front") = Surface In BoundingBox{-e, -e, -e, 60 + e, e, 25 + e};
Physical Surface("back") = Surface In BoundingBox{-e, 2 - e, -e, 60 + e, 2 + e, 25 + e};
