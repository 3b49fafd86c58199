// The paper slope (docs/method.md section 3) with the LEM critical slip circle as a
// conforming element interface "slip", as the paper did for eq. 21 and the
// progressive-failure run. The circle is the Bishop critical circle of
// `cdem lem verification/lem/paper-slope.toml` (c = 16 kPa, phi = 18 deg,
// gamma = 20.6 kN/m^3, FS 1.089): centre (24.006, 63.222) m through the toe
// (20, 20) (radius 43.407 m), leaving the crest at x = 60.68 m. It dips 0.19 m
// below z = 20 just behind the toe. Section in x-z, one layer in y (0..2 m);
// all-quadrangle section (subdivision), extruded to hexahedra. Units m.
Mesh.MshFileVersion = 4.1;

xc = 24.006; zc = 63.222;
r = Sqrt((20 - xc)^2 + (20 - zc)^2);
xe = xc + Sqrt(r^2 - (40 - zc)^2);   // entry on the crest z = 40
// `refine` divides the element size (1: the committed mesh; `cdem perf`'s cost
// against size meshes other values, src/harness/perf/trials.rs).
If (!Exists(refine))
  refine = 1;
EndIf
h = 3 / refine;                      // halved by the subdivision: about 1.5 m

Point(1) = {0, 0, 0, h};
Point(2) = {80, 0, 0, h};
Point(3) = {80, 0, 40, h};
Point(4) = {xe, 0, 40, h / 2};
Point(5) = {56, 0, 40, h / 2};
Point(6) = {20, 0, 20, h / 2};       // the toe: where the circle leaves the slope
Point(7) = {0, 0, 20, h};
Point(8) = {xc, 0, zc, h};           // centre of the circle (not meshed)

Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};                    // crest inside the sliding mass
Line(5) = {5, 6};                    // slope face
Line(6) = {6, 7};
Line(7) = {7, 1};
Circle(8) = {6, 8, 4};               // the slip circle, toe -> crest

Curve Loop(1) = {5, 8, 4};           // sliding mass
Plane Surface(1) = {1};
Curve Loop(2) = {1, 2, 3, -8, 6, 7}; // the rest
Plane Surface(2) = {2};

Mesh.RecombineAll = 1;
Mesh.Algorithm = 8;
Mesh.SubdivisionAlgorithm = 1;       // all quadrangles

mass[] = Extrude {0, 2, 0} { Surface{1}; Layers{1}; Recombine; };
rest[] = Extrude {0, 2, 0} { Surface{2}; Layers{1}; Recombine; };

e = 1e-6;
Physical Volume("mass") = {mass[1]};
Physical Volume("rest") = {rest[1]};
Physical Surface("slip") = {mass[3]};      // extruded from the circle (loop order 5, 8, 4)
Physical Surface("bottom") = Surface In BoundingBox{-e, -e, -e, 80 + e, 2 + e, e};
Physical Surface("left") = Surface In BoundingBox{-e, -e, -e, e, 2 + e, 20 + e};
Physical Surface("right") = Surface In BoundingBox{80 - e, -e, -e, 80 + e, 2 + e, 40 + e};
Physical Surface("front") = Surface In BoundingBox{-e, -e, -e, 80 + e, e, 40 + e};
Physical Surface("back") = Surface In BoundingBox{-e, 2 - e, -e, 80 + e, 2 + e, 40 + e};
