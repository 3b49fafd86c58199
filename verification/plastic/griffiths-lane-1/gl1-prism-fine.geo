// Griffiths & Lane (1999) Example 1 (section.geo; references/plastic.md), unstructured
// prisms at half the element size of gl1-prism.geo (the same slab thickness): the
// refinement check of the plastic strength reduction.
shape = 1;
refine = 2;
Include "section.geo";
Include "../slab.geo";
