// ACADS (1989) problem 1(a) (section.geo; references/plastic.md) as a
// one-element-thick plane-strain slab of structured hexahedra.
shape = 0;
Include "section.geo";
Include "../slab.geo";
