// Goodman & Bray's (1976) block toppling example (references/joints.md, "Block toppling"):
// 16 rectangular blocks dx = 10 m wide on a stepped base dipping psi_p = 30 deg (their
// joints dip 60 deg into the slope), a1 = 5 m, a2 = 5 m, b = 1 m, block 10 at the crest:
// heights y_n = n (a1 - b) up to the crest (4, 8, ..., 40 m), then y_n = y_{n-1} - a2 - b
// (34, 28, ..., 4 m). Drawn in the base's frame (x' along the base, rising into the
// slope; z' along the joints) and rotated by psi_p about the y axis at the toe (x' = z' = 0)
// into the model frame (x east into the slope, z up). Extruded w = 5 m along y.
// The base rock below the steps is one volume; every surface between two volumes is the
// group "joints" (the blocks' faces and bases: the interfaces of the limit-equilibrium
// analysis); "bottom" is the base rock's underside, "sides" both ends of the width.
SetFactory("OpenCASCADE");
Mesh.MshFileVersion = 4.1;
Mesh.MeshSizeMax = 5;
Geometry.Tolerance = 1e-9;

dx = 10; a1 = 5; a2 = 5; b = 1; nc = 10; nb = 16; w = 5;
psi = 30 * Pi / 180;
depth = 10;   // base rock below the lowest step (m, along z')
front = 10;   // base rock in front of the toe (m, along x')

// A box in the base frame: [x0, x1] x [z0, z1] (x', z'), extruded along y; rotated below.
y = 0;
For n In {1:nb}
  y = (n <= nc) ? n * (a1 - b) : y - a2 - b;
  z0 = (n - 1) * b;
  blk[n - 1] = newv;
  Box(blk[n - 1]) = {(n - 1) * dx, 0, z0, dx, w, y};
EndFor
// The base rock: a slab under the steps, minus the steps' notches (the blocks sit in them).
base = newv;
Box(base) = {-front, 0, -depth, front + nb * dx + front, w, depth + nb * b};
// the bench in front of the toe (z' = 0) and the steps
steps[] = {newv};
Box(steps[0]) = {-front, 0, 0, front, w, nb * b};
For n In {1:nb}
  s = newv;
  Box(s) = {(n - 1) * dx, 0, (n - 1) * b, (n < nb) ? dx : dx + front, w, nb * b};
  steps[] += s;
EndFor
rock[] = BooleanDifference{ Volume{base}; Delete; }{ Volume{steps[]}; Delete; };
all[] = BooleanFragments{ Volume{rock[]}; Delete; }{ Volume{blk[]}; Delete; };
Rotate {{0, 1, 0}, {0, 0, 0}, -psi} { Volume{:}; }

// How many volumes each surface bounds (1: outer, 2: between two volumes).
alls[] = Surface{:};
vols[] = Volume{:};
top = 0;
For i In {0:#alls[]-1}
  top = (alls[i] > top) ? alls[i] : top;
EndFor
nvol[] = {};
For i In {0:top}
  nvol[] += 0;
EndFor
For v In {0:#vols[]-1}
  bb[] = Abs(Boundary{ Volume{vols[v]}; });
  For q In {0:#bb[]-1}
    nvol[bb[q]] += 1;
  EndFor
EndFor
joints[] = {};
For i In {0:#alls[]-1}
  If (nvol[alls[i]] == 2)
    joints[] += alls[i];
  EndIf
EndFor

// The base rock's underside (z' = -depth) and both ends of the width.
c = Cos(psi); s = Sin(psi);
bottomsel[] = {};
sides[] = {};
For i In {0:#alls[]-1}
  pts[] = PointsOf{ Surface{alls[i]}; };
  onb = 1; ony0 = 1; onyw = 1;
  For q In {0:#pts[]-1}
    xyz[] = Point{pts[q]};
    // z' = -x sin(psi) + z cos(psi) (the inverse rotation)
    If (Fabs(-xyz[0] * s + xyz[2] * c + depth) > 1e-6) onb = 0; EndIf
    If (Fabs(xyz[1]) > 1e-6) ony0 = 0; EndIf
    If (Fabs(xyz[1] - w) > 1e-6) onyw = 0; EndIf
  EndFor
  If (onb) bottomsel[] += alls[i]; EndIf
  If (ony0 || onyw) sides[] += alls[i]; EndIf
EndFor

// The base rock is the volume on the bottom; the others are the blocks (the
// fragments renumber the volumes).
isbottom[] = {};
For i In {0:top}
  isbottom[] += 0;
EndFor
For i In {0:#bottomsel[]-1}
  isbottom[bottomsel[i]] = 1;
EndFor
baserock[] = {};
blocks[] = {};
For v In {0:#vols[]-1}
  bb[] = Abs(Boundary{ Volume{vols[v]}; });
  onbase = 0;
  For q In {0:#bb[]-1}
    If (isbottom[bb[q]])
      onbase = 1;
    EndIf
  EndFor
  If (onbase)
    baserock[] += vols[v];
  Else
    blocks[] += vols[v];
  EndIf
EndFor
Physical Volume("base") = baserock[];
Physical Volume("blocks") = blocks[];
Physical Surface("joints") = joints[];
Physical Surface("bottom") = bottomsel[];
Physical Surface("sides") = sides[];
