// Cheng, Lansivaara & Wei (2007), RS2 problem 61 case 1 (section.geo; references/plastic.md) as a
// one-element-thick plane-strain slab of unstructured prisms (triangles extruded by one layer).
shape = 1;
Include "section.geo";
Include "../slab.geo";
