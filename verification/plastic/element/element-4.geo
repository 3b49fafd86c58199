// A small block assembly for the same Mohr-Coulomb limit as element.geo: the unit cube
// as 2 x 2 hexahedra in x and z (one in y), joined by springs in a scene.
n = 2;
Include "element.geo";
