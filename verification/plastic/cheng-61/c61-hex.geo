// Cheng, Lansivaara & Wei (2007), RS2 problem 61 case 1 (section.geo; references/plastic.md) as a
// one-element-thick plane-strain slab of structured hexahedra.
shape = 0;
Include "section.geo";
Include "../slab.geo";
