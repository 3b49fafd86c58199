// Cheng, Lansivaara & Wei (2007), RS2 problem 61 case 1 (section.geo; references/plastic.md) as a
// one-element-thick plane-strain slab of tetrahedra (a 3D mesh of the slab).
shape = 2;
Include "section.geo";
Include "../slab.geo";
