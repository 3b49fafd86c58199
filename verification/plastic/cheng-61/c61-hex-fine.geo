// Cheng, Lansivaara & Wei (2007), RS2 problem 61 case 1 (section.geo; references/plastic.md), the
// hex mesh at half the element size of c61-hex.geo (the same slab thickness): the
// refinement check of the plastic strength reduction.
shape = 0;
refine = 2;
Include "section.geo";
Include "../slab.geo";
