// Written by `cdem mesh wedge-general-geometry.toml` (src/scene/joint_sets.rs): do not edit; edit the geometry file.
// The rock volume fragmented by the joint sets' planes (gmsh's OpenCASCADE kernel).
SetFactory("OpenCASCADE");
Mesh.MshFileVersion = 4.1;
Mesh.MeshSizeMax = 3;
Geometry.Tolerance = 1e-9;

// The section, extruded along strike.
Point(1) = {-4, -15, -4};
Point(2) = {16.36764281119443, -15, -4};
Point(3) = {16.36764281119443, -15, 12};
Point(4) = {4.367642811194429, -15, 12};
Point(5) = {0, -15, 0};
Point(6) = {-4, -15, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 6};
Line(6) = {6, 1};
Curve Loop(1) = {1, 2, 3, 4, 5, 6};
Plane Surface(1) = {1};
ex[] = Extrude {0, 30, 0} { Surface{1}; };
rock = ex[1];

// set1 plane 0: n . p = 0
Point(101) = {49.17802917373862, -14.543073672521846, 33.75576314923403};
Point(102) = {-1.7742469003363341, 46.17948438960898, 33.75576314923403};
Point(103) = {-40.8059548511455, 13.427992643865679, -26.9667949128968};
Point(104) = {10.146321222929462, -47.294565418265144, -26.9667949128968};
Line(101) = {101, 102};
Line(102) = {102, 103};
Line(103) = {103, 104};
Line(104) = {104, 101};
Curve Loop(101) = {101, 102, 103, 104};
Plane Surface(101) = {101};
j100[] = BooleanIntersection{ Surface{101}; Delete; }{ Volume{rock}; };

// set2 plane 0: n . p = 0
Point(111) = {-15.733730574396608, -37.12798487516257, 39.3050362993676};
Point(112) = {44.98882748773421, 13.824291198912407, 39.3050362993676};
Point(113) = {23.45546514157641, 39.48675313557882, -32.535870210474144};
Point(114) = {-37.267092920554404, -11.465522938496148, -32.535870210474144};
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
tol = 0.000003963383496060406;
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
  nx = -0.586824088833465; ny = -0.4924038765061041; nz = 0.6427876096865394; dd = 0; Call OnPlane;
  If (on && nvol[s] == 2) set1[] += s; EndIf
  nx = -0.5825634160695856; ny = 0.6942720440148836; nz = 0.42261826174069944; dd = 0; Call OnPlane;
  If (on && nvol[s] == 2) set2[] += s; EndIf
  nx = 0; ny = 0; nz = 1; dd = -4; Call OnPlane;
  If (on && nvol[s] == 1) bottom[] += s; EndIf
  nx = 1; ny = 0; nz = 0; dd = 16.36764281119443; Call OnPlane;
  If (on && nvol[s] == 1) back[] += s; EndIf
  nx = 1; ny = 0; nz = 0; dd = -4; Call OnPlane;
  If (on && nvol[s] == 1) front[] += s; EndIf
  nx = 0; ny = 1; nz = 0; dd = -15; Call OnPlane;
  If (on && nvol[s] == 1) sides[] += s; EndIf
  nx = 0; ny = 1; nz = 0; dd = 15; Call OnPlane;
  If (on && nvol[s] == 1) sides[] += s; EndIf
EndFor

Physical Volume("rock") = vols[];
Physical Surface("set1") = set1[];
Physical Surface("set2") = set2[];
Physical Surface("bottom") = bottom[];
Physical Surface("back") = back[];
Physical Surface("front") = front[];
Physical Surface("sides") = sides[];
