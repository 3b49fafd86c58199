// Cheng, Lansivaara & Wei (2007), RS2 problem 61 case 1 (section.geo; references/plastic.md), the
// prism mesh at half the element size of c61-prism.geo (the same slab thickness): the
// refinement check of the plastic strength reduction.
shape = 1;
refine = 2;
Include "section.geo";
Include "../slab.geo";
