// The infinite slope as one block on an inclined plane (tests/water.rs,
// references/water.md): a slab 16 m along the slope, 4 m wide and 4 m thick
// on a base of the same size, one hexahedron each, sharing the face
// "contact", both turned by beta = 30 deg about y so that the contact
// descends towards +x. (A cube would topple under the uplift of a full
// water table: its weight's lever about the downslope edge is too short.) The block's end faces are normal to
// the slope: with a water table parallel to the slope their water forces
// cancel, as the side forces of an infinite slope do. Units m.
Mesh.MshFileVersion = 4.1;
a = 4.0;  // thickness and width
l = 16.0; // length along the slope
beta = 30.0 * Pi / 180.0;

// The base's bottom face, turned: x -> (x cos(beta), -x sin(beta)).
Point(1) = {0, 0, 0};
Point(2) = {l * Cos(beta), 0, -l * Sin(beta)};
Point(3) = {l * Cos(beta), a, -l * Sin(beta)};
Point(4) = {0, a, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = 2;
Transfinite Surface{1};
Recombine Surface{1};

// Extruded along the slope's normal (a sin(beta), 0, a cos(beta)).
lo[] = Extrude {a * Sin(beta), 0, a * Cos(beta)} { Surface{1}; Layers{1}; Recombine; };
up[] = Extrude {a * Sin(beta), 0, a * Cos(beta)} { Surface{lo[0]}; Layers{1}; Recombine; };

Physical Volume("base") = {lo[1]};
Physical Volume("block") = {up[1]};
Physical Surface("bottom") = {1};
Physical Surface("contact") = {lo[0]};
