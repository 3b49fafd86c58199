// Written by `cdem mesh plane-geometry.toml` (src/scene/joint_sets.rs): do not edit; edit the geometry file.
// The rock volume fragmented by the joint sets' planes (gmsh's OpenCASCADE kernel).
SetFactory("OpenCASCADE");
Mesh.MshFileVersion = 4.1;
Mesh.MeshSizeMax = 4;
Geometry.Tolerance = 1e-9;

// The section, extruded along strike.
Point(1) = {-5, -2, -5};
Point(2) = {44.32050807568878, -2, -5};
Point(3) = {44.32050807568878, -2, 30};
Point(4) = {17.320508075688778, -2, 30};
Point(5) = {0, -2, 0};
Point(6) = {-5, -2, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 6};
Line(6) = {6, 1};
Curve Loop(1) = {1, 2, 3, 4, 5, 6};
Plane Surface(1) = {1};
ex[] = Extrude {0, 4, 0} { Surface{1}; };
rock = ex[1];

// set1 plane 0: n . p = 0
Point(101) = {68.09300375579123, -60.60950846891997, 39.31351404833626};
Point(102) = {68.09300375579123, 60.60950846891997, 39.31351404833626};
Point(103) = {-36.885744334154325, 60.60950846891997, -21.295994420583703};
Point(104) = {-36.885744334154325, -60.60950846891997, -21.295994420583703};
Line(101) = {101, 102};
Line(102) = {102, 103};
Line(103) = {103, 104};
Line(104) = {104, 101};
Curve Loop(101) = {101, 102, 103, 104};
Plane Surface(101) = {101};
j100[] = BooleanIntersection{ Surface{101}; Delete; }{ Volume{rock}; };

// set2 plane 0: n . p = -26.320508075688775
Point(111) = {26.320508075688775, -60.60950846891997, 68.9428418022533};
Point(112) = {26.320508075688775, 60.60950846891997, 68.9428418022533};
Point(113) = {26.320508075688775, 60.60950846891997, -52.276175135586634};
Point(114) = {26.320508075688775, -60.60950846891997, -52.276175135586634};
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
tol = 0.000006060950846891997;
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
  nx = -0.49999999999999994; ny = 0; nz = 0.8660254037844387; dd = 0; Call OnPlane;
  If (on && nvol[s] == 2) set1[] += s; EndIf
  nx = -1; ny = 0; nz = 0; dd = -26.320508075688775; Call OnPlane;
  If (on && nvol[s] == 2) set2[] += s; EndIf
  nx = 0; ny = 0; nz = 1; dd = -5; Call OnPlane;
  If (on && nvol[s] == 1) bottom[] += s; EndIf
  nx = 1; ny = 0; nz = 0; dd = 44.32050807568878; Call OnPlane;
  If (on && nvol[s] == 1) back[] += s; EndIf
  nx = 1; ny = 0; nz = 0; dd = -5; Call OnPlane;
  If (on && nvol[s] == 1) front[] += s; EndIf
  nx = 0; ny = 1; nz = 0; dd = -2; Call OnPlane;
  If (on && nvol[s] == 1) sides[] += s; EndIf
  nx = 0; ny = 1; nz = 0; dd = 2; Call OnPlane;
  If (on && nvol[s] == 1) sides[] += s; EndIf
EndFor

Physical Volume("rock") = vols[];
Physical Surface("set1") = set1[];
Physical Surface("set2") = set2[];
Physical Surface("bottom") = bottom[];
Physical Surface("back") = back[];
Physical Surface("front") = front[];
Physical Surface("sides") = sides[];
