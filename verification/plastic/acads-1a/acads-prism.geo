// ACADS (1989) problem 1(a) (section.geo; references/plastic.md) as a
// one-element-thick plane-strain slab of unstructured prisms (triangles extruded by one layer).
shape = 1;
Include "section.geo";
Include "../slab.geo";
