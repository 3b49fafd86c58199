// Cheng, Lansivaara & Wei (2007), RS2 problem 61 case 1 (section.geo; references/plastic.md), the
// prisms of c61-prism.geo (h = 2.1 m) with a skin band at the slope face: 0.525 m (h / 4)
// within 2.1 m of the face, growing to h at 4.2 m. The check of references/plastic.md
// ("Cheng #61: a skin band at the face"): with no tensile strength the face cells part
// in a layer one element deep; the band makes that layer thin.
shape = 1;
h_face = 0.525;
face_band = 2.1;
Include "section.geo";
Include "../slab.geo";
