// Griffiths & Lane (1999) Example 1 (section.geo; references/plastic.md), structured
// hexahedra at twice the divisions of gl1-hex.geo in x and z (4x the elements; the
// same slab thickness): the refinement check of the plastic strength reduction.
shape = 0;
refine = 2;
Include "section.geo";
Include "../slab.geo";
