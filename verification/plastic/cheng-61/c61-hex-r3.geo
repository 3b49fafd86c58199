// Cheng, Lansivaara & Wei (2007), RS2 problem 61 case 1 (section.geo; references/plastic.md), the
// hex mesh at a third of the element size of c61-hex.geo (refine = 3; the same slab
// thickness): the hexahedra's convergence check (references/plastic.md, "Cheng #61: a skin
// band at the face").
shape = 0;
refine = 3;
Include "section.geo";
Include "../slab.geo";
