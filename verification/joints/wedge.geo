// Written by `cdem mesh wedge-geometry.toml` (src/scene/joint_sets.rs): do not edit; edit the geometry file.
// The rock volume fragmented by the joint sets' planes (gmsh's OpenCASCADE kernel).
SetFactory("OpenCASCADE");
Mesh.MshFileVersion = 4.1;
Mesh.MeshSizeMax = 3;
Geometry.Tolerance = 1e-9;

// The section, extruded along strike.
Point(1) = {-4, -14, -4};
Point(2) = {19.215390309173472, -14, -4};
Point(3) = {19.215390309173472, -14, 12};
Point(4) = {3.2153903091734723, -14, 12};
Point(5) = {0, -14, 0};
Point(6) = {-4, -14, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 6};
Line(6) = {6, 1};
Curve Loop(1) = {1, 2, 3, 4, 5, 6};
Plane Surface(1) = {1};
ex[] = Extrude {0, 28, 0} { Surface{1}; };
rock = ex[1];

// set1 plane 0: n . p = 0
Point(101) = {50.71104931000599, -4.863438573882354, 35.850467078615694};
Point(102) = {-14.388697837640933, 40.71989511444608, 35.850467078615694};
Point(103) = {-40.53422393159295, 3.380214138144582, -29.249280069031226};
Point(104) = {24.565523216053975, -42.20311955018385, -29.249280069031226};
Line(101) = {101, 102};
Line(102) = {102, 103};
Line(103) = {103, 104};
Line(104) = {104, 101};
Curve Loop(101) = {101, 102, 103, 104};
Plane Surface(101) = {101};
j100[] = BooleanIntersection{ Surface{101}; Delete; }{ Volume{rock}; };

// set2 plane 0: n . p = 0
Point(111) = {-14.388697837640917, -40.719895114446096, 35.8504670786157};
Point(112) = {50.71104931000598, 4.863438573882372, 35.8504670786157};
Point(113) = {24.565523216053954, 42.203119550183864, -29.249280069031233};
Point(114) = {-40.53422393159294, -3.380214138144599, -29.249280069031233};
Line(111) = {111, 112};
Line(112) = {112, 113};
Line(113) = {113, 114};
Line(114) = {114, 111};
Curve Loop(111) = {111, 112, 113, 114};
Plane Surface(111) = {111};
j110[] = BooleanIntersection{ Surface{111}; Delete; }{ Volume{rock}; };

BooleanFragments{ Volume{rock}; Delete; }{ Surface{j100[], j110[]}; Delete; }

// How many volumes each surface bounds (1: outer, 2: between two volumes).
all[] = Surface{:};
vols[] = Volume{:};
top = 0;
For i In {0:#all[]-1}
  top = (all[i] > top) ? all[i] : top;
EndFor
nvol[] = {};
For i In {0:top}
  nvol[] += 0;
EndFor
For v In {0:#vols[]-1}
  b[] = Abs(Boundary{ Volume{vols[v]}; });
  For q In {0:#b[]-1}
    nvol[b[q]] += 1;
  EndFor
EndFor

// on = 1 if every point of surface s lies on the plane nx x + ny y + nz z = dd.
tol = 0.000003973605852632173;
Macro OnPlane
  on = 1;
  pts[] = PointsOf{ Surface{s}; };
  For q In {0:#pts[]-1}
    xyz[] = Point{pts[q]};
    If (Fabs(nx * xyz[0] + ny * xyz[1] + nz * xyz[2] - dd) > tol)
      on = 0;
    EndIf
  EndFor
Return
set1[] = {};
set2[] = {};
bottom[] = {};
back[] = {};
front[] = {};
sides[] = {};
For i In {0:#all[]-1}
  s = all[i];
  nx = -0.46984631039295427; ny = -0.6710100716628343; nz = 0.5735764363510462; dd = 0; Call OnPlane;
  If (on && nvol[s] == 2) set1[] += s; EndIf
  nx = -0.46984631039295455; ny = 0.6710100716628342; nz = 0.5735764363510462; dd = 0; Call OnPlane;
  If (on && nvol[s] == 2) set2[] += s; EndIf
  nx = 0; ny = 0; nz = 1; dd = -4; Call OnPlane;
  If (on && nvol[s] == 1) bottom[] += s; EndIf
  nx = 1; ny = 0; nz = 0; dd = 19.215390309173472; Call OnPlane;
  If (on && nvol[s] == 1) back[] += s; EndIf
  nx = 1; ny = 0; nz = 0; dd = -4; Call OnPlane;
  If (on && nvol[s] == 1) front[] += s; EndIf
  nx = 0; ny = 1; nz = 0; dd = -14; Call OnPlane;
  If (on && nvol[s] == 1) sides[] += s; EndIf
  nx = 0; ny = 1; nz = 0; dd = 14; Call OnPlane;
  If (on && nvol[s] == 1) sides[] += s; EndIf
EndFor

Physical Volume("rock") = vols[];
Physical Surface("set1") = set1[];
Physical Surface("set2") = set2[];
Physical Surface("bottom") = bottom[];
Physical Surface("back") = back[];
Physical Surface("front") = front[];
Physical Surface("sides") = sides[];
