// Cheng, Lansivaara & Wei (2007), RS2 problem 63 (section.geo; references/plastic.md), the
// hex mesh at half the element size of c63-hex.geo (the same slab thickness): the
// refinement check of the plastic strength reduction.
shape = 0;
refine = 2;
Include "section.geo";
Include "../slab.geo";
