// The plane-strain slab of a homogeneous slope section, in one of three element
// shapes (included by every verification/plastic/<case>/<case>-<shape>.geo after its
// section file; this file has no .msh of its own).
//
// The section file (<case>/section.geo) defines, in the x-z plane (y = 0):
//   the surfaces surf[] of the section (quadrilateral patches A, B, C as in
//   verification/cases/slope/slope.geo), their transfinite divisions for
//   shape = 0, the slope height H, the curves of the slope face fc[], the
//   element size h of the unstructured shapes near the face, the slab
//   thickness t, the extents x0, x1, zb and the ground polyline gx[], gz[]
//   (leftmost to rightmost point), and has_left (0 when the toe is the
//   section's left end: no left side).
// The including file sets
//   shape = 0: structured hexahedra (transfinite patches, recombined, extruded
//              by one layer),
//   shape = 1: unstructured prisms (triangles extruded by one layer),
//   shape = 2: tetrahedra (a 3D Delaunay mesh of the slab);
// both of size h within H/2 of the face, growing linearly to 2 h at 1.5 H from it
// (with h_face set: h_face within face_band of the face, growing to h at 2 face_band).
// y runs from 0 to t: the slab is one element thick.
//
// Physical groups: the volume "soil"; surfaces "bottom" (z = zb), "left"
// (x = x0, if has_left), "right" (x = x1), "front" (y = 0), "back" (y = t) and
// "ground" (the slope's top surface, one box per ground segment).
Mesh.MshFileVersion = 4.1;
General.AbortOnError = 4; // an Error() below ends gmsh with exit status 1, no .msh written

// The including file's sizes, checked before they reach gmsh's own (less specific) errors.
If (shape != 0 && h <= 0)
  Error("slab.geo: h = %g: the element size near the face must be positive", h);
EndIf
If (Exists(h_face))
  If (h_face <= 0)
    Error("slab.geo: h_face = %g: the skin band's element size must be positive", h_face);
  EndIf
  If (!Exists(face_band))
    Error("slab.geo: h_face is set but face_band is not: set the skin band's depth (m)");
  EndIf
  If (face_band <= 0)
    Error("slab.geo: face_band = %g: the skin band's depth must be positive", face_band);
  EndIf
EndIf

If (shape == 1 || shape == 2)
  // Size h within H/2 of the slope face (the curves fc[]), growing to 2 h beyond 1.5 H.
  Field[1] = Distance;
  Field[1].CurvesList = {fc[]};
  Field[1].Sampling = 100;
  Field[2] = Threshold;
  Field[2].InField = 1;
  Field[2].SizeMin = h;
  Field[2].SizeMax = 2 * h;
  Field[2].DistMin = 0.5 * H;
  Field[2].DistMax = 1.5 * H;
  If (Exists(h_face))
    // Optional skin band (set h_face, and face_band, before including): size h_face
    // within face_band of the slope face, growing linearly to h at 2 face_band.
    Field[3] = Threshold;
    Field[3].InField = 1;
    Field[3].SizeMin = h_face;
    Field[3].SizeMax = h;
    Field[3].DistMin = face_band;
    Field[3].DistMax = 2 * face_band;
    Field[4] = Min;
    Field[4].FieldsList = {2, 3};
    Background Field = 4;
  Else
    Background Field = 2;
  EndIf
  Mesh.MeshSizeExtendFromBoundary = 0;
  Mesh.MeshSizeFromPoints = 0;
  Mesh.MeshSizeFromCurvature = 0;
  Mesh.Algorithm = 6;      // Frontal-Delaunay triangles
  Mesh.Algorithm3D = 1;    // Delaunay tetrahedra
EndIf

If (shape == 2)
  out[] = Extrude {0, t, 0} { Surface{surf[]}; };
Else
  out[] = Extrude {0, t, 0} { Surface{surf[]}; Layers{1}; Recombine; };
EndIf

e = 1e-6 * (x1 - x0);
ztop = zb;
For k In {0 : #gz[] - 1}
  If (gz[k] > ztop)
    ztop = gz[k];
  EndIf
EndFor
Physical Volume("soil") = Volume{:};
Physical Surface("bottom") = Surface In BoundingBox{x0 - e, -e, zb - e, x1 + e, t + e, zb + e};
If (has_left)
  Physical Surface("left") = Surface In BoundingBox{x0 - e, -e, zb - e, x0 + e, t + e, gz[0] + e};
EndIf
Physical Surface("right") = Surface In BoundingBox{x1 - e, -e, zb - e, x1 + e, t + e, gz[#gz[] - 1] + e};
Physical Surface("front") = Surface In BoundingBox{x0 - e, -e, zb - e, x1 + e, e, ztop + e};
Physical Surface("back") = Surface In BoundingBox{x0 - e, t - e, zb - e, x1 + e, t + e, ztop + e};
ground[] = {};
For k In {0 : #gx[] - 2}
  zlo = gz[k]; zhi = gz[k + 1];
  If (zlo > zhi)
    zlo = gz[k + 1]; zhi = gz[k];
  EndIf
  ground[] += Surface In BoundingBox{gx[k] - e, -e, zlo - e, gx[k + 1] + e, t + e, zhi + e};
EndFor
Physical Surface("ground") = {ground[]};
